// The hybrid in a real window (issue 6): tests/viewer/hybrid.txt is played on
// scenes/cornell_spheres.gltf by the `viewer_hybrid_script` CTest fixture (Xvfb, Mesa's software
// GL, as tests/viewer/run_viewer_script.sh does for the classroom script); these tests check what
// it left. Skipped only when xvfb-run is missing (setup.sh installs it).
//
// Tolerances, in 8-bit sRGB codes:
// - the untraced model 6 against model 5's picture of the same solution (shooter off), and after
//   a cancelled trace: the same GL context draws the same vertex colours, so every value equal;
// - "the trace changed the picture": more than 5% of the values move by more than 8 codes (the
//   mirror and the glass are dark, diffuse-only spheres in radiosity);
// - the finished trace against `luz render --model hybrid` with the same patch size, hemicube and
//   stopping rule: the same number of shots (deterministic, seeded hemicube turns), then
//   test_viewer.cpp's two-GL-contexts tolerance (the radiosity solve runs on the window's GL here
//   and on OSMesa there; the tracer is the same CPU code): mean difference <= 0.5 code, 99.5% of
//   values within 2 codes.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "io/image_io.h"
#include "support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;

const fs::path run_dir = LUZ_VIEWER_HYBRID_RUN_DIR;

std::vector<int> codes(const fs::path& png, int& width, int& height) {
  const Image image = io::read_image(png);
  width = image.width;
  height = image.height;
  std::vector<int> out;
  for (const Rgb& p : image.pixels)
    for (int c = 0; c < 3; ++c) out.push_back(int(std::lround(255.0f * srgb_encode(p[c]))));
  return out;
}

std::vector<int> codes(const fs::path& png) {
  int w = 0, h = 0;
  return codes(png, w, h);
}

nlohmann::json json_of(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

double share_moved(const std::vector<int>& a, const std::vector<int>& b, int by) {
  EXPECT_EQ(a.size(), b.size());
  size_t moved = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) moved += std::abs(a[i] - b[i]) > by;
  return double(moved) / double(a.size());
}

class ViewerHybrid : public ::testing::Test {
protected:
  void SetUp() override {
    if (!fs::exists(run_dir / "done")) {
      if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is missing";
      FAIL() << "the scripted viewer did not finish in " << run_dir << " (see the viewer_hybrid_script test)";
    }
  }
  static fs::path file(const std::string& name) { return run_dir / name; }
};

TEST_F(ViewerHybrid, KeySixSolvesRadiosityFirstWhenThereIsNone) {
  const nlohmann::json first = json_of(file("first-frames.json"));
  EXPECT_TRUE(first["built"].get<bool>());
  EXPECT_TRUE(first["running"].get<bool>());  // run to the stopping rule without being asked
  EXPECT_GT(first["shots"].get<int>(), 0);
  EXPECT_FALSE(first["done"].get<bool>());
  EXPECT_EQ(json_of(file("untraced.json"))["phase"], "raster");
  const nlohmann::json solved = json_of(file("solved.json"));
  EXPECT_TRUE(solved["done"].get<bool>());
  EXPECT_LT(solved["unshot_fraction"].get<double>(), 0.01);
}

TEST_F(ViewerHybrid, UntracedItShowsTheRadiosityPicture) {
  const std::vector<int> untraced = codes(file("untraced.png"));
  EXPECT_EQ(share_moved(untraced, codes(file("radiosity.png")), 0), 0.0);
  // Backspace cancelled a trace: the radiosity picture is back, the trace says so.
  const nlohmann::json cancelled = json_of(file("cancelled.json"));
  EXPECT_TRUE(cancelled["cancelled"].get<bool>());
  EXPECT_EQ(cancelled["phase"], "raster");
  EXPECT_LT(cancelled["tiles"][0].get<int>(), cancelled["tiles"][1].get<int>());
  EXPECT_EQ(share_moved(untraced, codes(file("after-cancel.png")), 0), 0.0);
}

TEST_F(ViewerHybrid, TracedItIsWhatLuzRenderMakes) {
  const nlohmann::json traced = json_of(file("traced.json"));
  EXPECT_EQ(traced["phase"], "done");
  EXPECT_EQ(traced["tiles"][0], traced["tiles"][1]);
  EXPECT_GT(traced["rays"]["reflected"].get<int>(), 0);
  EXPECT_GT(traced["rays"]["transmitted"].get<int>(), 0);

  int width = 0, height = 0;
  const std::vector<int> viewer = codes(file("traced.png"), width, height);
  EXPECT_GT(share_moved(codes(file("untraced.png")), viewer, 8), 0.05);

  test::ScratchDir dir;
  const fs::path out = dir / "render.png";
  const auto result = test::run_luz({"render", (test::scene_dir() / "cornell_spheres.gltf").string(), "--model",
                                     "hybrid", "--patch-size", "0.15", "--hemicube-res", "128", "--converge", "0.01",
                                     "--size", std::to_string(width) + "x" + std::to_string(height), "--out",
                                     out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::smatch shots;
  ASSERT_TRUE(std::regex_search(result.output, shots, std::regex("(\\d+) shots"))) << result.output;
  EXPECT_EQ(json_of(file("solved.json"))["shots"].get<int>(), std::stoi(shots[1])) << result.output;

  const std::vector<int> render = codes(out);
  ASSERT_EQ(render.size(), viewer.size());
  double total = 0;
  size_t within = 0;
  for (size_t i = 0; i < render.size(); ++i) {
    const int difference = std::abs(render[i] - viewer[i]);
    total += difference;
    within += difference <= 2;
  }
  EXPECT_LE(total / double(render.size()), 0.5);
  EXPECT_GE(double(within) / double(render.size()), 0.995);
}

TEST_F(ViewerHybrid, AClickGivesTheHybridsRayTree) {
  const nlohmann::json tree = json_of(file("tree.json"));
  ASSERT_GE(tree["nodes"].size(), 2u);
  EXPECT_EQ(tree["nodes"][0]["hit"]["mesh"], "mirror_sphere");
  bool reflected = false;
  for (const auto& node : tree["nodes"]) reflected = reflected || node["kind"] == "reflected";
  EXPECT_TRUE(reflected);
}

}  // namespace
}  // namespace luz
