// The viewer's script language and shortcut table, without a window: a bad line is refused
// with FILE:LINE before anything opens, and the runner paces commands over frames.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/common/model_registry.h"
#include "app/viewer/orbit_camera.h"
#include "app/script/script.h"
#include "app/viewer/shortcuts.h"
#include "app/viewer/widget_registry.h"
#include "core/error.h"
#include "support.h"

namespace luz::app {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_script_text(text, "demo.txt");
  } catch (const Error& error) {
    EXPECT_EQ(error.kind, ErrorKind::usage);
    return error.what();
  }
  return "";
}

TEST(ViewerScript, ParsesEveryCommand) {
  const Script script = parse_script_text(
      "# a demo\n\nkey 2\nkey Shift+P\nclick 400 300\ndrag 1 2 3 4 right\nscroll -2\nwait 3 # frames\n"
      "screenshot a.png --with-panel\ncamera 0\nmodel whitted\nset diffuse off\nset exposure -1.5\n"
      "resize 800 600\nload x.glb\nreload\ndump-inspector i.json\nquit\n",
      "demo.txt");
  ASSERT_EQ(script.commands.size(), 16u);
  EXPECT_EQ(script.commands[0].verb, "key");
  EXPECT_EQ(script.commands[0].line, 3);
  EXPECT_EQ(script.commands[5].args, (std::vector<std::string>{"3"}));  // the comment is not an argument
  EXPECT_EQ(script.commands[6].args, (std::vector<std::string>{"a.png", "--with-panel"}));
}

TEST(ViewerScript, BadLinesNameFileAndLine) {
  EXPECT_EQ(error_of("wait 1\nfly away\n"), "demo.txt:2: unknown command \"fly\"");
  EXPECT_EQ(error_of("key Hyper\n"), "demo.txt:1: unknown key \"Hyper\"");
  EXPECT_EQ(error_of("\n\nclick 1\n"), "demo.txt:3: `click` takes 2 arguments");
  EXPECT_EQ(error_of("screenshot a.jpg\n"), "demo.txt:1: screenshots are .png files");
  EXPECT_NE(error_of("model cartoon\n").find("demo.txt:1: unknown model"), std::string::npos);
  EXPECT_NE(error_of("set specular maybe\n").find("demo.txt:1:"), std::string::npos);
  EXPECT_NE(error_of("wait -1\n").find("demo.txt:1:"), std::string::npos);
}

struct Recorder : ScriptTarget {
  std::vector<std::string> done;
  bool run(const ScriptCommand& command, std::string& error) override {
    if (command.verb == "camera" && command.args[0] == "nowhere") {
      error = "no camera \"nowhere\"";
      return false;
    }
    done.push_back(command.verb);
    return true;
  }
};

TEST(ViewerScript, WaitAndScreenshotsEndTheFrame) {
  ScriptRunner runner(parse_script_text("key 1\nkey S\nwait 2\nscreenshot a.png\nkey 3\nquit\n", "d.txt"));
  Recorder target;
  std::string error;
  ASSERT_TRUE(runner.step(target, error));  // frame 1: both keys, then the wait's first frame
  EXPECT_EQ(target.done, (std::vector<std::string>{"key", "key"}));
  ASSERT_TRUE(runner.step(target, error));  // frame 2: still waiting
  EXPECT_EQ(target.done.size(), 2u);
  ASSERT_TRUE(runner.step(target, error));  // frame 3: the screenshot ends it
  EXPECT_EQ(target.done.back(), "screenshot");
  ASSERT_TRUE(runner.step(target, error));
  EXPECT_EQ(target.done, (std::vector<std::string>{"key", "key", "screenshot", "key", "quit"}));
  EXPECT_TRUE(runner.finished());
}

// A script stopped from outside names the command it stood at (script_watch.h): the one run
// last, whose wait or work was going on, with its words as written.
TEST(ViewerScript, ItsPositionIsTheCommandRunLast) {
  ScriptRunner runner(parse_script_text("# a comment\nkey 1\nwait 2\nscreenshot a.png\nquit\n", "d.txt"));
  Recorder target;
  std::string error;
  EXPECT_EQ(runner.position(), "d.txt: before the first command");
  ASSERT_TRUE(runner.step(target, error));
  EXPECT_EQ(runner.position(), "d.txt:3 `wait 2`");
  ASSERT_TRUE(runner.step(target, error));
  ASSERT_TRUE(runner.step(target, error));
  EXPECT_EQ(runner.position(), "d.txt:4 `screenshot a.png`");
  ASSERT_TRUE(runner.step(target, error));
  EXPECT_EQ(runner.position(), "d.txt:5 `quit` (the last)");
}

// A tour paced to talk over: `wait 2s` lasts two seconds however many frames pass meanwhile (an
// idle window draws few, a trace many), and `wait 500ms` half of one.
TEST(ViewerScript, WaitsInSecondsLastThatLongWhateverTheFrames) {
  using namespace std::chrono_literals;
  const ScriptRunner::Clock::time_point start{};
  ScriptRunner::Clock::time_point now = start;
  ScriptRunner runner(parse_script_text("key 1\nwait 2s\nkey 2\nwait 500ms\nquit\n", "d.txt"), [&now] { return now; });
  Recorder target;
  std::string error;
  ASSERT_TRUE(runner.step(target, error));
  EXPECT_EQ(target.done, (std::vector<std::string>{"key"}));
  EXPECT_EQ(runner.waiting_until(), start + 2s);
  for (int frame = 0; frame < 300; ++frame) {  // 300 frames in 1.5 s: still waiting
    now += 5ms;
    ASSERT_TRUE(runner.step(target, error));
  }
  now = start + 1999ms;
  ASSERT_TRUE(runner.step(target, error));
  EXPECT_EQ(target.done.size(), 1u);
  now = start + 2s;  // one frame when the time is up
  ASSERT_TRUE(runner.step(target, error));
  EXPECT_EQ(target.done, (std::vector<std::string>{"key", "key"}));
  EXPECT_EQ(runner.waiting_until(), start + 2500ms);
  now = start + 2499ms;
  ASSERT_TRUE(runner.step(target, error));
  EXPECT_FALSE(runner.finished());
  now = start + 2500ms;
  ASSERT_TRUE(runner.step(target, error));
  EXPECT_EQ(target.done.back(), "quit");
  EXPECT_TRUE(runner.finished());
  EXPECT_FALSE(runner.waiting_until());
}

TEST(ViewerScript, WaitTakesFramesSecondsOrMilliseconds) {
  EXPECT_EQ(parse_script_text("wait 30\nwait 2s\nwait 1.5s\nwait 500ms\nwait 0s\n", "d.txt").commands.size(), 5u);
  for (const char* bad : {"wait 2h\n", "wait s\n", "wait 1.5ms\n", "wait -2s\n", "wait two\n"})
    EXPECT_EQ(error_of(bad), "demo.txt:1: `wait` takes frames (30), seconds (2s) or milliseconds (500ms)") << bad;
}

// The README's tour is paced to talk over: most of a minute of waits in seconds, none in frames
// (a frame count plays at whatever speed the machine draws).
TEST(ViewerScript, TheToursWaitsAreInSeconds) {
  const Script tour = parse_script(test::scene_dir().parent_path() / "docs" / "tour.txt");
  std::chrono::milliseconds talk{0};
  for (const ScriptCommand& c : tour.commands)
    if (c.verb == "wait") {
      const std::optional<WaitLength> length = parse_wait(c.args[0]);
      ASSERT_TRUE(length && length->time) << "line " << c.line << ": wait " << c.args[0];
      talk += *length->time;
    }
  EXPECT_GE(talk, std::chrono::seconds(45));
}

TEST(ViewerScript, AFailingCommandNamesItsLine) {
  ScriptRunner runner(parse_script_text("key 1\n\ncamera nowhere\n", "d.txt"));
  Recorder target;
  std::string error;
  EXPECT_FALSE(runner.step(target, error));
  EXPECT_EQ(error, "d.txt:3: no camera \"nowhere\"");
}

// The line a key press runs, or "" when the key runs nothing.
std::string line_of(int key, int mods) {
  const Shortcut* s = shortcut_for(key, mods);
  return s ? s->line : "";
}

TEST(ViewerShortcuts, KeysRunScriptLines) {
  int key = 0, mods = 0;
  ASSERT_TRUE(parse_key("Shift+p", key, mods));
  EXPECT_EQ(key, GLFW_KEY_P);
  EXPECT_EQ(mods, GLFW_MOD_SHIFT);
  EXPECT_EQ(line_of(GLFW_KEY_P, GLFW_MOD_SHIFT), "screenshot --with-panel");
  EXPECT_EQ(line_of(GLFW_KEY_P, 0), "screenshot");
  ASSERT_TRUE(parse_key("F1", key, mods));
  EXPECT_EQ(line_of(key, mods), "toggle help");
  EXPECT_EQ(line_of(GLFW_KEY_4, 0), "model whitted");  // the registry's digit
  EXPECT_EQ(line_of(GLFW_KEY_MINUS, GLFW_MOD_CONTROL), "interface smaller");
  EXPECT_EQ(line_of(GLFW_KEY_Z, 0), "");
  EXPECT_EQ(line_of(GLFW_KEY_UP, 0), "");  // held to fly, listed for help only
  ASSERT_NE(shortcut_for_character('+'), nullptr);
  EXPECT_EQ(shortcut_for_character('+')->line, "exposure +0.5");
  // Every model has its digit, and no key does two things.
  for (const ModelEntry& m : models()) EXPECT_EQ(line_of(GLFW_KEY_0 + m.key, 0), std::string("model ") + m.name);
  for (const Shortcut& a : shortcuts())
    for (const Shortcut& b : shortcuts())
      if (&a != &b && !a.line.empty()) {
        EXPECT_FALSE(a.key == b.key && a.mods == b.mods && a.character == b.character) << a.name;
      }
}

// Every key names a key `key NAME` takes and runs a line the script accepts: a bad line would
// only show when the key is pressed.
TEST(ViewerShortcuts, EveryKeyIsAKeyAndEveryLineAScriptLine) {
  for (const Shortcut& s : shortcuts()) {
    int key = 0, mods = 0;
    unsigned character = 0;
    EXPECT_TRUE(parse_key(s.name, key, mods, character)) << s.name;
    EXPECT_TRUE(key != 0 || character != 0) << s.name;
    if (s.line.empty()) continue;
    EXPECT_EQ(error_of(s.line + "\n"), "") << s.name << ": " << s.line;
  }
}

TEST(ViewerScript, RadiosityCommandsAreCheckedBeforeAnyWindow) {
  const Script script = parse_script_text(
      "model radiosity\nradiosity run\nradiosity pause\nradiosity reset\nradiosity step 3\n"
      "radiosity patch-size 0.1\nradiosity hemicube 256\nradiosity budget 20\nradiosity heat-map on\n"
      "radiosity outlines off\nwait-shots 50\ndump-patch p.json\ndump-radiosity r.json\n",
      "demo.txt");
  EXPECT_EQ(script.commands.size(), 13u);
  EXPECT_EQ(script.commands[4].args, (std::vector<std::string>{"step", "3"}));
  EXPECT_NE(error_of("radiosity step 0\n").find("demo.txt:1: `radiosity step N` takes N >= 1"), std::string::npos);
  EXPECT_EQ(error_of("radiosity hemicube 100\n"), "");  // even and in range, as --hemicube-res takes it
  EXPECT_NE(error_of("radiosity hemicube 63\n").find("even"), std::string::npos);
  EXPECT_NE(error_of("radiosity hemicube 2048\n").find("64 .. 1024"), std::string::npos);
  EXPECT_NE(error_of("radiosity run now\n").find("takes no value"), std::string::npos);
  EXPECT_NE(error_of("radiosity heat-map maybe\n").find("on, off or toggle"), std::string::npos);
  EXPECT_NE(error_of("radiosity sparkle on\n").find("unknown radiosity setting"), std::string::npos);
  EXPECT_EQ(error_of("radiosity meshing uniform\nradiosity form-factors hemicube\n"), "");
  EXPECT_NE(error_of("radiosity meshing fine\n").find("`radiosity meshing` takes one of uniform, adaptive"),
            std::string::npos);
  EXPECT_NE(error_of("radiosity form-factors guess\n").find("hemicube, analytic, rays"), std::string::npos);
  EXPECT_NE(error_of("wait-shots\n").find("takes 1 argument"), std::string::npos);
  EXPECT_NE(error_of("dump-patch p.txt\n").find(".json"), std::string::npos);
}

TEST(ViewerShortcuts, RadiositysKeys) {
  int key = 0, mods = 0;
  ASSERT_TRUE(parse_key(".", key, mods));
  EXPECT_EQ(line_of(key, mods), "radiosity shot");
  ASSERT_TRUE(parse_key("space", key, mods));
  EXPECT_EQ(line_of(key, mods), "radiosity run-pause");
  EXPECT_EQ(line_of(GLFW_KEY_0, 0), "radiosity reset");
  EXPECT_EQ(line_of(GLFW_KEY_U, 0), "radiosity heat-map toggle");
  EXPECT_EQ(line_of(GLFW_KEY_A, GLFW_MOD_SHIFT), "radiosity ambient-estimate toggle");
  EXPECT_EQ(line_of(GLFW_KEY_A, 0), "toggle ambient");  // A stays the local ambient term
}

TEST(ViewerCommand, ABadScriptIsAUsageErrorBeforeAnyWindow) {
  test::ScratchDir dir;
  const auto script = dir / "demo.txt";
  FILE* f = fopen(script.c_str(), "w");
  fputs("key 1\nwiggle\n", f);
  fclose(f);
  const auto result = test::run_luz({"--script", script.string()}, {.cwd = dir.path, .no_display = true});
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("demo.txt:2: unknown command \"wiggle\""), std::string::npos) << result.output;
}

// A drag turns the view by a quarter of a degree per window unit, whatever the window's size
// (the orbit takes no size): 160 units are 40 degrees.
TEST(ViewerOrbit, ADragOf160UnitsTurnsTheViewBy40Degrees) {
  Camera start;
  start.to_world = glm::mat4(1.0f);  // at the origin, looking down -Z
  OrbitCamera orbit;
  orbit.start_from(start, glm::vec3(0.0f, 0.0f, -5.0f));
  orbit.orbit(160.0f, 0.0f);
  const float degrees = glm::degrees(std::acos(glm::dot(start.forward(), orbit.camera().forward())));
  EXPECT_NEAR(degrees, 40.0f, 0.05f);
}

// Dragging right turns the scene right: the eye goes left around the target, which stays put.
TEST(ViewerOrbit, ADragToTheRightTakesTheEyeLeftAroundTheTarget) {
  Camera start;
  start.to_world = glm::mat4(1.0f);
  OrbitCamera orbit;
  orbit.start_from(start, glm::vec3(0.0f, 0.0f, -5.0f));
  orbit.orbit(160.0f, 0.0f);
  const Camera view = orbit.camera();
  EXPECT_LT(view.position().x, -1.0f);
  EXPECT_NEAR(glm::length(view.position() - glm::vec3(0.0f, 0.0f, -5.0f)), 5.0f, 1e-4f);
  EXPECT_NEAR(glm::length(orbit.target() - glm::vec3(0.0f, 0.0f, -5.0f)), 0.0f, 1e-5f);
}

// A pan keeps the point under the mouse under it: the target moves on the screen by as many
// pixels as the mouse did (dx to the right, dy down, as the window counts), at any distance.
TEST(ViewerOrbit, APanMovesTheTargetWithTheMouse) {
  Camera start;
  start.to_world = glm::mat4(1.0f);
  start.yfov = 0.8f;
  for (const float distance : {2.0f, 7.0f}) {
    OrbitCamera orbit;
    orbit.start_from(start, glm::vec3(0.0f, 0.0f, -distance));
    const glm::vec3 point = orbit.target();
    orbit.pan(30.0f, 12.0f, 600.0f);
    const Camera view = orbit.camera();
    const glm::vec3 seen = glm::vec3(view.view() * glm::vec4(point, 1.0f));  // camera space
    const float pixels_per_metre = 600.0f / (2.0f * -seen.z * std::tan(0.5f * start.yfov));
    EXPECT_NEAR(seen.x * pixels_per_metre, 30.0f, 1e-2f) << distance;
    EXPECT_NEAR(seen.y * pixels_per_metre, -12.0f, 1e-2f) << distance;
  }
}

// The wheel scales the distance to the target by 0.9 a step: forward comes closer, and a step
// back undoes it.
TEST(ViewerOrbit, TheWheelZoomsByATenthAStep) {
  Camera start;
  start.to_world = glm::mat4(1.0f);
  OrbitCamera orbit;
  orbit.start_from(start, glm::vec3(0.0f, 0.0f, -5.0f));
  orbit.zoom(2.0f);
  EXPECT_NEAR(orbit.distance(), 5.0f * 0.81f, 1e-4f);
  orbit.zoom(-2.0f);
  EXPECT_NEAR(orbit.distance(), 5.0f, 1e-4f);
}

// The keys that are characters on every layout ('+', '-') are bound by the character; the
// digits show the registry's models.
TEST(ViewerShortcuts, PlusAndMinusAreCharactersAndTheDigitsShowTheModels) {
  EXPECT_EQ(shortcut_for_character('+')->line, "exposure +0.5");
  EXPECT_EQ(shortcut_for_character('-')->line, "exposure -0.5");
  EXPECT_EQ(shortcut_for(GLFW_KEY_EQUAL, 0), nullptr);  // the US position of '+' is not it
  int key = 0, mods = 0;
  unsigned character = 0;
  ASSERT_TRUE(parse_key("+", key, mods, character));
  EXPECT_EQ(character, unsigned('+'));
  ASSERT_TRUE(parse_key("KP_Add", key, mods, character));
  EXPECT_EQ(key, GLFW_KEY_KP_ADD);
  for (const ModelEntry& m : models()) {
    EXPECT_EQ(line_of(GLFW_KEY_0 + m.key, 0), std::string("model ") + m.name) << m.name;
    EXPECT_EQ(model_on_key(m.key), &m);
  }
}

// Every verb of the script, common or a model's, is found by name, and its name is unique.
TEST(ViewerScript, EveryVerbIsInOneTable) {
  std::vector<std::string> names;
  for (const ScriptVerb& v : common_verbs()) names.push_back(v.name);
  for (const ModelEntry& m : models())
    for (const ScriptVerb& v : m.verbs) names.push_back(v.name);
  for (const std::string& name : names) {
    EXPECT_EQ(std::count(names.begin(), names.end(), name), 1) << name;
    EXPECT_NE(find_verb(name), nullptr) << name;
  }
  for (const char* verb : {"trace", "radiosity", "wait-shots", "solvers", "set", "idle", "dump-windows"})
    EXPECT_NE(find_verb(verb), nullptr) << verb;
}

// `set` takes what the options tables take: nan and inf are refused, ranges are the CLI's.
TEST(ViewerScript, SetTakesTheOptionsTablesRanges) {
  EXPECT_EQ(error_of("set depth 64\n"), "");
  EXPECT_NE(error_of("set depth 65\n").find("0 .. 64"), std::string::npos);
  EXPECT_NE(error_of("set exposure nan\n").find("finite"), std::string::npos);
  EXPECT_NE(error_of("set fog-density inf\n").find("finite"), std::string::npos);
  EXPECT_NE(error_of("set spp 5\n").find("square"), std::string::npos);
  EXPECT_EQ(error_of("set fog exponential\n"), "");
}

}  // namespace
}  // namespace luz::app

// ---- widgets by name, states waited for ---------------------------------------------------------
namespace luz::app {
namespace {

TEST(ViewerScript, WidgetAndWaitVerbsAreCheckedBeforeAnyWindow) {
  EXPECT_EQ(error_of("click-widget \"Blinn N·H  [B]\"\nclick-picture 0 12\ndump-widgets w.json\n"
                     "wait-until trace-done 600\nwait-until radiosity-done 1\ntrace --held\n"),
            "");
  EXPECT_EQ(error_of("click-widget\n"), "demo.txt:1: `click-widget` takes 1 argument");
  EXPECT_EQ(error_of("click-widget Blinn N.H\n"), "demo.txt:1: `click-widget` takes 1 argument");  // quotes needed
  EXPECT_NE(error_of("click-picture -1 3\n").find("demo.txt:1: `click-picture X Y`"), std::string::npos);
  EXPECT_EQ(error_of("dump-widgets w.txt\n"), "demo.txt:1: `dump-widgets` writes a .json file");
  EXPECT_EQ(error_of("wait-until converged 10\n"),
            "demo.txt:1: unknown condition \"converged\" (trace-done, radiosity-done)");
  EXPECT_NE(error_of("wait-until trace-done 0\n").find("FRAMES"), std::string::npos);
  EXPECT_NE(error_of("wait-until trace-done\n").find("2 arguments"), std::string::npos);
}

// A mistyped label's error lists the labels it most likely meant, not the whole panel.
TEST(ViewerScript, NearLabelsAreTheLikelyMeant) {
  const std::vector<std::string> labels{"Phong R·V", "Blinn N·H  [B]", "kd texture  [T]", "max depth",
                                        "shots##stop", "shots", "samples per emitter"};
  EXPECT_EQ(near_labels("Blin N·H", labels, 3), (std::vector<std::string>{"Blinn N·H  [B]"}));
  EXPECT_EQ(near_labels("blinn", labels, 3), (std::vector<std::string>{"Blinn N·H  [B]"}));  // case, a prefix
  EXPECT_EQ(near_labels("max dept", labels, 3), (std::vector<std::string>{"max depth"}));
  EXPECT_EQ(near_labels("shot", labels, 3), (std::vector<std::string>{"shots##stop", "shots"}));
  EXPECT_TRUE(near_labels("radiosity budget", labels, 3).empty());
}

// wait-until holds the script until the condition holds, counting frames, and fails the run
// naming its line when FRAMES pass without it.
struct Waiter : ScriptTarget {
  int frames_until_done = 0;
  std::vector<std::string> done;
  bool run(const ScriptCommand& command, std::string&) override {
    done.push_back(command.verb);
    return true;
  }
  bool holds(const std::string& condition) override { return condition == "trace-done" && frames_until_done-- <= 0; }
};

TEST(ViewerScript, WaitUntilWaitsForTheStateWithinItsFrames) {
  ScriptRunner runner(parse_script_text("wait-until trace-done 5\nquit\n", "d.txt"));
  Waiter target;
  target.frames_until_done = 3;
  std::string error;
  for (int frame = 0; frame < 4; ++frame) {
    ASSERT_TRUE(runner.step(target, error)) << error;
    EXPECT_TRUE(target.done.empty()) << "frame " << frame;
  }
  ASSERT_TRUE(runner.step(target, error)) << error;
  EXPECT_EQ(target.done, (std::vector<std::string>{"quit"}));

  ScriptRunner late(parse_script_text("key 1\nwait-until trace-done 2\nquit\n", "d.txt"));
  Waiter never;
  never.frames_until_done = 1000;
  bool ok = true;
  for (int frame = 0; frame < 5 && ok; ++frame) ok = late.step(never, error);
  EXPECT_FALSE(ok);
  EXPECT_EQ(error, "d.txt:2: `wait-until trace-done` did not hold within 2 frames");
  EXPECT_EQ(never.done, (std::vector<std::string>{"key"}));
}

}  // namespace
}  // namespace luz::app
