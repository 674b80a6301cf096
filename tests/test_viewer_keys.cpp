// The exposure keys from a real keyboard: tests/viewer/run_viewer_keys.sh plays keys.txt on
// scenes/phong_spheres.gltf under Xvfb with a Spanish layout, typing the keypad's + and -, and
// the character '+' (the key right of P there), through X and GLFW. Each changes the exposure
// by half a stop: + + - + is one stop more. Skipped when xvfb-run or xdotool is missing.
#include <filesystem>

#include <gtest/gtest.h>

#include "viewer_support.h"

namespace luz {
namespace {

const std::filesystem::path run_dir = LUZ_VIEWER_RUN_DIR;

TEST(ViewerKeys, TheKeypadAndTheCharacterPlusChangeTheExposure) {
  test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST);
  const double start = test::json_of(run_dir / "start.json")["exposure"].get<double>();
  const double end = test::json_of(run_dir / "end.json")["exposure"].get<double>();
  EXPECT_DOUBLE_EQ(end - start, 1.0);
}

}  // namespace
}  // namespace luz
