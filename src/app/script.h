#pragma once
// `luz --script FILE`: a prepared demo, or a test, fed to the viewer one command per line:
//   key 2 | key Shift+P           press a key (shortcuts.h names)
//   click X Y                     left click at window coordinates (the inspector, the panel;
//                                 in Whitted's model the pixel's ray tree)
//   drag X0 Y0 X1 Y1 [right]      drag with the left (orbit) or right (pan) button
//   scroll STEPS                  the mouse wheel over the picture (zoom)
//   wait N                        let N frames pass
//   screenshot FILE.png [--with-panel]
//   camera N|NAME                 a scene camera by index or name
//   model flat|gouraud|phong|whitted|radiosity|hybrid
//   set TERM on|off               ambient, diffuse, specular, emission, textures, blinn,
//                                 panel, inspector
//   set exposure EV
//   set depth|spp|light-samples N Whitted's numbers (model 4)
//   set fresnel|adaptive|brute-force|shadow-rays on|off   Whitted's switches
//   trace [--no-wait]             trace the view in Whitted's model (as Enter) and wait for the
//                                 last tile, or go on at once
//   wait-trace                    wait until the trace running has finished
//   dump-ray-tree FILE.json       the ray tree of the last pixel clicked in Whitted's model, as
//                                 `luz render --ray-tree X,Y` writes it
//   dump-trace FILE.json          the trace's phase, tiles done and counters
//   radiosity run|pause|reset     model 5's loop (as Space, and 0); `radiosity step N`: N shots
//   radiosity patch-size M | hemicube N   a new mesh / hemicube (remesh: the solve restarts)
//   radiosity budget MS           shooting time per frame
//   radiosity heat-map|outlines|flat-patches|ambient-estimate|shooter|item-buffer|rotation on|off
//   wait-shots N                  run the solver and pause at exactly N shots (or when it is done)
//   dump-patch FILE.json          the clicked patch (E, rho, area, radiosity, unshot, B, B/pi)
//   dump-radiosity FILE.json      shots, unshot fraction, patches, where the plot is, ...
//   resize W H                    the window, in window coordinates
//   load FILE | reload            as dropping a file on the window / pressing R
//   dump-inspector FILE.json      the inspector's values, for tests and handouts
//   quit
// Blank lines are ignored, and so is everything from a word starting with #. Paths are relative to the working folder.
// The whole file is checked before the window opens: a bad line is an error naming FILE:LINE.
#include <filesystem>
#include <string>
#include <vector>

namespace luz::app {

struct ScriptCommand {
  int line = 0;
  std::string verb;               // the first word
  std::vector<std::string> args;  // the other words
};

struct Script {
  std::filesystem::path file;
  std::vector<ScriptCommand> commands;
};

// Throws luz::Error (kind usage) "FILE:LINE: what is wrong".
Script parse_script(const std::filesystem::path& file);
Script parse_script_text(const std::string& text, const std::filesystem::path& name);

// What the viewer does for each command. Returns false (after setting `error`) when the command
// cannot be done (a camera that does not exist, a screenshot that cannot be written).
class ScriptTarget {
public:
  virtual ~ScriptTarget() = default;
  virtual bool run(const ScriptCommand& command, std::string& error) = 0;
  // True while an earlier command is still playing out over frames (a click's press and
  // release); the runner waits for it.
  virtual bool busy() const { return false; }
};

// Steps through a script, a few commands per frame: `wait N` ends the frame N times; commands
// whose effect must be seen before the next one (a click, a screenshot, a resize, a load) end it
// once.
class ScriptRunner {
public:
  explicit ScriptRunner(Script script) : script_(std::move(script)) {}
  // Runs the commands of this frame. False on the first failing command, `error` holding
  // "FILE:LINE: ...".
  bool step(ScriptTarget& target, std::string& error);
  bool finished() const { return next_ >= script_.commands.size() && waiting_ == 0; }

private:
  Script script_;
  size_t next_ = 0;
  int waiting_ = 0;
};

}  // namespace luz::app
