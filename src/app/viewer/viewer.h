#pragma once
// The classroom viewer: the scene in a local model in a resizable window, the panel, the
// inspector, the shortcuts and the scripted runs. Returns the exit code (0; 1 when the scene
// cannot be loaded, there is no window, or a script command fails).
#include <optional>
#include <string>
#include <vector>

#include "app/classroom/lesson.h"
#include "app/script/script.h"

namespace luz::app {

struct ViewerSettings {
  std::string scene;
  std::optional<Script> script;  // `--script FILE`, already checked
  int width = 0;                 // `--size WxH`: the window, in window coordinates; 0: default
  int height = 0;
  float ui_scale = 1.0f;         // `--ui-scale`: the interface's size (1: the default)
  std::vector<std::string> models;  // `--model a,b,...`: side by side (panes.h); one: that model
  std::optional<Lesson> lesson;  // `--lesson [FILE]`, already read: the window opens on its first step
};

int run_viewer(const ViewerSettings& settings);

}  // namespace luz::app
