#pragma once
// `luz --script FILE`: a prepared demo, or a test, fed to the viewer one command per line. The
// verbs (every one, with its arguments; `luz --script-help` prints this list from the table):
//   key 2 | key Shift+P | key +   press a key (shortcuts.h names; + and - are typed characters,
//                                 KP_Add / KP_Subtract the keypad's keys): it runs the line it is
//                                 bound to, one of those below (F1 and docs/viewer.md list them)
//   type TEXT                     type characters (a panel field being edited gets them)
//   click X Y                     left click at window coordinates (the inspector, the panel;
//                                 in Whitted's model the pixel's ray tree)
//   click-widget "LABEL"          a click at the centre of the panel's widget of that label (as
//                                 drawn in the last frame; the part before ## is enough when no
//                                 other widget reads the same); an unknown label fails the script,
//                                 naming it and the nearest labels on screen
//   click-picture X Y             a click on pixel (X, Y) of the picture (row 0 at the top),
//                                 wherever the panel and the window's size put the picture
//   dump-widgets FILE.json        every named panel widget's label, rectangle, and whether it is
//                                 in view
//   drag X0 Y0 X1 Y1 [right]      drag with the left (orbit) or right (pan) button
//   scroll STEPS                  the mouse wheel over the picture (zoom)
//   wait N | wait 2s | wait 500ms  let N frames pass, or that much time (seconds or
//                                 milliseconds: a tour paced to talk over; the window draws only
//                                 what changes meanwhile)
//   wait-until CONDITION FRAMES   let frames pass until trace-done (every traced pane shown has
//                                 finished its trace) or radiosity-done (the solver has reached
//                                 its stopping rule, unasked: a wait-shots runs it); the script
//                                 fails when that takes more than FRAMES frames
//   idle SECONDS                  let the viewer sit idle (no frames unless an event comes),
//                                 measuring its CPU use (dump-state's idle_cpu_fraction)
//   screenshot FILE.png [--with-panel]
//   screenshot [--with-panel]     P's and Shift+P's: a new luz-SCENE-N.png in the working folder
//   camera N|NAME                 a scene camera by index or name; `camera` alone: back to the
//                                 scene camera (C); `camera next`: the scene's next camera (N)
//   model NAME                    a model of the registry: flat, gouraud, phong, whitted,
//                                 radiosity, hybrid, ...
//   panes MODEL[,MODEL...] | panes off   2 to 4 models side by side (panes.h); one, or off:
//                                 one picture
//   dump-panes FILE.json          each pane's model, label, rectangles, camera drawn with
//   set NAME VALUE                a setting of the options tables (options_tables.h): the
//                                 local terms (ambient, diffuse, ... on|off), fog, exposure,
//                                 Whitted's depth, spp, light-samples, fresnel, adaptive,
//                                 brute-force, shadow-rays, and panel, inspector on|off,
//                                 ui-scale S, help on|off
//   toggle NAME | cycle NAME      a switch of `set` to its other value (ambient, ..., panel,
//                                 inspector, help), a choice to its next (fog): the keys' lines
//   attenuation toggle|inverse-square|classroom   f_att of every light (F)
//   exposure +EV | exposure -EV   the exposure moved by that many stops (+ and -)
//   interface larger|smaller      the interface's size by one step (Ctrl+= / Ctrl+-)
//   trace [--no-wait|--held]      trace the view in Whitted's model (as Enter) and wait for the
//                                 last tile, or go on at once (the hybrid's when it is shown);
//                                 --held: go on at once with no tile landing until the trace is
//                                 cancelled (a trace that is surely still running, for a test)
//   wait-trace                    wait until the trace running has finished
//   cancel-trace | clear-ray-tree  every traced pane's trace cancelled / ray tree let go of
//                                 (Backspace, X)
//   dump-ray-tree FILE.json       the ray tree of the last pixel clicked in Whitted's model, as
//                                 `luz render --ray-tree X,Y` writes it
//   dump-trace FILE.json          the trace's phase, tiles done and counters
//   radiosity run|pause|reset     model 5's loop; `radiosity step N`: N shots; run-pause and shot,
//                                 Space's and '.', show model 5 too where no pane shows it
//   radiosity patch-size M | hemicube N   a new mesh / hemicube (remesh: the solve restarts)
//   radiosity budget MS           shooting time per frame
//   radiosity heat-map|outlines|flat-patches|ambient-estimate|shooter|item-buffer|rotation on|off|toggle
//   radiosity patches outlined|gouraud|toggle   flat patches with their outlines, or Gouraud (L)
//   wait-shots N                  run the solver and pause at exactly N shots (or when it is done)
//   dump-patch FILE.json          the clicked patch (E, rho, area, radiosity, unshot, B, B/pi)
//   dump-radiosity FILE.json      shots, unshot fraction, patches, where the plot is, ...
//   path spp N|depth N|seed S|restart   the path tracer's target, depth, seed (model 7)
//   wait-path [N]                 until N samples per pixel (the target) are on screen, or in
//                                 the difference view's reference
//   dump-path FILE.json           spp, target, noise, size, restarts, ...
//   difference on|off             the model shown against the path tracer, as a heat map
//   dump-difference FILE.json     its figures (those `luz compare` prints)
//   solvers open|close|toggle|run|pause|reset | solvers budget MS | solvers patches N   slide 36's window
//   wait-solver-rows N            run slide 36's methods until each has used N rows
//   dump-solvers FILE.json        their curves
//   resize W H                    the window, in window coordinates
//   load FILE | reload            as dropping a file on the window / pressing R
//   dump-inspector FILE.json      the inspector's values, for tests and handouts
//   dump-windows FILE.json        the picture's viewport and every floating window's rectangle
//   dump-state FILE.json          exposure, model, UI scale, note, warnings: what a test checks
//   lesson next|prev|goto N       the lesson's steps (luz --lesson; N counts from 1)
//   lang es|en                    the window's language, from the next frame on
//   caption collapse|expand|toggle  the lesson's caption folded to one line (F9) or whole
//   dump-lesson FILE.json         the lesson's step, slide, title and text (current language), model
//   quit [--ask]                  --ask: Esc's, which asks first with a lesson open or work running
// Blank lines are ignored, and so is everything from a word starting with #; a word in double
// quotes may hold spaces (type "0.5"). Paths are relative to the working folder. The whole file is checked
// before the window opens: a bad line is an error naming FILE:LINE.
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/common/numbers.h"

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

class ViewerServices;  // viewer/model_view.h

// One verb: its name, its usage line, the check of its arguments (before any window opens) and
// what the viewer does for it, through the narrow interface a model's view gets (ViewerServices). The common verbs are in script_verbs.cpp; a model's own verbs
// come with its registry entry (model_registry.h).
struct ScriptVerb {
  const char* name;
  const char* usage;                                    // "click X Y"
  std::string (*check)(const ScriptCommand& command);   // "" when the arguments are right
  bool (*run)(ViewerServices& viewer, const ScriptCommand& command, std::string& error);
  bool ends_frame;  // the next command must see its effect drawn (a click, a screenshot, ...)
};

std::span<const ScriptVerb> common_verbs();
// The verb of that name, common or a model's; nullptr when there is none.
const ScriptVerb* find_verb(std::string_view name);

// Argument checks the verbs share: "" when right, else what is wrong.
std::string check_count(const ScriptCommand& command, size_t low, size_t high);
std::string check_json_file(const ScriptCommand& command);

// How long a `wait` lasts: frames ("30") or time ("2s", "1.5s", "500ms").
struct WaitLength {
  int frames = 0;
  std::optional<std::chrono::milliseconds> time;
};
std::optional<WaitLength> parse_wait(const std::string& text);

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
  // Whether a `wait-until` condition holds now (trace-done, radiosity-done).
  virtual bool holds(const std::string& condition) { return condition.empty(); }
};

// Steps through a script, a few commands per frame: `wait N` ends the frame N times,
// `wait-until CONDITION FRAMES` until the condition holds (or fails the script after FRAMES); commands
// whose effect must be seen before the next one (a click, a screenshot, a resize, a load) end it
// once.
class ScriptRunner {
public:
  using Clock = std::chrono::steady_clock;
  // `now` tells the time for the waits in seconds (a test's own clock).
  explicit ScriptRunner(Script script, std::function<Clock::time_point()> now = Clock::now)
      : script_(std::move(script)), now_(std::move(now)) {}
  // Runs the commands of this frame. False on the first failing command, `error` holding
  // "FILE:LINE: ...".
  bool step(ScriptTarget& target, std::string& error);
  bool finished() const { return next_ >= script_.commands.size() && waiting_ == 0 && !wait_until_; }
  // While a `wait 2s` runs: when it ends (the viewer sleeps until then unless something moves).
  std::optional<Clock::time_point> waiting_until() const { return wait_until_; }
  // "FILE:LINE `command`" of the command run last (the one whose work is waited on), or of the
  // script's start or end.
  std::string position() const;

private:
  Script script_;
  std::function<Clock::time_point()> now_;
  size_t next_ = 0;
  int waiting_ = 0;
  std::optional<Clock::time_point> wait_until_;
  const ScriptCommand* until_ = nullptr;  // the `wait-until` waiting
  int until_frames_left_ = 0;
};

}  // namespace luz::app
