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

class ViewerEffects : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
};

TEST_F(ViewerEffects, EachKeyChangesThePicture) {
  for (const char* shot : {"shadows.png", "fog-linear.png", "fog-exponential.png", "transparency.png", "reflection.png"})
    EXPECT_GT(share_moved(codes(run_dir / "plain.png"), codes(run_dir / shot), 8), 0.01) << shot;
  EXPECT_GT(share_moved(codes(run_dir / "fog-linear.png"), codes(run_dir / "fog-exponential.png"), 8), 0.01) << "G cycles the fog's modes";
}

// What the window shows right of the panel (the picture's top-right corner is the window's)
// is the picture the screenshot saved: with transparency on the local models' displayed values
// cannot be copied (the blend acts on radiance), so the display pass draws them. Its sRGB curve
// follows the PNG encoder's within 0.002 of a code, so a value differs by one code only where
// the radiance lies at the edge between two.
TEST_F(ViewerEffects, TheWindowShowsThePictureWithEveryEffectOn) {
  const Codes window = codes(run_dir / "all-panel.png"), picture = codes(run_dir / "all.png");
  ASSERT_LT(picture.width, window.width);
  const int left = window.width - picture.width;
  Codes shown{picture.width, picture.height, {}};
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x)
      for (int c = 0; c < 3; ++c) shown.values.push_back(window.at(left + x, y, c));
  EXPECT_LT(share_moved(shown, picture, 1), 0.001);
  EXPECT_LT(share_moved(shown, picture, 0), 0.005);
  EXPECT_EQ(json_of(run_dir / "all-state.json")["display_copy"]["copied_panes"].get<int>(), 0);
}

TEST_F(ViewerEffects, EverythingOnIsWhatLuzRenderMakesWithTheFlags) {
  const Codes viewer = codes(run_dir / "all.png");
  test::ScratchDir dir;
  const fs::path out = dir / "render.png";
  const auto result = test::run_luz({"render", (test::scene_dir() / "local_effects.gltf").string(), "--size",
                                     viewer.size(), "--shadows",
                                     "--transparency", "--reflection-map", "--fog", "linear", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  expect_same_picture(codes(out), viewer);
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

// A scene warning a model gives (radiosity names a metal it shows black) is listed in the
// viewer's warnings window, not only printed to the terminal.
TEST_F(ViewerEffects, RadiositysWarningIsShownInTheWindow) {
  const nlohmann::json state = test::json_of(run_dir / "radiosity-state.json");
  bool listed = false;
  for (const auto& w : state["warnings"]) listed |= w.get<std::string>().find("radiosity: material \"Red\" is a metal") != std::string::npos;
  EXPECT_TRUE(listed) << state.dump();
  bool window = false;
  const nlohmann::json windows = test::json_of(run_dir / "radiosity-windows.json");
  for (const auto& w : windows["windows"])
    window |= w["name"].get<std::string>().find("warning") != std::string::npos;
  EXPECT_TRUE(window);
}

}  // namespace
}  // namespace luz
