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
#include "viewer_support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;

const fs::path run_dir = LUZ_VIEWER_RUN_DIR;  // where the fixture played the script

using test::Codes;
using test::codes;
using test::json_of;
using test::expect_same_picture;
using test::share_moved;

class ViewerHybrid : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
  static fs::path file(const std::string& name) { return run_dir / name; }
};

// The script presses 6 and waits for the solver's stopping rule (`wait-until radiosity-done`),
// never asking it to run: key 6 did.
TEST_F(ViewerHybrid, KeySixSolvesRadiosityFirstWhenThereIsNone) {
  EXPECT_EQ(json_of(file("untraced.json"))["phase"], "raster");
  const nlohmann::json solved = json_of(file("solved.json"));
  EXPECT_TRUE(solved["built"].get<bool>());
  EXPECT_TRUE(solved["done"].get<bool>());
  EXPECT_FALSE(solved["running"].get<bool>());  // stopped by its rule
  EXPECT_GT(solved["shots"].get<int>(), 0);
  EXPECT_LT(solved["unshot_fraction"].get<double>(), 0.005);
}

TEST_F(ViewerHybrid, UntracedItShowsTheRadiosityPicture) {
  const Codes untraced = codes(file("untraced.png"));
  EXPECT_EQ(share_moved(untraced, codes(file("radiosity.png")), 0), 0.0);
  // Backspace cancelled a trace (held by the script, so it was still running): the radiosity
  // picture is back, the trace says so.
  const nlohmann::json cancelled = json_of(file("cancelled.json"));
  EXPECT_TRUE(cancelled["cancelled"].get<bool>());
  EXPECT_EQ(cancelled["phase"], "raster");
  EXPECT_EQ(cancelled["tiles"][0], 0);
  EXPECT_GT(cancelled["tiles"][1].get<int>(), 0);
  EXPECT_EQ(share_moved(untraced, codes(file("after-cancel.png")), 0), 0.0);
}

TEST_F(ViewerHybrid, TracedItIsWhatLuzRenderMakes) {
  const nlohmann::json traced = json_of(file("traced.json"));
  EXPECT_EQ(traced["phase"], "done");
  EXPECT_EQ(traced["tiles"][0], traced["tiles"][1]);
  EXPECT_GT(traced["rays"]["reflected"].get<int>(), 0);
  EXPECT_GT(traced["rays"]["transmitted"].get<int>(), 0);

  const Codes viewer = codes(file("traced.png"));
  EXPECT_GT(share_moved(codes(file("untraced.png")), viewer, 8), 0.05);

  test::ScratchDir dir;
  const fs::path out = dir / "render.png";
  const auto result = test::run_luz({"render", (test::scene_dir() / "cornell_spheres.gltf").string(), "--model",
                                     "hybrid", "--patch-size", "0.15", "--hemicube-res", "128",
                                     "--size", viewer.size(), "--out",
                                     out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::smatch shots;
  ASSERT_TRUE(std::regex_search(result.output, shots, std::regex("(\\d+) shots"))) << result.output;
  EXPECT_EQ(json_of(file("solved.json"))["shots"].get<int>(), std::stoi(shots[1])) << result.output;

  expect_same_picture(codes(out), viewer);
  test::expect_rays_of_render(traced, result.output);
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
