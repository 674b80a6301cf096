#pragma once
// A lesson: the lecture walked slide by slide. A JSON file (lessons/sintesis.json) holds an
// ordered list of steps; each names its slide, a title and a short text in Spanish and English,
// and the state it sets in the viewer. A step becomes a list of the viewer's script commands
// (script.h), so a lesson drives exactly what a prepared demo script can drive.
//
//   {"title": {"es": "...", "en": "..."},
//    "steps": [{"slide": 17, "title": {...}, "text": {...},
//               "scene": "../scenes/phong_spheres.gltf",  // relative to the lesson file
//               "camera": 0, "model": "phong", "exposure": 0.5,
//               "terms":     {"ambient": false, "diffuse": false},      // slides 15-18
//               "effects":   {"shadows": true, "fog": "linear"},        // slide 19
//               "whitted":   {"depth": 1, "spp": 4, "fresnel": true},   // slides 24-27
//               "radiosity": {"patch-size": 0.1, "hemicube": 64, "heat-map": true},
//               "panes":     ["flat", "gouraud", "phong", "whitted"],  // slide 44
//               "actions":   ["run-solver", {"shots": 5}, "trace", {"click": [0.7, 0.4]},
//                             "open-solvers"]}]}
//
// What a step does not name: scene, camera and model stay as the step before left them (the
// first step must name a scene and a model); exposure stays as it is; every switch and setting of
// "terms", "effects", "whitted" and "radiosity" goes back to its default (the options structs'
// defaults). So a step shows the same thing whether the class walks to it or jumps to it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/common/i18n.h"
#include "app/script/script.h"

namespace luz::app {

struct LessonText {
  std::string es, en;
  const std::string& in(i18n::Language language) const { return language == i18n::Language::es ? es : en; }
};

struct LessonStep {
  int line = 0;   // where the step starts in the file
  int slide = 0;
  LessonText title, text;
  std::string scene;   // resolved against the lesson's folder; after carrying over, never empty
  std::string camera;  // empty: the scene's first
  std::string model;
  std::vector<std::string> panes;  // several models side by side; empty: one picture
  // The state and the actions as script commands, in the order they must run: load, camera,
  // model, the switches, the settings, panes, actions.
  std::vector<ScriptCommand> commands;
};

struct Lesson {
  std::filesystem::path file;
  LessonText title;
  std::vector<LessonStep> steps;
};

// Throws luz::Error (kind usage) "FILE:LINE: what is wrong": JSON syntax, unknown keys, a missing
// language, a model, term or action that does not exist, a value out of its range, a scene file
// that is not there.
Lesson parse_lesson(const std::filesystem::path& file);
Lesson parse_lesson_text(const std::string& text, const std::filesystem::path& name);

// lessons/sintesis.json: next to the binary (an installed or copied tree), else in the source
// tree the build was configured from.
std::filesystem::path default_lesson();

// The verbs a lesson adds to the script language. `lesson next|prev|goto N` (N counts steps
// from 1), `lang es|en`, `dump-lesson FILE.json`. Returns std::nullopt when `command` is not one
// of them, else "" when its arguments are right or what is wrong with them.
std::optional<std::string> lesson_verb_problem(const ScriptCommand& command);

// Where the class is in a lesson, and the commands that take the viewer to a step. The commands
// that rebuild something slow (a scene load, a new radiosity mesh) come only when the step needs
// another one than the viewer has.
class LessonPlayer {
public:
  explicit LessonPlayer(Lesson lesson);

  const Lesson& lesson() const { return lesson_; }
  size_t index() const { return index_; }  // 0-based
  size_t size() const { return lesson_.steps.size(); }
  const LessonStep& step() const { return lesson_.steps[index_]; }

  // Moves to a step (clamped to the lesson) and returns the commands that set its state.
  std::vector<ScriptCommand> go_to(size_t index);
  std::vector<ScriptCommand> next() { return go_to(index_ + 1 < size() ? index_ + 1 : index_); }
  std::vector<ScriptCommand> previous() { return go_to(index_ > 0 ? index_ - 1 : 0); }

  // The current step as `dump-lesson` writes it: step (from 1), steps, slide, title, text (in
  // `language`), language, model, panes, scene.
  nlohmann::json to_json(i18n::Language language) const;

  // Runs a lesson verb (see lesson_verb_problem): `to_run` receives the commands a move needs;
  // false with `error` set when a file cannot be written or N is not a step.
  bool run(const ScriptCommand& command, std::vector<ScriptCommand>& to_run, std::string& error);

private:
  Lesson lesson_;
  size_t index_ = 0;
  std::string loaded_scene_;   // what the last move loaded
  std::string mesh_settings_;  // the radiosity patch size and hemicube the last move set
  bool showing_panes_ = false;
};

}  // namespace luz::app
