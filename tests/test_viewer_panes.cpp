// Side by side in a real window (slide 44): tests/viewer/panes.txt is played on
// scenes/phong_spheres.gltf by the `viewer_panes_script` CTest fixture (Xvfb, Mesa's software GL);
// these tests check what it left. Skipped only when xvfb-run is missing.
//
// Each pane is cut out of the panes' screenshot at the place dump-panes gives, its label box
// left out (the label is the headless grid's, drawn over the picture), and compared with
// - the same model alone in the same window, resized so that its picture is the pane's size:
//   at most 1 code (one GL context; a pane is its model's view, nothing else);
// - `luz render --model M --size WxH` at the pane's size: a local pane within test_viewer.cpp's
//   two-contexts tolerance (mean difference <= 0.5 code, 99.5% of the values within 2 codes),
//   a traced pane code for code (the tracer is deterministic and its floats reach the PNG
//   through the same encoder, as test_viewer_whitted.cpp holds for one picture).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/viewer/panes.h"
#include "support.h"
#include "viewer_support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;

const fs::path run_dir = LUZ_VIEWER_RUN_DIR;  // where the fixture played the script

using test::Codes;
using test::codes;
using test::json_of;

fs::path scene() { return test::scene_dir() / "phong_spheres.gltf"; }

struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
  bool contains(int px, int py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};

Rect rect_of(const nlohmann::json& j) { return {j[0].get<int>(), j[1].get<int>(), j[2].get<int>(), j[3].get<int>()}; }

// The values of `picture`'s pixels inside `area` but outside every box of `left_out` (boxes in
// the area's own pixels), as one row.
Codes cut(const Codes& picture, const Rect& area, const std::vector<Rect>& left_out) {
  Codes out;
  out.height = 1;
  for (int y = 0; y < area.height; ++y)
    for (int x = 0; x < area.width; ++x) {
      if (std::any_of(left_out.begin(), left_out.end(), [&](const Rect& r) { return r.contains(x, y); })) continue;
      for (int c = 0; c < 3; ++c) out.values.push_back(picture.at(area.x + x, area.y + y, c));
      ++out.width;
    }
  return out;
}

int largest_difference(const Codes& a, const Codes& b) {
  EXPECT_EQ(a.values.size(), b.values.size());
  int largest = 0;
  for (size_t i = 0; i < a.values.size() && i < b.values.size(); ++i)
    largest = std::max(largest, std::abs(a.values[i] - b.values[i]));
  return largest;
}

bool traced(const std::string& model) { return model == "whitted" || model == "hybrid"; }

class ViewerPanes : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
  static fs::path file(const std::string& name) { return run_dir / name; }

  // `luz render --model MODEL` of the scene camera at `size`, as codes.
  static Codes rendered(const std::string& model, int width, int height) {
    test::ScratchDir dir;
    const fs::path out = dir / "render.png";
    const auto result = test::run_luz({"render", scene().string(), "--model", model, "--size",
                                       std::to_string(width) + "x" + std::to_string(height), "-q", "--out", out.string()});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return codes(out);
  }

  // Every pane of a screenshot against its model alone (alone-MODEL-SUFFIX.png, the local
  // models) and against `luz render` of its model at the pane's size.
  static void expect_panes_rendered(const std::string& screenshot, const std::string& dump, const std::string& suffix,
                                    const std::vector<std::string>& expected_models) {
    const Codes shot = codes(file(screenshot));
    const nlohmann::json panes = json_of(file(dump))["panes"];
    ASSERT_EQ(panes.size(), expected_models.size());
    for (size_t i = 0; i < panes.size(); ++i) {
      const std::string model = panes[i]["model"];
      SCOPED_TRACE("pane " + std::to_string(i) + ": " + model);
      EXPECT_EQ(model, expected_models[i]);
      const Rect area = rect_of(panes[i]["screenshot"]);
      const Rect label = rect_of(panes[i]["screenshot_label"]);
      const Rect everything{0, 0, area.width, area.height};
      const Codes viewer = cut(shot, area, {label});
      if (const fs::path alone = file("alone-" + model + "-" + suffix + ".png"); fs::exists(alone)) {
        const Codes picture = codes(alone);
        ASSERT_EQ(picture.size(), std::to_string(area.width) + "x" + std::to_string(area.height));
        EXPECT_LE(largest_difference(viewer, cut(picture, everything, {label})), 1);
      } else {
        EXPECT_TRUE(traced(model)) << "no picture of " << model << " alone to compare with";
      }
      const Codes render = cut(rendered(model, area.width, area.height), everything, {label});
      if (traced(model)) EXPECT_EQ(largest_difference(viewer, render), 0);
      else test::expect_same_picture(viewer, render);
    }
  }
};

TEST_F(ViewerPanes, TwoPanesAreEachTheirModelsPicture) {
  expect_panes_rendered("two.png", "two.json", "2", {"gouraud", "whitted"});
  // Side by side: each pane half the picture's width, its full height.
  const nlohmann::json panes = json_of(file("two.json"))["panes"];
  const Rect a = rect_of(panes[0]["screenshot"]), b = rect_of(panes[1]["screenshot"]);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(b.x, a.x + a.width);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.width, (1280 - 440) / 2);
}

TEST_F(ViewerPanes, FourPanesAreEachTheirModelsPicture) {
  expect_panes_rendered("four.png", "four.json", "4", {"flat", "gouraud", "phong", "whitted"});
  const nlohmann::json panes = json_of(file("four.json"))["panes"];
  const Rect first = rect_of(panes[0]["screenshot"]), last = rect_of(panes[3]["screenshot"]);
  EXPECT_EQ(last.x, first.width);  // 2 x 2, from the top-left
  EXPECT_EQ(last.y, first.height);
  const Codes shot = codes(file("four.png"));
  EXPECT_EQ(shot.width, 2 * first.width);  // the headless grid's sheet
  EXPECT_EQ(shot.height, 2 * first.height);
}

// What the window shows: each pane's picture in its rectangle (the window is 1280x760 pixels,
// one a unit under Xvfb), but for the labels, within 1 code of its float picture (the display
// pass encodes on the GPU what the screenshot encodes on the CPU).
TEST_F(ViewerPanes, TheWindowShowsEachPaneInItsRectangle) {
  const Codes window = codes(file("four-window.png")), panes_shot = codes(file("four.png"));
  ASSERT_EQ(window.size(), "1280x760");
  const nlohmann::json panes = json_of(file("four.json"))["panes"];
  for (size_t i = 0; i < panes.size(); ++i) {
    SCOPED_TRACE("pane " + std::to_string(i));
    const nlohmann::json& r = panes[i]["rect"];
    const nlohmann::json& l = panes[i]["label_rect"];
    const Rect in_window{int(r[0].get<float>()), int(r[1].get<float>()), int(r[2].get<float>() - r[0].get<float>()),
                         int(r[3].get<float>() - r[1].get<float>())};
    const Rect window_label{0, 0, int(std::ceil(l[2].get<float>() - r[0].get<float>())),
                            int(std::ceil(l[3].get<float>() - r[1].get<float>()))};
    const std::vector<Rect> labels = {window_label, rect_of(panes[i]["screenshot_label"])};
    const Rect area = rect_of(panes[i]["screenshot"]);
    ASSERT_EQ(in_window.width, area.width);
    ASSERT_EQ(in_window.height, area.height);
    EXPECT_LE(largest_difference(cut(window, in_window, labels), cut(panes_shot, area, labels)), 1);
  }
}

// Each label is the model's name as the headless grid writes it, in a box at the top-left.
TEST_F(ViewerPanes, EachPaneIsLabelledWithItsModel) {
  const nlohmann::json panes = json_of(file("four.json"))["panes"];
  const std::vector<std::string> labels = {"flat", "Gouraud", "Phong", "Whitted"};
  for (size_t i = 0; i < panes.size(); ++i) {
    EXPECT_EQ(panes[i]["label"], labels[i]);
    const nlohmann::json& rect = panes[i]["rect"];
    const nlohmann::json& label = panes[i]["label_rect"];
    EXPECT_EQ(label[0], rect[0]);
    EXPECT_EQ(label[1], rect[1]);
    EXPECT_LT(label[2].get<float>(), rect[2].get<float>());
    EXPECT_LT(label[3].get<float>(), rect[3].get<float>());
  }
}

// One camera: after a drag every pane was drawn from the same new place, and every pane's
// picture moved; Whitted's pane, back to its raster view, is the Phong pane's picture.
TEST_F(ViewerPanes, AnOrbitMovesEveryPane) {
  const nlohmann::json before = json_of(file("four.json"))["panes"];
  const nlohmann::json after = json_of(file("orbited.json"))["panes"];
  ASSERT_EQ(after.size(), 4u);
  for (size_t i = 0; i < after.size(); ++i) {
    EXPECT_EQ(before[i]["camera"], before[0]["camera"]);
    EXPECT_EQ(after[i]["camera"], after[0]["camera"]) << "pane " << i << " did not follow";
  }
  EXPECT_NE(after[0]["camera"]["position"], before[0]["camera"]["position"]);
  EXPECT_NE(after[0]["camera"]["forward"], before[0]["camera"]["forward"]);

  const Codes four = codes(file("four.png")), orbited = codes(file("orbited.png"));
  for (size_t i = 0; i < after.size(); ++i) {
    const Rect area = rect_of(after[i]["screenshot"]), label = rect_of(after[i]["screenshot_label"]);
    EXPECT_GT(test::share_moved(cut(four, area, {label}), cut(orbited, area, {label}), 8), 0.05) << "pane " << i;
  }
  const Rect phong = rect_of(after[2]["screenshot"]), whitted = rect_of(after[3]["screenshot"]);
  const std::vector<Rect> labels = {rect_of(after[2]["screenshot_label"]), rect_of(after[3]["screenshot_label"])};
  EXPECT_LE(largest_difference(cut(orbited, phong, labels), cut(orbited, whitted, labels)), 1);
}

// A click on the Whitted pane: that pane becomes the active one and its ray tree is the one
// `luz render --ray-tree` traces at the pane's size, for the pixel under the click in that pane.
TEST_F(ViewerPanes, AClickOnATracedPaneGivesThatPanesRayTree) {
  const nlohmann::json clicked = json_of(file("clicked.json"));
  EXPECT_EQ(clicked["active"], 3);
  const nlohmann::json& pane = clicked["panes"][3];
  const nlohmann::json tree = json_of(file("tree.json"));
  const int x = tree["pixel"][0], y = tree["pixel"][1];
  EXPECT_EQ(x, int(std::floor(1000.0f - pane["rect"][0].get<float>())));
  EXPECT_EQ(y, int(std::floor(500.0f - pane["rect"][1].get<float>())));
  const Rect area = rect_of(pane["screenshot"]);
  EXPECT_EQ(tree["size"][0], area.width);
  EXPECT_EQ(tree["size"][1], area.height);

  test::ScratchDir dir;
  const auto result = test::run_luz({"render", scene().string(), "--model", "whitted", "--size",
                                     std::to_string(area.width) + "x" + std::to_string(area.height), "--ray-tree",
                                     std::to_string(x) + "," + std::to_string(y), "-q", "--out", (dir / "w.png").string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(tree, json_of(dir / "w.ray-tree.json"));
}

// `panes off`: one picture again, of the active pane's model, over the whole view.
TEST_F(ViewerPanes, PanesOffShowsTheActiveModelAlone) {
  const nlohmann::json single = json_of(file("single.json"));
  ASSERT_EQ(single["panes"].size(), 1u);
  EXPECT_EQ(single["panes"][0]["model"], "whitted");
  EXPECT_EQ(single["panes"][0]["rect"][0], 440.0);
  EXPECT_EQ(single["panes"][0]["rect"][2], 1280.0);
}

// ---- lists the window refuses: a usage error before any window opens -------------------------
struct Refused {
  const char* list;
  const char* says;
};

TEST(PaneLists, BadListsAreUsageErrorsNamingTheProblem) {
  for (const Refused& r : {Refused{"flat,nosuch", "unknown model \"nosuch\""},
                           Refused{"flat,gouraud,phong,whitted,radiosity", "at most 4 models, not 5"},
                           Refused{"phong,phong", "phong is in the list twice"},
                           Refused{"flat,", "unknown model \"\""}}) {
    SCOPED_TRACE(r.list);
    const auto option = test::run_luz({"--lang", "en", "--model", r.list, scene().string()}, {.cwd = {}, .no_display = true});
    EXPECT_EQ(option.exit_code, 2) << option.output;
    EXPECT_NE(option.output.find(r.says), std::string::npos) << option.output;

    test::ScratchDir dir;
    std::ofstream(dir / "demo.txt") << "wait 1\npanes " << r.list << "\n";
    const auto script = test::run_luz({"--lang", "en", "--script", (dir / "demo.txt").string(), scene().string()},
                                      {.cwd = {}, .no_display = true});
    EXPECT_EQ(script.exit_code, 2) << script.output;
    EXPECT_NE(script.output.find("demo.txt:2: "), std::string::npos) << script.output;
    EXPECT_NE(script.output.find(r.says), std::string::npos) << script.output;
  }
}

TEST(PaneLists, TheWindowTakesOneToFourModels) {
  EXPECT_EQ(app::pane_list_problem({"phong"}), "");
  EXPECT_EQ(app::pane_list_problem({"radiosity", "hybrid"}), "");
  EXPECT_EQ(app::pane_list_problem({"flat", "gouraud", "phong"}), "");
  EXPECT_EQ(app::pane_list_problem({"flat", "gouraud", "phong", "whitted"}), "");
  EXPECT_NE(app::pane_list_problem({}), "");
}

// ---- the tiling ---------------------------------------------------------------------------------
// Equal panes of whole pixels inside the view, apart, from its top-left corner (row 0 at the
// top in window units, at the bottom in GL's pixels); a point finds the pane it is in.
TEST(PaneTiling, PanesTileThePictureInWholePixels) {
  app::Viewport view;
  view.origin = {440.0f, 0.0f};
  view.scale = {2.0f, 2.0f};  // HiDPI: two pixels a unit
  view.pixels = {1681, 1457};
  view.size = glm::vec2(view.pixels) / view.scale;
  view.gl_origin = {880, 63};
  for (size_t count : {2u, 3u, 4u}) {
    SCOPED_TRACE(count);
    const std::vector<app::Viewport> panes = app::pane_viewports(view, count);
    ASSERT_EQ(panes.size(), count);
    const int columns = 2, rows = count == 2 ? 1 : 2;
    for (size_t i = 0; i < count; ++i) {
      const app::Viewport& p = panes[i];
      EXPECT_EQ(p.pixels, glm::ivec2(view.pixels.x / columns, view.pixels.y / rows));
      const glm::ivec2 cell(int(i) % columns, int(i) / columns);
      EXPECT_EQ(p.gl_origin.x, view.gl_origin.x + cell.x * p.pixels.x);
      EXPECT_EQ(p.gl_origin.y + p.pixels.y, view.gl_origin.y + view.pixels.y - cell.y * p.pixels.y);
      EXPECT_EQ(view.pixel_of(p.origin), cell * p.pixels);
      EXPECT_EQ(p.pixel_of(p.origin), glm::ivec2(0));
      EXPECT_EQ(app::pane_at(panes, p.centre()), int(i));
      EXPECT_LE(p.origin.x + p.size.x, view.origin.x + view.size.x);
      EXPECT_LE(p.origin.y + p.size.y, view.origin.y + view.size.y);
    }
  }
  EXPECT_EQ(app::pane_at(app::pane_viewports(view, 3), view.origin + 0.9f * view.size), -1);  // the empty quarter
  EXPECT_EQ(app::pane_viewports(view, 1).front().pixels, view.pixels);
}

}  // namespace
}  // namespace luz
