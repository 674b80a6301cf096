// The classroom defects found when the viewer was first tried as a new teacher would:
// tests/viewer/layout.txt is played on scenes/cornell_box.gltf by the `viewer_layout_script` CTest
// fixture (Xvfb, Mesa's software GL); these tests read what it dumped. Skipped only when xvfb-run
// is missing.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "viewer_support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;

const fs::path run_dir = LUZ_VIEWER_RUN_DIR;  // where the fixture played the script

using test::json_of;

class ViewerLayout : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
  static fs::path file(const std::string& name) { return run_dir / name; }
};

struct Rect {
  double x0, y0, x1, y1;
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
  bool meets(const Rect& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};
Rect rect_of(const nlohmann::json& r) { return {r[0], r[1], r[2], r[3]}; }

const nlohmann::json* window_named(const nlohmann::json& dump, const std::string& prefix) {
  for (const auto& w : dump["windows"])
    if (w["name"].get<std::string>().starts_with(prefix)) return &w;
  return nullptr;
}

// The windows over the picture (not the panel, not the status line) keep off its centre and
// off each other; nothing in any window is cut at its right edge.
void expect_laid_out(const std::string& dump_file) {
  SCOPED_TRACE(dump_file);
  const nlohmann::json dump = json_of(dump_file);
  const Rect view = rect_of(dump["view"]);
  const double cx = 0.5 * (view.x0 + view.x1), cy = 0.5 * (view.y0 + view.y1);
  std::vector<std::pair<std::string, Rect>> floating;
  for (const auto& w : dump["windows"]) {
    const std::string name = w["name"];
    // A window squeezed into its corner scrolls sideways instead (its scrollbar shows it).
    if (!w["scrolls_sideways"].get<bool>()) {
      EXPECT_LE(w["content_width"].get<double>(), w["visible_width"].get<double>() + 0.5) << name << " cuts its text";
    }
    if (name == "Luz" || name == "status" || name.starts_with("Keys") || name.starts_with("The scene")) continue;
    const Rect r = rect_of(w["rect"]);
    EXPECT_FALSE(r.contains(cx, cy)) << name << " covers the picture's centre";
    for (const auto& [other, o] : floating) EXPECT_FALSE(r.meets(o)) << name << " overlaps " << other;
    floating.emplace_back(name, r);
  }
}

TEST_F(ViewerLayout, NothingInThePanelIsCutAndTheWindowsKeepApart) {
  for (const char* dump : {"phong-windows.json", "whitted-windows.json", "radiosity-windows.json"}) {
    const nlohmann::json windows = json_of(file(dump));
    const nlohmann::json* panel = window_named(windows, "Luz");
    ASSERT_NE(panel, nullptr);
    EXPECT_FALSE((*panel)["scrolls_sideways"].get<bool>()) << dump;
  }
  for (const char* dump : {"phong-windows.json", "whitted-windows.json", "radiosity-windows.json",
                           "radiosity-inspector-windows.json", "solvers-windows.json", "ui-large-windows.json"})
    expect_laid_out(file(dump).string());
  // The radiosity dump holds the three windows the trial saw pile up.
  const nlohmann::json r = json_of(file("radiosity-inspector-windows.json"));
  EXPECT_NE(window_named(r, "Inspector: patch"), nullptr);
  EXPECT_NE(window_named(r, "item buffer"), nullptr);
  EXPECT_NE(window_named(json_of(file("solvers-windows.json")), "Slide 36"), nullptr);
}

TEST_F(ViewerLayout, KeyFiveSaysHowToStartTheSolver) {
  const nlohmann::json r = json_of(file("radiosity-windows.json"));
  EXPECT_NE(window_named(r, "radiosity hint"), nullptr);
  // Shot 0: the lamp is lit, the room is not (a hint is needed).
  const test::Codes shot0 = test::codes(file("radiosity-shot-0.png"));
  int lit = 0;
  for (int y = 0; y < shot0.height; ++y)
    for (int x = 0; x < shot0.width; ++x) lit += shot0.at(x, y, 0) > 40;
  EXPECT_LT(lit, shot0.width * shot0.height / 20);
}

TEST_F(ViewerLayout, FOneFitsTheWindowAndCanBeClosed) {
  const nlohmann::json dump = json_of(file("help-windows.json"));
  const nlohmann::json* help = window_named(dump, "Keys (F1)");
  ASSERT_NE(help, nullptr);
  const Rect view = rect_of(dump["view"]), r = rect_of((*help)["rect"]);
  EXPECT_GE(r.y0, view.y0 - 0.5);
  EXPECT_LE(r.y1, view.y1 + 0.5);  // scrolled inside, not cut off at 760 units
  EXPECT_LE(r.x1, view.x1 + 0.5);
}

TEST_F(ViewerLayout, TheStatusLineSaysWhatTheLastKeyDid) {
  const nlohmann::json s = json_of(file("exposure-note.json"));
  EXPECT_EQ(s["note"], "exposure +1.0 EV");  // the Cornell box's +0.5 EV, then '+'
  EXPECT_DOUBLE_EQ(s["exposure"].get<double>(), 1.0);
}

TEST_F(ViewerLayout, TheMaterialSectionFollowsTheInspectorAfterACameraMove) {
  const nlohmann::json before = json_of(file("material-before.json")), after = json_of(file("material-after.json"));
  const nlohmann::json inspector = json_of(file("inspector-after.json"));
  ASSERT_TRUE(before.contains("material"));
  ASSERT_TRUE(after.contains("material"));
  EXPECT_NE(before["material"], after["material"]) << "the zoom must bring another object under the pixel";
  EXPECT_EQ(after["material"], inspector["material"]);
}

// A fixed scale: as the unshot power drains, the heat map darkens (with a scale from the
// current maximum the most unshot patch stays yellow and the picture red to the end).
TEST_F(ViewerLayout, TheHeatMapDarkensAsTheSolveConverges) {
  const test::Codes early = test::codes(file("heat-early.png")), late = test::codes(file("heat-late.png"));
  // The ramp's green rises from red to yellow: the hotter the map, the greener.
  auto mean_green = [](const test::Codes& c) {
    double sum = 0.0;
    for (int y = 0; y < c.height; ++y)
      for (int x = 0; x < c.width; ++x) sum += c.at(x, y, 1);
    return sum / (double(c.width) * c.height);
  };
  const double unshot_early = json_of(file("heat-early.json"))["unshot_fraction"].get<double>();
  const double unshot_late = json_of(file("heat-late.json"))["unshot_fraction"].get<double>();
  ASSERT_LT(unshot_late, 0.5 * unshot_early);  // the solve went on between the two
  EXPECT_LT(mean_green(late), 0.8 * mean_green(early));
}

TEST_F(ViewerLayout, TheInterfaceScalesForAProjector) {
  const nlohmann::json large = json_of(file("ui-large.json")), smaller = json_of(file("ui-smaller.json"));
  EXPECT_DOUBLE_EQ(large["user_scale"].get<double>(), 1.5);
  EXPECT_NEAR(smaller["user_scale"].get<double>(), 1.5 / 1.25, 1e-6);
  const nlohmann::json windows = json_of(file("ui-large-windows.json")), normal = json_of(file("phong-windows.json"));
  const Rect panel_large = rect_of((*window_named(windows, "Luz"))["rect"]);
  const Rect panel_normal = rect_of((*window_named(normal, "Luz"))["rect"]);
  EXPECT_NEAR(panel_large.x1 - panel_large.x0, 1.5 * (panel_normal.x1 - panel_normal.x0), 1.0);
}

// The panel's pixels (left of the picture, above the status line).
test::Codes panel_of(const test::Codes& window, const Rect& view) {
  test::Codes panel{int(std::lround(view.x0)), int(std::lround(view.y1)), {}};
  for (int y = 0; y < panel.height; ++y)
    for (int x = 0; x < panel.width; ++x)
      for (int c = 0; c < 3; ++c) panel.values.push_back(window.at(x, y, c));
  return panel;
}

// The window above the status line, and the status line (under the picture and the panel).
test::Codes above_status(const test::Codes& window, const Rect& view) {
  test::Codes above{window.width, int(std::lround(view.y1)), {}};
  above.values.assign(window.values.begin(), window.values.begin() + ptrdiff_t(above.width) * above.height * 3);
  return above;
}

test::Codes status_of(const test::Codes& window, const Rect& view) {
  const int top = int(std::lround(view.y1));
  test::Codes status{window.width, window.height - top, {}};
  status.values.assign(window.values.begin() + ptrdiff_t(window.width) * top * 3, window.values.end());
  return status;
}

// The panel and the status line are drawn into a cache when they change and copied from it on
// the other frames: what the window shows is the same as drawing them every frame, and a change
// shows at once.
TEST_F(ViewerLayout, ThePanelFromItsCacheIsThePanelDrawnAgain) {
  const nlohmann::json steady = json_of(file("panel-steady.json"))["panel_cache"];
  EXPECT_TRUE(steady["on"].get<bool>());
  EXPECT_GE(steady["hits"].get<long>(), 8) << "ten steady frames: the panel should come from the cache";
  const Rect view = rect_of(json_of(file("panel-windows.json"))["view"]);
  ASSERT_GT(view.x0, 100.0);
  // The steady windows: above the status line pixel for pixel; the status line (the script holds
  // its frame time and gives both the same message) within 4 codes, as Mesa's software rasteriser
  // blends its anti-aliased edges into the cache's RGBA8 texture up to 4 codes darker than into
  // the window. After key 1 the panels (the status line says which screenshot was taken last).
  const test::Codes cached = test::codes(file("panel-cached.png")), drawn = test::codes(file("panel-drawn.png"));
  const test::Codes changed_cached = panel_of(test::codes(file("panel-changed-cached.png")), view);
  const test::Codes changed_drawn = panel_of(test::codes(file("panel-changed-drawn.png")), view);
  EXPECT_EQ(test::share_moved(above_status(cached, view), above_status(drawn, view), 0), 0.0);
  EXPECT_EQ(test::share_moved(status_of(cached, view), status_of(drawn, view), 4), 0.0);
  EXPECT_GT(test::share_moved(changed_drawn, panel_of(drawn, view), 0), 0.0) << "key 1 should have changed the panel";
  EXPECT_EQ(test::share_moved(changed_cached, changed_drawn, 0), 0.0) << "the cache kept the panel of before key 1";
}

// Where the window keeps its back buffer (Mesa's software rasteriser, which these tests run
// on), a steady panel and status line are left in the window and only the rest is shown again;
// what the display shows, read back from the X server, is what the frame drew, status line
// included, before and after the panel and the status line's message change, and with every
// frame shown whole.
TEST_F(ViewerLayout, TheDisplayShowsTheFrameDrawnWhenOnlyItsChangedPartsArePresented) {
  const nlohmann::json steady = json_of(file("present-steady.json"));
  ASSERT_TRUE(steady["present_parts"]["window_keeps_back_buffer"].get<bool>()) << "llvmpipe under Xvfb keeps it";
  EXPECT_GE(steady["panel_cache"]["kept"].get<long>(), 8) << "ten steady frames: the panel should have stayed in the window";
  const nlohmann::json whole = json_of(file("present-whole.json"));
  EXPECT_FALSE(whole["present_parts"]["on"].get<bool>());
  // (the script's dump and switch are a frame apart)
  EXPECT_LE(whole["panel_cache"]["kept"].get<long>() - json_of(file("present-back.json"))["panel_cache"]["kept"].get<long>(), 1)
      << "with every frame shown whole the panel is copied in";

  const Rect view = rect_of(json_of(file("panel-windows.json"))["view"]);
  const auto shown_vs_drawn = [&](const std::string& name) {
    const test::Codes drawn = test::codes(file("present-" + name + "-drawn.png"));
    const test::Codes shown = test::codes(file("present-" + name + "-shown.png"));
    return test::share_moved(shown, drawn, 0);
  };
  EXPECT_EQ(test::share_moved(test::codes(file("present-shown.png")), test::codes(file("present-drawn.png")), 0),
            0.0);
  EXPECT_EQ(shown_vs_drawn("changed"), 0.0) << "the display should show key 1's panel and picture";
  EXPECT_EQ(shown_vs_drawn("back"), 0.0) << "the display should show key 3's panel and picture";
  EXPECT_EQ(shown_vs_drawn("whole"), 0.0);
  const test::Codes before = panel_of(test::codes(file("present-shown.png")), view);
  const test::Codes changed = panel_of(test::codes(file("present-changed-shown.png")), view);
  EXPECT_GT(test::share_moved(changed, before, 0), 0.0) << "key 1 should have changed the panel shown";
  EXPECT_GT(test::share_moved(status_of(test::codes(file("present-changed-shown.png")), view),
                              status_of(test::codes(file("present-shown.png")), view), 0),
            0.0)
      << "key 1 should have changed the status line shown";
  const test::Codes flashed = panel_of(test::codes(file("present-flash-shown.png")), view);
  EXPECT_EQ(test::share_moved(flashed, before, 0), 0.0) << "the panel of a one-frame change stayed on the display";
}

// How the last frame before a dump showed its pane: drawn into the window, copied, or neither
// (the display pass).
std::pair<int, int> direct_and_copied(const std::filesystem::path& state) {
  const nlohmann::json d = json_of(state)["display_copy"];
  return {d["direct_panes"].get<int>(), d["copied_panes"].get<int>()};
}

// Whether pixel (x, y) of `a` is, within one code, one of the 3x3 pixels around (x, y) of `b`.
bool near_a_neighbour(const test::Codes& a, const test::Codes& b, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int u = x + dx, v = y + dy;
      if (u < 0 || v < 0 || u >= b.width || v >= b.height) continue;
      bool close = true;
      for (int c = 0; c < 3; ++c) close = close && std::abs(a.at(x, y, c) - b.at(u, v, c)) <= 1;
      if (close) return true;
    }
  return false;
}

// Within the view: the share of pixels of `a` that differ from `b`'s by more than `codes` in a
// channel, and how many of those are not explained by a neighbour of `b` (near_a_neighbour).
struct EdgeDifferences {
  double moved = 0.0;
  size_t unexplained = 0;
};
EdgeDifferences edge_differences(const test::Codes& a, const test::Codes& b, const Rect& view, int codes) {
  size_t pixels = 0, moved = 0, unexplained = 0;
  for (int y = int(view.y0); y < int(view.y1); ++y)
    for (int x = int(view.x0); x < int(view.x1); ++x) {
      ++pixels;
      bool close = true;
      for (int c = 0; c < 3; ++c) close = close && std::abs(a.at(x, y, c) - b.at(x, y, c)) <= codes;
      if (close) continue;
      ++moved;
      unexplained += !near_a_neighbour(a, b, x, y);
    }
  return {double(moved) / double(pixels), unexplained};
}

// The Phong picture drawn straight into the window (the sRGB curve computed as it draws) is the
// one copied from the picture's second colour buffer, but for a few pixels on triangles' edges:
// the pane's offset in the window rounds the vertices' window coordinates differently, so an
// edge's pixel may fall to the triangle beside it, and shows what its neighbour shows.
TEST_F(ViewerLayout, ThePictureDrawnIntoTheWindowIsTheCopiedOne) {
  EXPECT_EQ(direct_and_copied(file("display-direct.json")), std::make_pair(1, 0));
  EXPECT_EQ(direct_and_copied(file("display-copied.json")), std::make_pair(0, 1));
  const Rect view = rect_of(json_of(file("panel-windows.json"))["view"]);
  const test::Codes direct = test::codes(file("display-direct.png")), copied = test::codes(file("display-copied.png"));
  ASSERT_EQ(direct.size(), copied.size());
  const EdgeDifferences d = edge_differences(direct, copied, view, 0);
  EXPECT_LT(d.moved, 1e-4);
  EXPECT_EQ(d.unexplained, 0u);
  // The panel beside it is untouched by the picture's clears.
  EXPECT_EQ(test::share_moved(panel_of(direct, view), panel_of(copied, view), 0), 0.0);
}

// Flat shading drawn into the window, its displayed values computed once per triangle, is the
// display pass over its radiance: within one code, but for the few pixels on triangles' edges
// that the pane's offset gives to the triangle beside them.
TEST_F(ViewerLayout, FlatDrawnIntoTheWindowIsTheDisplayPasss) {
  EXPECT_EQ(direct_and_copied(file("flat-direct.json")), std::make_pair(1, 0));
  const Rect view = rect_of(json_of(file("panel-windows.json"))["view"]);
  const test::Codes direct = test::codes(file("flat-direct.png")), pass = test::codes(file("flat-pass.png"));
  ASSERT_EQ(direct.size(), pass.size());
  const EdgeDifferences d = edge_differences(direct, pass, view, 1);
  EXPECT_LT(d.moved, 1e-3);
  EXPECT_EQ(d.unexplained, 0u);
}

// The Phong picture copied from the model's second colour buffer is the display pass's over the
// radiance, within one code.
TEST_F(ViewerLayout, TheCopiedPictureIsTheDisplayPasss) {
  EXPECT_EQ(direct_and_copied(file("display-pass.json")), std::make_pair(0, 0));
  const Rect view = rect_of(json_of(file("panel-windows.json"))["view"]);
  const test::Codes copied = test::codes(file("display-copied.png")), drawn = test::codes(file("display-pass.png"));
  ASSERT_EQ(copied.size(), drawn.size());
  size_t values = 0, moved = 0, far = 0;
  for (int y = int(view.y0); y < int(view.y1); ++y)
    for (int x = int(view.x0); x < int(view.x1); ++x)
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(copied.at(x, y, c) - drawn.at(x, y, c));
        ++values;
        moved += d > 0;
        far += d > 1;
      }
  EXPECT_EQ(far, 0u);
  EXPECT_LT(double(moved) / double(values), 0.001);
}

// Redrawn only on events and while something runs: 10 s idle cost (well) under 5 % of a core.
TEST_F(ViewerLayout, AnIdleWindowCostsNoCpu) {
  const double cpu = json_of(file("idle.json"))["idle_cpu_fraction"].get<double>();
  EXPECT_GE(cpu, 0.0);
  EXPECT_LT(cpu, 0.05);
}

}  // namespace
}  // namespace luz
