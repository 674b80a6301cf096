// The path tracer and the difference view in a real window: tests/viewer/path.txt is played on
// scenes/whitted.gltf by the `viewer_path_script` CTest fixture (Xvfb, Mesa's software GL, as
// tests/viewer/run_viewer_script.sh does); these tests check what it left against `luz render`
// and `luz compare` of the same view, run here.
//
// Tolerances:
// - the viewer's path picture after N passes against `luz render --model path --spp N`: none,
//   in 8-bit codes. A pixel's k-th sample depends only on (pixel, seed, k), the viewer shows
//   whole passes and uploads the mean's floats to a float texture that the screenshot reads
//   back through the same encoder as the PNG;
// - the difference view's figures against `luz compare`'s printed ones: half a unit of the last
//   digit printed (the same floats go into the same function: only the printing rounds);
// - its heat map against `luz compare --heatmap`'s: none (the same colours; the script sets the
//   exposure to 1 EV there, and the view divides by the 2 the display pass multiplies by);
// - the sign: every pixel the test finds at least 40% darker (or brighter) than the reference,
//   with its own luminance, is blue (or red) on screen.
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "io/image_io.h"
#include "support.h"
#include "viewer_support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;

const fs::path run_dir = LUZ_VIEWER_RUN_DIR;  // where the fixture played the script

using test::Codes;
using test::codes;
using test::json_of;

fs::path scene() { return test::scene_dir() / "whitted.gltf"; }

class ViewerPath : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
  static fs::path file(const std::string& name) { return run_dir / name; }

public:
  // `luz render SCENE --size WxH ARGS... --out OUT`, which must succeed.
  static void render(const std::string& size, std::vector<std::string> args, const fs::path& out) {
    std::vector<std::string> all = {"render", scene().string(), "--size", size, "-q", "--out", out.string()};
    all.insert(all.end(), args.begin(), args.end());
    const auto result = test::run_luz(all);
    ASSERT_EQ(result.exit_code, 0) << result.output;
  }
};

int largest_difference(const Codes& a, const Codes& b) {
  EXPECT_EQ(a.values.size(), b.values.size());
  int largest = 0;
  for (size_t i = 0; i < a.values.size() && i < b.values.size(); ++i)
    largest = std::max(largest, std::abs(a.values[i] - b.values[i]));
  return largest;
}

std::string size_of(const nlohmann::json& dump) {
  return std::to_string(dump["size"][0].get<int>()) + "x" + std::to_string(dump["size"][1].get<int>());
}

TEST_F(ViewerPath, AfterNPassesThePictureIsLuzRenderWithNSamples) {
  const nlohmann::json dump = json_of(file("path4.json"));
  EXPECT_EQ(dump["spp"], 4);
  EXPECT_EQ(dump["seed"], 7);
  EXPECT_FALSE(dump["running"].get<bool>()) << "it stops at the target";
  EXPECT_GT(dump["noise"].get<double>(), 0.0);
  const Codes viewer = codes(file("path4.png"));
  ASSERT_EQ(viewer.size(), size_of(dump));
  test::ScratchDir dir;
  render(viewer.size(), {"--model", "path", "--spp", "4", "--seed", "7"}, dir / "path.png");
  EXPECT_EQ(largest_difference(viewer, codes(dir / "path.png")), 0);
  // Another seed is another picture: the agreement is not that of two blurred averages.
  render(viewer.size(), {"--model", "path", "--spp", "4", "--seed", "8"}, dir / "other.png");
  EXPECT_GT(largest_difference(viewer, codes(dir / "other.png")), 32);
}

TEST_F(ViewerPath, MovingTheCameraStartsANewPicture) {
  const nlohmann::json before = json_of(file("before-move.json")), after = json_of(file("after-move.json"));
  EXPECT_GE(before["spp"].get<int>(), 6);
  EXPECT_TRUE(before["running"].get<bool>()) << "refining toward 1000 samples";
  EXPECT_LT(after["spp"].get<int>(), before["spp"].get<int>());
  EXPECT_EQ(after["restarts"].get<int>(), before["restarts"].get<int>() + 1);
}

// "mean relative error over lit pixels: 0.1234 (12.34%, 5678 of 171200 pixels lit)" and the
// other lines of `luz compare`, as numbers.
struct Printed {
  double mean_error[3] = {0, 0, 0};
  double rel_rmse = 0.0, mean_relative_error = 0.0;
  int lit = 0;
};

Printed parse_compare(const std::string& out) {
  Printed p;
  std::smatch m;
  const std::string number = "([-+]?[0-9.]+)";
  EXPECT_TRUE(std::regex_search(out, m, std::regex("mean error \\(A - B\\): +R " + number + " +G " + number + " +B " + number)))
      << out;
  for (int c = 0; c < 3 && m.size() == 4; ++c) p.mean_error[c] = std::stod(m[size_t(c) + 1]);
  EXPECT_TRUE(std::regex_search(out, m, std::regex("rel-RMSE: +" + number))) << out;
  if (m.size() == 2) p.rel_rmse = std::stod(m[1]);
  EXPECT_TRUE(std::regex_search(out, m, std::regex("over lit pixels: " + number + " .*, ([0-9]+) of"))) << out;
  if (m.size() == 3) p.mean_relative_error = std::stod(m[1]), p.lit = std::stoi(m[2]);
  return p;
}

// The figures dumped (Whitted's traced picture against 4 passes of seed 7) are what `luz compare`
// prints for the headless renders of the same size; its heat map goes to `heatmap`.
void expect_luz_compares(const nlohmann::json& d, const fs::path& heatmap) {
  ASSERT_TRUE(d["valid"].get<bool>()) << d.dump(1);
  EXPECT_EQ(d["reference_spp"], 4);
  EXPECT_EQ(d["model"], "Whitted");
  const std::string size = size_of(d);
  test::ScratchDir dir;
  ViewerPath::render(size, {"--model", "whitted"}, dir / "whitted.exr");
  ViewerPath::render(size, {"--model", "path", "--spp", "4", "--seed", "7"}, dir / "path.exr");
  const auto compare = test::run_luz({"compare", (dir / "whitted.exr").string(), (dir / "path.exr").string(),
                                      "--heatmap", heatmap.string()});
  ASSERT_EQ(compare.exit_code, 0) << compare.output;
  const Printed p = parse_compare(compare.output);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(d["mean_error"][size_t(c)].get<double>(), p.mean_error[c], 0.5e-6) << c;
  EXPECT_NEAR(d["rel_rmse"].get<double>(), p.rel_rmse, 0.5e-6);
  EXPECT_NEAR(d["mean_relative_error"].get<double>(), p.mean_relative_error, 0.5e-4);
  EXPECT_EQ(d["lit_pixels"].get<int>(), p.lit);
  EXPECT_GT(p.lit, 1000);
}

// The difference view's legend keeps its text inside its window.
void expect_legend_whole(const nlohmann::json& windows) {
  bool found = false;
  for (const auto& w : windows["windows"]) {
    if (!w["name"].get<std::string>().starts_with("difference view")) continue;
    found = true;
    EXPECT_LE(w["content_width"].get<double>(), w["visible_width"].get<double>() + 0.5) << w.dump();
    EXPECT_FALSE(w["scrolls_sideways"].get<bool>()) << w.dump();
  }
  EXPECT_TRUE(found) << windows.dump(1);
}

TEST_F(ViewerPath, TheDifferenceViewsFiguresAreLuzCompares) {
  test::ScratchDir dir;
  expect_luz_compares(json_of(file("difference.json")), dir / "heatmap.png");
  expect_legend_whole(json_of(file("difference-windows.json")));

  // The picture is luz compare's heat map (above its legend), code for code.
  const Codes viewer = codes(file("difference.png")), printed = codes(dir / "heatmap.png");
  ASSERT_EQ(viewer.width, printed.width);
  ASSERT_GT(printed.height, viewer.height);
  int largest = 0;
  for (int y = 0; y < viewer.height; ++y)
    for (int x = 0; x < viewer.width; ++x)
      for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(viewer.at(x, y, c) - printed.at(x, y, c)));
  EXPECT_EQ(largest, 0);
}

TEST_F(ViewerPath, AModelDarkerThanTheReferenceShowsTheNegativeColour) {
  const nlohmann::json d = json_of(file("darker.json"));
  ASSERT_TRUE(d["valid"].get<bool>()) << d.dump(1);
  for (int c = 0; c < 3; ++c) EXPECT_LT(d["mean_error"][size_t(c)].get<double>(), 0.0) << c;
  const Codes viewer = codes(file("darker.png"));
  test::ScratchDir dir;
  render(viewer.size(), {"--model", "whitted", "--no-diffuse"}, dir / "model.exr");
  render(viewer.size(), {"--model", "path", "--spp", "4", "--seed", "7"}, dir / "path.exr");
  const Image model = io::read_image(dir / "model.exr"), reference = io::read_image(dir / "path.exr");
  ASSERT_EQ(model.width, viewer.width);
  ASSERT_EQ(reference.height, viewer.height);
  // The test's own luminance and its own idea of lit: well above the picture's mean / 20.
  auto luminance = [](const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
  double mean = 0.0;
  for (const Rgb& c : reference.pixels) mean += luminance(c);
  mean /= double(reference.pixels.size());
  int darker = 0, darker_blue = 0, brighter = 0, brighter_red = 0, lit = 0;
  for (int y = 0; y < viewer.height; ++y)
    for (int x = 0; x < viewer.width; ++x) {
      const double a = luminance(model.at(x, y)), b = luminance(reference.at(x, y));
      if (b < 0.05 * mean) continue;
      ++lit;
      const int red = viewer.at(x, y, 0), blue = viewer.at(x, y, 2);
      if (a < 0.6 * b) ++darker, darker_blue += blue > red;
      if (a > 1.4 * b) ++brighter, brighter_red += red > blue;
    }
  EXPECT_GT(darker, lit / 5) << "without kd most of the scene is darker";
  EXPECT_EQ(darker_blue, darker);
  EXPECT_EQ(brighter_red, brighter);
}

TEST_F(ViewerPath, TurnedOffThePictureIsTheModelsAgain) {
  test::ScratchDir dir;
  const Codes off = codes(file("off.png"));
  render(off.size(), {"--model", "whitted", "--no-diffuse"}, dir / "model.png");
  EXPECT_EQ(largest_difference(off, codes(dir / "model.png")), 0);
}

// Side by side, the active pane is the one compared: its figures are luz compare's at the
// pane's size; the reference shown in the other pane is not stopped with the difference.
TEST_F(ViewerPath, SideBySideTheActivePaneShowsItsDifference) {
  const nlohmann::json d = json_of(file("pane-difference.json"));
  ASSERT_TRUE(d["valid"].get<bool>()) << d.dump(1);
  const nlohmann::json whole = json_of(file("difference.json"));
  EXPECT_LT(d["size"][0].get<int>(), whole["size"][0].get<int>()) << "a pane is narrower than the picture";
  EXPECT_EQ(d["size"][1], whole["size"][1]);
  test::ScratchDir dir;
  expect_luz_compares(d, dir / "heatmap.png");
  expect_legend_whole(json_of(file("pane-windows.json")));
  const nlohmann::json reference = json_of(file("pane-path.json"));
  EXPECT_EQ(reference["spp"], 8) << reference.dump(1);
}

}  // namespace
}  // namespace luz
