// Every key does what its script line does (shortcuts.h): one run of the viewer presses every
// bound key in turn, another runs their lines instead, each dumping the state after every step;
// the two runs must agree step by step, so a key and its line can never drift apart. Both run
// under Xvfb with a lesson open (F7 and F8 have steps to move, Esc its question to ask). The
// panel's buttons are held to their lines the same way (panel.h): a click and the line agree,
// and a button that names its key runs that key's line.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/common/model_registry.h"
#include "app/viewer/panel.h"
#include "app/viewer/shortcuts.h"
#include "support.h"

namespace luz::app {
namespace {

namespace fs = std::filesystem;

// The bound keys in F1's order, Esc last: its question takes the keys until it is answered.
std::vector<const Shortcut*> bound_keys() {
  std::vector<const Shortcut*> keys;
  const Shortcut* esc = nullptr;
  for (const Shortcut& s : shortcuts()) {
    if (s.line.empty()) continue;
    if (s.name == "Esc") esc = &s;
    else keys.push_back(&s);
  }
  if (esc) keys.push_back(esc);
  return keys;
}

// The same steps, pressed as keys or run as lines, the state dumped after each once its frame is
// drawn and a trace it asked for has finished (the note then says the trace is done, in both).
std::string script(bool by_key) {
  std::string text = "status-time off\nwait 3\ndump-state state-0.json\n";
  int step = 0;
  for (const Shortcut* s : bound_keys())
    text += (by_key ? "key " + s->name : s->line) + "\nwait 1\nwait-trace\ndump-state state-" + std::to_string(++step) +
            ".json\n";
  return text + "quit\n";
}

// Plays `text` in the window; false when the run could not start for want of Xvfb.
bool play(const std::string& text, const fs::path& out) {
  fs::create_directories(out.parent_path());
  const fs::path file = out.parent_path() / (out.filename().string() + ".txt");
  std::ofstream(file) << text;
  const std::string command = std::string("sh '") + LUZ_VIEWER_RUNNER + "' '" + LUZ_WITH_LESSON + "' '" +
                              file.string() + "' '" + (test::scene_dir() / "phong_spheres.gltf").string() + "' '" +
                              out.string() + "'";
  const int status = std::system(command.c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 77) return false;
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
  return true;
}

nlohmann::json read(const fs::path& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in) << file;
  return in ? nlohmann::json::parse(in) : nlohmann::json();
}

// What a key changes, without the figures that depend on the machine's speed (frame times,
// frames drawn, the status line, the seconds a note gives) and with a trace's progress reduced
// to whether one was asked for: it runs on other threads at their own pace.
nlohmann::json comparable(nlohmann::json state) {
  for (const char* timing : {"frame_ms", "frame_phases_ms", "idle_cpu_fraction", "frames_drawn", "status_line",
                             "panel_cache", "display_copy"})
    state.erase(timing);
  std::string note = state["note"].get<std::string>();
  std::erase_if(note, [](char c) { return c >= '0' && c <= '9'; });
  state["note"] = note;
  for (nlohmann::json& pane : state["panes"])
    if (pane["trace"].is_string()) pane["trace"] = pane["trace"] == "raster" ? "raster" : "traced";
  return state;
}

TEST(ViewerBindings, EveryKeyLeavesTheStateItsLineLeaves) {
  const fs::path dir = LUZ_BINDINGS_RUN_DIR;
  if (!play(script(true), dir / "keys")) GTEST_SKIP() << "xvfb-run is missing";
  ASSERT_TRUE(play(script(false), dir / "lines"));
  const std::vector<const Shortcut*> keys = bound_keys();
  ASSERT_EQ(comparable(read(dir / "keys" / "state-0.json")), comparable(read(dir / "lines" / "state-0.json")));
  for (size_t i = 0; i < keys.size(); ++i) {
    const std::string name = "state-" + std::to_string(i + 1) + ".json";
    const nlohmann::json by_key = comparable(read(dir / "keys" / name));
    const nlohmann::json by_line = comparable(read(dir / "lines" / name));
    EXPECT_EQ(by_key, by_line) << "key " << keys[i]->name << " against `" << keys[i]->line
                               << "`:\n" << nlohmann::json::diff(by_key, by_line).dump(1);
  }
}

// The panel's buttons that run a line, as a script clicks them: the models' radio buttons, then
// (the Model section folded, so that the Scene section's buttons are in view) the fixed buttons.
struct PanelStep {
  std::string widget, line;
};
std::vector<PanelStep> panel_steps() {
  std::vector<PanelStep> steps;
  for (const ModelEntry& m : models()) steps.push_back({fmt::format("{} [{}]", m.label, m.key), fmt::format("model {}", m.name)});
  steps.push_back({"Phong [3]", "model phong"});
  for (const PanelButton& b : panel_buttons()) steps.push_back({b.widget, b.line});
  return steps;
}

std::string panel_script(bool by_click) {
  std::string text = "status-time off\nwait 3\ndump-state state-0.json\n";
  int step = 0;
  for (const PanelStep& s : panel_steps()) {
    if (s.widget == panel_buttons().front().widget) text += "click-widget \"Model\"\nwait 1\n";
    text += (by_click ? "click-widget \"" + s.widget + "\"" : s.line) + "\nwait 2\nwait-trace\ndump-state state-" +
            std::to_string(++step) + ".json\n";
  }
  return text + "quit\n";
}

TEST(ViewerBindings, EveryPanelButtonLeavesTheStateItsLineLeaves) {
  const fs::path dir = LUZ_BINDINGS_RUN_DIR;
  if (!play(panel_script(true), dir / "clicks")) GTEST_SKIP() << "xvfb-run is missing";
  ASSERT_TRUE(play(panel_script(false), dir / "panel-lines"));
  const std::vector<PanelStep> steps = panel_steps();
  for (size_t i = 0; i <= steps.size(); ++i) {
    const std::string name = "state-" + std::to_string(i) + ".json";
    const nlohmann::json by_click = comparable(read(dir / "clicks" / name));
    const nlohmann::json by_line = comparable(read(dir / "panel-lines" / name));
    EXPECT_EQ(by_click, by_line) << (i == 0 ? "the start" : "\"" + steps[i - 1].widget + "\" against `" + steps[i - 1].line + "`")
                                 << ":\n" << nlohmann::json::diff(by_click, by_line).dump(1);
  }
  // The steps changed something: the models were shown in turn.
  EXPECT_EQ(read(dir / "clicks" / "state-4.json")["model"], models()[3].name);
}

// A button that names its key ("reload [R]") runs that key's line.
TEST(ViewerBindings, APanelButtonRunsItsKeysLine) {
  for (const PanelButton& b : panel_buttons()) {
    const std::string widget = b.widget;
    const size_t open = widget.rfind('[');
    ASSERT_NE(open, std::string::npos) << widget;
    const std::string key = widget.substr(open + 1, widget.size() - open - 2);
    const auto s = std::find_if(shortcuts().begin(), shortcuts().end(), [&](const Shortcut& k) { return k.name == key; });
    ASSERT_NE(s, shortcuts().end()) << widget;
    EXPECT_EQ(s->line, b.line) << widget;
  }
  EXPECT_GE(panel_buttons().size(), 3u);
}

// docs/viewer.md's table of keys gives each key's line: every line bound is there.
TEST(ViewerBindings, TheDocsGiveEveryKeysLine) {
  std::ifstream in(LUZ_DOCS_VIEWER);
  ASSERT_TRUE(in) << LUZ_DOCS_VIEWER;
  const std::string docs((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const Shortcut* s : bound_keys())
    EXPECT_NE(docs.find("`" + s->line + "`"), std::string::npos) << s->name << ": `" << s->line << "`";
}

}  // namespace
}  // namespace luz::app
