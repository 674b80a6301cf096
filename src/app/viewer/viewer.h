#pragma once
// The classroom viewer: the scene in a local model in a resizable window, the panel, the
// inspector, the shortcuts and the scripted runs. Returns the exit code (0; 1 when the scene
// cannot be loaded, there is no window, or a script command fails).
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/classroom/lesson.h"
#include "app/script/script.h"

namespace luz::app {

// The viewer's door for a program that drives it while it runs (the page's window.luz.run): a
// line of the script language, checked and run between frames as a script's lines are; `done`
// is told "" once its work is done and drawn, or the error when the line is wrong or fails.
using LineDone = std::function<void(const std::string& error)>;
class LineQueue {
public:
  virtual ~LineQueue() = default;
  virtual void run_later(const std::string& line, LineDone done) = 0;
};

struct ViewerSettings {
  std::string scene;
  std::optional<Script> script;  // `--script FILE`, already checked
  int width = 0;                 // `--size WxH`: the window, in window coordinates; 0: default
  int height = 0;
  float ui_scale = 1.0f;         // `--ui-scale`: the interface's size (1: the default)
  std::vector<std::string> models;  // `--model a,b,...`: side by side (panes.h); one: that model
  std::optional<Lesson> lesson;  // `--lesson [FILE]`, already read: the window opens on its first step
  std::function<void(LineQueue&)> started;  // told once, when the window is open
  // Told of each screenshot a key or `screenshot` without a file saved (P, Shift+P), once written:
  // the page hands it to the browser as a download.
  std::function<void(const std::filesystem::path&)> screenshot_saved;
  // While the only change from frame to frame is a view's work on threads of its own or between
  // frames (paced(): a trace's tiles, the radiosity loop at its default budget), a frame at most
  // this often, the passes in between given to that work; zero: every frame. The page's: its
  // WebGL draws on the CPU (SwiftShader, often), taking from the tracer's threads and from the
  // solver's shots on the main thread what a frame costs.
  std::chrono::milliseconds paced_frames{0};
};

// On the desktop it returns when the window closes; in the page (WindowContext::drive_frames) as
// soon as the browser draws its frames, the viewer living on.
int run_viewer(const ViewerSettings& settings);
// The same, throwing luz::Error when the scene cannot be loaded or there is no window, where
// run_viewer prints it (the page shows it in words).
int start_viewer(const ViewerSettings& settings);

}  // namespace luz::app
