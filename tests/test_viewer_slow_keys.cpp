// Keys typed into a panel field while frames are slow: tests/viewer/run_viewer_slow_keys.sh plays
// slow_keys.txt on scenes/cornell_box.gltf under Xvfb, radiosity shooting 400 ms a frame, and
// types into radiosity's patch size field through X and GLFW: 0.0577, Backspace, Enter, then '+'.
// Every key counts: Backspace leaves 0.057, Enter commits it and lets the keys go, and '+' is
// then the exposure shortcut, half a stop more. A lost Backspace would leave 0.0577, a lost Enter
// the '+' in the field and the exposure as it was. Skipped when xvfb-run or xdotool is missing.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "viewer_support.h"

namespace luz {
namespace {

const std::filesystem::path run_dir = LUZ_VIEWER_RUN_DIR;

TEST(ViewerSlowKeys, EveryKeyTypedDuringSlowFramesTakesEffect) {
  test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST);
  const nlohmann::json start = test::json_of(run_dir / "start.json");
  // The frames were as slow as those that lost keys (100-600 ms).
  EXPECT_GT(start["frame_ms"].get<double>(), 100.0);
  const nlohmann::json end = test::json_of(run_dir / "end.json");
  EXPECT_DOUBLE_EQ(end["exposure"].get<double>(), start["exposure"].get<double>() + 0.5);
  EXPECT_GT(end["frame_ms"].get<double>(), 100.0);  // still slow while the keys came
  const std::string options = test::json_of(run_dir / "end-radiosity.json")["options"];
  EXPECT_NE(options.find("patch size 0.057 m"), std::string::npos) << options;
}

}  // namespace
}  // namespace luz
