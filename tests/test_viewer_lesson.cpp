// `luz --lesson FILE` opens the viewer on the lesson's first step: its scene, camera, model and
// term switches, the picture `luz render` makes of that state (within the two-contexts tolerance).
#include <gtest/gtest.h>

#include "support.h"
#include "viewer_support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;
using test::Codes;
using test::codes;

const fs::path run_dir = LUZ_VIEWER_RUN_DIR;

class ViewerLesson : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
};

TEST_F(ViewerLesson, OpensOnTheFirstStepsState) {
  const Codes viewer = codes(run_dir / "lesson.png");
  const test::ScratchDir dir;
  auto render = [&](const std::vector<std::string>& flags, const std::string& name) {
    std::vector<std::string> args = {"render", (test::scene_dir() / "phong_spheres.gltf").string(), "--size",
                                     viewer.size(), "--out", (dir / name).string(), "-q"};
    args.insert(args.end(), flags.begin(), flags.end());
    const test::CommandResult result = test::run_luz(args);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return codes(dir / name);
  };
  test::expect_same_picture(viewer, render({"--model", "gouraud", "--no-diffuse"}, "step1.png"));
  // The state mattered: the plain model looks otherwise.
  EXPECT_GT(test::share_moved(viewer, render({"--model", "gouraud"}, "plain.png"), 8), 0.05);
}

}  // namespace
}  // namespace luz
