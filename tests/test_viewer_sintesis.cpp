// The shipped lesson as a class sees it on a projector: tests/lesson/sintesis.txt is played on
// lessons/sintesis.json by the `viewer_sintesis_script` CTest fixture (Xvfb, Mesa's software GL);
// these tests read what it dumped. Skipped only when xvfb-run is missing.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support.h"
#include "viewer_support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;
using test::json_of;

const fs::path run_dir = LUZ_VIEWER_RUN_DIR;

class ViewerSintesis : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
  static fs::path file(const std::string& name) { return run_dir / name; }
};

// Esc with a lesson open shows "Quit Luz?" instead of ending the class; Esc again answers "stay",
// and the script went on to its end (its own `quit` quits without asking).
TEST_F(ViewerSintesis, EscAsksBeforeEndingTheClass) {
  EXPECT_TRUE(json_of(file("quit-asked.json"))["asking_to_quit"].get<bool>());
  const nlohmann::json windows = json_of(file("quit-asked-windows.json"));
  const bool shown = std::any_of(windows["windows"].begin(), windows["windows"].end(), [](const nlohmann::json& w) {
    return w["name"].get<std::string>().ends_with("###quit");
  });
  EXPECT_TRUE(shown) << windows.dump(2);
  EXPECT_FALSE(json_of(file("quit-stayed.json"))["asking_to_quit"].get<bool>());
}

// A trace nobody waits for ends inside a frame whose panel and status line were laid out while it
// still ran: the window must draw once more, with no input, and then wait. What the screen showed
// after the idle seconds is what it shows frames later: the finished picture, no "tracing 98%".
TEST_F(ViewerSintesis, TheEndOfATraceIsDrawnWithoutInput) {
  EXPECT_EQ(json_of(file("traced-trace.json"))["phase"], "done");
  const test::Codes idle = test::codes(file("traced-idle-shown.png"));
  const test::Codes later = test::codes(file("traced-later-shown.png"));
  ASSERT_EQ(idle.size(), later.size());
  // Above the status line, whose message the first screenshot changed ("saved ...").
  int moved = 0;
  for (int y = 0; y < idle.height - 40; ++y)
    for (int x = 0; x < idle.width; ++x)
      for (int c = 0; c < 3; ++c) moved += std::abs(idle.at(x, y, c) - later.at(x, y, c)) > 2;
  EXPECT_EQ(moved, 0);

  const nlohmann::json state = json_of(file("traced-idle.json"));
  EXPECT_EQ(state["status_line"], json_of(file("traced-later.json"))["status_line"]);
  EXPECT_EQ(state["model"], "whitted");
}

// The same for radiosity run to its stopping rule: the status line the class reads says it is
// done (not "running") without anyone touching the window.
TEST_F(ViewerSintesis, ASolveRunToItsEndIsDrawnWithoutInput) {
  const nlohmann::json radiosity = json_of(file("converged-idle-radiosity.json"));
  ASSERT_TRUE(radiosity["done"].get<bool>()) << radiosity.dump(2);
  EXPECT_FALSE(radiosity["running"].get<bool>());
  const nlohmann::json state = json_of(file("converged-idle.json"));
  EXPECT_EQ(state["status_line"], json_of(file("converged-later.json"))["status_line"]);
}

int max_depth(const nlohmann::json& tree) {
  int depth = 0;
  for (const auto& node : tree["nodes"]) depth = std::max(depth, node["depth"].get<int>());
  return depth;
}

size_t rays_of_kind(const nlohmann::json& tree, const std::string& kind) {
  return size_t(std::count_if(tree["nodes"].begin(), tree["nodes"].end(),
                              [&](const nlohmann::json& n) { return n["kind"] == kind; }));
}

// Step 28's clicked pixel keeps its ray tree through steps 29-35, traced again with each step's
// switches: no shadow rays listed once they are off, no ray deeper than the depth set.
TEST_F(ViewerSintesis, TheRayTreeFollowsTheStepsSwitches) {
  const nlohmann::json tree = json_of(file("tree-28.json"));
  ASSERT_GT(rays_of_kind(tree, "shadow"), 0u) << tree.dump(2);
  ASSERT_GT(max_depth(tree), 2);
  const nlohmann::json no_shadows = json_of(file("tree-30-no-shadow-rays.json"));
  EXPECT_EQ(no_shadows["pixel"], tree["pixel"]);
  EXPECT_EQ(rays_of_kind(no_shadows, "shadow"), 0u);
  const nlohmann::json shallow = json_of(file("tree-31-depth-2.json"));
  EXPECT_EQ(shallow["pixel"], tree["pixel"]);
  EXPECT_GT(rays_of_kind(shallow, "shadow"), 0u);  // back on in step 31
  EXPECT_LE(max_depth(shallow), 2);
  EXPECT_LT(shallow["nodes"].size(), tree["nodes"].size());
}

std::set<std::string> models_of(const nlohmann::json& panes) {
  std::set<std::string> models;
  for (const auto& pane : panes["panes"]) models.insert(pane["model"].get<std::string>());
  return models;
}

// Each traced pane of a step, traced: its trace is the step's, not one left over from an earlier step.
void expect_traced(const nlohmann::json& panes, const std::string& model) {
  bool found = false;
  for (const auto& pane : panes["panes"])
    if (pane["model"] == model) {
      found = true;
      EXPECT_EQ(pane.value("trace", ""), "done") << model;
    }
  EXPECT_TRUE(found) << model << " is not among the panes: " << panes.dump(2);
}

// Step 18 shows flat, Gouraud and Phong, as its title says (with Whitted's per-pixel trace);
// 58 and 59 trace their Whitted and hybrid panes.
TEST_F(ViewerSintesis, SidebySideStepsShowWhatTheirTextSays) {
  const nlohmann::json step18 = json_of(file("panes-18.json"));
  EXPECT_EQ(models_of(step18), (std::set<std::string>{"flat", "gouraud", "phong", "whitted"}));
  expect_traced(step18, "whitted");
  const nlohmann::json step58 = json_of(file("panes-58.json"));
  EXPECT_EQ(models_of(step58), (std::set<std::string>{"flat", "gouraud", "phong", "whitted"}));
  expect_traced(step58, "whitted");
  const nlohmann::json step59 = json_of(file("panes-59.json"));
  EXPECT_EQ(models_of(step59), (std::set<std::string>{"radiosity", "hybrid"}));
  expect_traced(step59, "hybrid");
}

// Step 58 entered and the window resized at once: the Whitted pane is traced at its new size,
// its pixels (but for its label) `luz render --model whitted`'s at that size, code for code (the
// tracer is deterministic, test_viewer_panes.cpp). Cancelled by the resize, it would show its
// raster view.
TEST_F(ViewerSintesis, AStepsTraceFollowsTheWindowResizedAsTheStepStarts) {
  const nlohmann::json panes = json_of(file("panes-58-resized.json"));
  expect_traced(panes, "whitted");
  const test::Codes shot = test::codes(file("panes-58-resized.png"));
  for (const auto& pane : panes["panes"]) {
    if (pane["model"] != "whitted") continue;
    const nlohmann::json& at = pane["screenshot"];
    const nlohmann::json& label = pane["screenshot_label"];
    const int x0 = at[0], y0 = at[1], width = at[2], height = at[3];
    test::ScratchDir dir;
    const fs::path out = dir / "whitted.png";
    const auto result = test::run_luz({"render", (test::scene_dir() / "whitted.gltf").string(), "--model", "whitted",
                                       "--size", std::to_string(width) + "x" + std::to_string(height), "-q",
                                       "--out", out.string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const test::Codes render = test::codes(out);
    const auto in_label = [&](int x, int y) {
      return x >= label[0].get<int>() && y >= label[1].get<int>() && x < label[0].get<int>() + label[2].get<int>() &&
             y < label[1].get<int>() + label[3].get<int>();
    };
    int largest = 0, compared = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        if (in_label(x, y)) continue;
        ++compared;
        for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(shot.at(x0 + x, y0 + y, c) - render.at(x, y, c)));
      }
    EXPECT_GT(compared, width * height / 2);
    EXPECT_EQ(largest, 0) << "the Whitted pane, " << width << "x" << height;
  }
}

// ---- presenter mode -----------------------------------------------------------------------------
struct Rect {
  double x0, y0, x1, y1;
  bool meets(const Rect& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

Rect rect_of(const nlohmann::json& r) {
  return {r[0].get<double>(), r[1].get<double>(), r[2].get<double>(), r[3].get<double>()};
}

const char* const presenter_dumps[] = {
    "presenter-28-1.json",   "presenter-45-1.json",   "presenter-46-1.json",   "presenter-58-1.json",
    "presenter-28-1.5.json", "presenter-45-1.5.json", "presenter-46-1.5.json", "presenter-58-1.5.json",
    "presenter-45-2.json",   "presenter-46-2.json",   "presenter-58-2.json",   "presenter-28-1120-1.5.json",
    "presenter-5-1.json",    "presenter-5-folded.json", "presenter-46-folded.json", "presenter-46-unfolded.json",
    "presenter-44-1.json"};

std::string fmt_name(const std::string& stem, const std::string& scale) { return stem + scale + ".json"; }

bool has_window(const nlohmann::json& dump, const std::string& prefix) {
  return std::any_of(dump["windows"].begin(), dump["windows"].end(),
                     [&](const nlohmann::json& w) { return w["name"].get<std::string>().starts_with(prefix); });
}

// At 1280x720 and UI scales 1, 1.5 and 2: the caption and every window the steps open (the ray
// tree's hint, slide 36's solvers, the item buffer, the heat map's legend, the panes' hint) lie
// in the dock beside or below the picture, none over it; the panel and the status line frame it as always.
TEST_F(ViewerSintesis, TheCaptionAndTheWindowsLeaveThePictureUncovered) {
  for (const char* name : presenter_dumps) {
    SCOPED_TRACE(name);
    const nlohmann::json dump = json_of(file(name));
    const Rect view = rect_of(dump["view"]), dock = rect_of(dump["dock"]);
    EXPECT_GT(view.width(), 0.0);
    EXPECT_GT(dock.width(), 0.0);
    EXPECT_FALSE(dock.meets(view));
    EXPECT_TRUE(has_window(dump, "##lesson caption")) << dump.dump(2);
    size_t over_the_picture = 0;
    for (const auto& w : dump["windows"]) {
      const std::string window = w["name"];
      if (window == "Luz" || window == "status") continue;
      ++over_the_picture;
      EXPECT_FALSE(rect_of(w["rect"]).meets(view)) << window << " covers the picture: " << dump.dump(2);
    }
    EXPECT_GE(over_the_picture, 1u);
  }
  for (const char* scale : {"1", "1.5", "2"}) {
    EXPECT_TRUE(has_window(json_of(file(fmt_name("presenter-45-", scale))), "Slide 36")) << scale;
    EXPECT_TRUE(has_window(json_of(file(fmt_name("presenter-46-", scale))), "item buffer")) << scale;
  }
  EXPECT_TRUE(has_window(json_of(file("presenter-44-1.json")), "heat map"));
}

const nlohmann::json& window_named(const nlohmann::json& dump, const std::string& prefix) {
  for (const auto& w : dump["windows"])
    if (w["name"].get<std::string>().starts_with(prefix)) return w;
  ADD_FAILURE() << "no window " << prefix << " in " << dump.dump(2);
  static const nlohmann::json none = {{"name", ""}, {"rect", {0, 0, 0, 0}}, {"content_height", 0}, {"visible_height", 0}};
  return none;
}

bool below(const Rect& dock, const Rect& view) { return dock.y0 >= view.y1 - 0.5 && dock.x0 <= view.x0 + 0.5; }
bool beside(const Rect& dock, const Rect& view) { return dock.x0 >= view.x1 - 0.5 && dock.y0 <= view.y0 + 0.5; }

// Slide 6's plate of spheres (its camera 4:3, scenes/phong_spheres.gltf) at 1280x720 with the
// panel open: beside a dock the picture would be narrower than 4:3 and lose the plate's outer
// columns, so the caption goes below the picture, which is then at least 4:3, and the caption's
// text is all in view. The Cornell box (1:1) at the same size keeps its dock beside.
TEST_F(ViewerSintesis, AWideScenesCaptionGoesBelowThePictureAndTheWholeFrameShows) {
  const nlohmann::json plate = json_of(file("presenter-5-1.json"));
  const Rect view = rect_of(plate["view"]), dock = rect_of(plate["dock"]);
  EXPECT_TRUE(below(dock, view)) << plate.dump(2);
  EXPECT_GE(view.width() / view.height(), 4.0 / 3.0 - 1e-3) << plate.dump(2);
  const nlohmann::json& caption = window_named(plate, "##lesson caption");
  EXPECT_LE(caption["content_height"].get<double>(), caption["visible_height"].get<double>() + 1.0) << plate.dump(2);
  const nlohmann::json box = json_of(file("presenter-46-1.json"));
  EXPECT_TRUE(beside(rect_of(box["dock"]), rect_of(box["view"]))) << box.dump(2);
}

// F9 folds the caption to one line. With no window docked (the plate's step), in a row below the
// picture, which grows; with step 46's item buffer docked, the room the folded caption frees is
// the window's: it shows whole (no scrolling), over neither the caption nor the picture. F9 again
// brings the whole text back, in the dock beside the box.
TEST_F(ViewerSintesis, FNineFoldsTheCaptionToOneLine) {
  const nlohmann::json whole = json_of(file("presenter-5-1.json"));
  for (const char* name : {"presenter-5-folded.json", "presenter-46-folded.json"}) {
    SCOPED_TRACE(name);
    const nlohmann::json dump = json_of(file(name));
    const double font = dump["font_size"].get<double>();
    EXPECT_LT(rect_of(window_named(dump, "##lesson caption")["rect"]).height(), 3.0 * font) << dump.dump(2);
  }
  const nlohmann::json plate = json_of(file("presenter-5-folded.json"));
  EXPECT_TRUE(below(rect_of(plate["dock"]), rect_of(plate["view"]))) << plate.dump(2);
  EXPECT_GT(rect_of(plate["view"]).height(), rect_of(whole["view"]).height());
  const nlohmann::json folded = json_of(file("presenter-46-folded.json"));
  const nlohmann::json& items = window_named(folded, "item buffer");
  EXPECT_LE(items["content_height"].get<double>(), items["visible_height"].get<double>() + 1.0) << folded.dump(2);
  EXPECT_GT(rect_of(items["rect"]).height(), 8.0 * folded["font_size"].get<double>()) << folded.dump(2);
  EXPECT_FALSE(rect_of(items["rect"]).meets(rect_of(window_named(folded, "##lesson caption")["rect"]))) << folded.dump(2);
  EXPECT_FALSE(rect_of(items["rect"]).meets(rect_of(folded["view"]))) << folded.dump(2);
  const nlohmann::json unfolded = json_of(file("presenter-46-unfolded.json"));
  EXPECT_TRUE(beside(rect_of(unfolded["dock"]), rect_of(unfolded["view"]))) << unfolded.dump(2);
  EXPECT_GT(rect_of(window_named(unfolded, "##lesson caption")["rect"]).height(), 4.0 * unfolded["font_size"].get<double>());
}

// The caption's text is never cut at those sizes and scales, with the panel shown: in the room
// left it is drawn smaller rather than scrolled (folded to one line, a long title is cut on purpose).
TEST_F(ViewerSintesis, TheCaptionsTextIsWhole) {
  for (const char* name : presenter_dumps) {
    if (std::string(name).find("folded") != std::string::npos) continue;
    SCOPED_TRACE(name);
    const nlohmann::json dump = json_of(file(name));
    const nlohmann::json& caption = window_named(dump, "##lesson caption");
    EXPECT_LE(caption["content_height"].get<double>(), caption["visible_height"].get<double>() + 1.0) << caption.dump(2);
    EXPECT_LE(caption["content_width"].get<double>(), caption["visible_width"].get<double>() + 1.0) << caption.dump(2);
  }
}

// At the UI's own scale the panel takes a third of the 1280-unit window: a lesson opens with it
// shown, and no hint (tests/test_viewer_presenter_start.cpp: at scale 2 it starts hidden).
TEST_F(ViewerSintesis, ANarrowPanelStartsShown) {
  const nlohmann::json start = json_of(file("quit-asked.json"));
  EXPECT_TRUE(start["show_panel"].get<bool>()) << start.dump(2);
  EXPECT_TRUE(start["panel_hint"].is_null()) << start.dump(2);
}

// The status line never runs past the window's edge, at any of those sizes and scales: it leaves
// out its figures that matter least (the triangles, the camera, ...) instead, the model and the
// latest message staying.
TEST_F(ViewerSintesis, TheStatusLineFitsTheWindow) {
  for (const char* name : presenter_dumps) {
    SCOPED_TRACE(name);
    const nlohmann::json dump = json_of(file(name));
    const nlohmann::json& status = window_named(dump, "status");
    EXPECT_LE(status["content_width"].get<double>(), status["visible_width"].get<double>() + 1.0) << status.dump(2);
  }
}

// Every table of every window at scales 1, 1.5 and 2 (the inspector's, slide 36's legend): no
// column narrower than its widest cell, and none past its window's edge unless the window
// scrolls sideways to it. Slide 36's exponents ("2.7e-02") are read whole.
TEST_F(ViewerSintesis, NoTableCellIsNarrowerThanItsText) {
  size_t columns = 0;
  for (const char* name : presenter_dumps) {
    SCOPED_TRACE(name);
    const nlohmann::json dump = json_of(file(name));
    for (const auto& table : dump["tables"])
      for (const auto& c : table["columns"]) {
        ++columns;
        EXPECT_LE(c["text"].get<double>(), c["room"].get<double>() + 1.0) << table.dump(2);
        EXPECT_TRUE(c["right"].get<double>() <= table["clip_right"].get<double>() + 1.0 ||
                    table["scrolls_sideways"].get<bool>())
            << table.dump(2);
      }
  }
  EXPECT_GE(columns, 4u);  // slide 36's legend at least
}

// Step 28 clicks a point of the picture given as fractions of it: at 1280x720 at scale 1, at
// 1120x630 at scale 1.5 with the panel hidden and in the default window, different pictures, the
// same ray leaves the eye and meets the same object.
TEST_F(ViewerSintesis, StepTwentyEightsClickHitsTheSameObjectAtAnySizeAndScale) {
  const nlohmann::json a = json_of(file("presenter-tree-1280-1.json")), b = json_of(file("presenter-tree-1120-1.5.json")),
                       c = json_of(file("tree-28.json"));
  EXPECT_NE(a["size"], b["size"]);
  EXPECT_NE(a["size"], c["size"]);
  for (const nlohmann::json* other : {&b, &c}) {
    const nlohmann::json& p = a["nodes"][0];
    const nlohmann::json& q = (*other)["nodes"][0];
    ASSERT_FALSE(p["hit"].is_null());
    ASSERT_FALSE(q["hit"].is_null());
    EXPECT_EQ(p["hit"]["mesh"], q["hit"]["mesh"]);
    EXPECT_EQ(p["hit"]["material"], q["hit"]["material"]);
    double dot = 0.0;
    for (int i = 0; i < 3; ++i) dot += p["direction"][i].get<double>() * q["direction"][i].get<double>();
    EXPECT_GT(dot, std::cos(0.01)) << "the primary rays differ by more than 0.01 rad";
  }
}

}  // namespace
}  // namespace luz
