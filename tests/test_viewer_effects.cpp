// Slide 19's switches in a real window: tests/viewer/effects.txt is played on
// scenes/local_effects.gltf by the `viewer_effects_script` CTest fixture (Xvfb, Mesa's software
// GL, as tests/viewer/run_viewer_script.sh does for the classroom script); these tests check what
// it left. Skipped only when xvfb-run is missing (setup.sh installs it).
//
// Tolerances, in 8-bit sRGB codes: a switch "changes the picture" when more than 1% of the values
// move by more than 8 codes; "the same picture as luz render" is test_viewer.cpp's mean
// difference <= 0.5 code with 99.5% of values within 2 codes; the inspector's sum against the
// GPU's pixel within 1% (test_local_terms.cpp's).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
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

const fs::path run_dir = LUZ_VIEWER_EFFECTS_RUN_DIR;

std::vector<int> codes(const fs::path& png, int& width, int& height) {
  const Image image = io::read_image(png);
  width = image.width;
  height = image.height;
  std::vector<int> out;
  for (const Rgb& p : image.pixels)
    for (int c = 0; c < 3; ++c) out.push_back(int(std::lround(255.0f * srgb_encode(p[c]))));
  return out;
}

double share_moved(const fs::path& a, const fs::path& b) {
  int wa = 0, ha = 0, wb = 0, hb = 0;
  const std::vector<int> ca = codes(a, wa, ha), cb = codes(b, wb, hb);
  EXPECT_EQ(ca.size(), cb.size());
  size_t moved = 0;
  for (size_t i = 0; i < ca.size() && i < cb.size(); ++i) moved += std::abs(ca[i] - cb[i]) > 8;
  return double(moved) / double(ca.size());
}

class ViewerEffects : public ::testing::Test {
protected:
  void SetUp() override {
    if (!fs::exists(run_dir / "done")) {
      if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is missing";
      FAIL() << "the scripted viewer did not finish in " << run_dir << " (see the viewer_effects_script test)";
    }
  }
};

TEST_F(ViewerEffects, EachKeyChangesThePicture) {
  for (const char* shot : {"shadows.png", "fog-linear.png", "fog-exponential.png", "transparency.png", "reflection.png"})
    EXPECT_GT(share_moved(run_dir / "plain.png", run_dir / shot), 0.01) << shot;
  EXPECT_GT(share_moved(run_dir / "fog-linear.png", run_dir / "fog-exponential.png"), 0.01) << "G cycles the fog's modes";
}

TEST_F(ViewerEffects, EverythingOnIsWhatLuzRenderMakesWithTheFlags) {
  int width = 0, height = 0;
  const std::vector<int> viewer = codes(run_dir / "all.png", width, height);
  test::ScratchDir dir;
  const fs::path out = dir / "render.png";
  const auto result = test::run_luz({"render", (test::scene_dir() / "local_effects.gltf").string(), "--size",
                                     std::to_string(width) + "x" + std::to_string(height), "--shadows",
                                     "--transparency", "--reflection-map", "--fog", "linear", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  int rw = 0, rh = 0;
  const std::vector<int> render = codes(out, rw, rh);
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

TEST_F(ViewerEffects, TheInspectorShowsTheShadowFactorsAndTheFog) {
  std::ifstream in(run_dir / "all.json");
  const nlohmann::json reading = nlohmann::json::parse(in);
  EXPECT_EQ(reading["material"], "floor");
  ASSERT_EQ(reading["lights"].size(), 6u);
  for (const auto& light : reading["lights"]) EXPECT_TRUE(light.contains("S")) << light.dump();
  EXPECT_LE(reading["fog_factor"].get<float>(), 1.0f);
  for (int c = 0; c < 3; ++c) {
    const float cpu = reading["sum"][c], gpu = reading["gl_pixel"][c];
    EXPECT_NEAR(cpu, gpu, 0.01f * std::max(cpu, gpu) + 1e-5f) << "channel " << c;
  }
}

}  // namespace
}  // namespace luz
