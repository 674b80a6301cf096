#pragma once
// What a lesson step's picture shows, headless: the step's commands (lesson.h) read as
// `luz render`'s settings, so that `luz lesson --handout` draws each step as the window's picture
// shows it at the end of the step: its scene, camera, model or panes, switches, settings and
// exposure, the radiosity solver as far as the step's actions take it. What the window shows
// beside the picture (the solvers' window, the inspector a click opens) is not in it.
#include <string>
#include <vector>

#include "app/classroom/lesson.h"
#include "app/models/radiosity/render_radiosity.h"
#include "app/cli/render_command.h"

namespace luz::app {

struct StepPicture {
  RenderSettings settings;          // scene, camera, options and exposure; settings.model the step's model
  std::vector<std::string> models;  // the step's model, or its panes
  // Radiosity as the window has it when the step's actions are done: `shots` shots after a
  // reset (0: the emitters alone), or the stopping rule where the solver was left running; the
  // hybrid's always by the stopping rule (its trace waits for a solution).
  SolveExtent radiosity;
  bool heat_map = false;            // radiosity shows the heat map of the unshot power
  bool shows_radiosity() const;     // a pane (or the picture) shows a radiosity solution
};

// Every step of the lesson, in order: the exposure, the scene and the solver's state carry from
// one step to the next as they do in the window walked from the first step.
std::vector<StepPicture> step_pictures(const Lesson& lesson);

}  // namespace luz::app
