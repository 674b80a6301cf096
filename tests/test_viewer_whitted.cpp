// Whitted's model in a real window: tests/viewer/whitted.txt is played on
// scenes/whitted.gltf by the `viewer_whitted_script` CTest fixture (Xvfb, Mesa's software GL, as
// tests/viewer/run_viewer_script.sh does for the classroom script); these tests check what it
// left. Skipped only when xvfb-run is missing (setup.sh installs it).
//
// Tolerances, in 8-bit sRGB codes:
// - a finished trace's screenshot against `luz render --model whitted`: none. The viewer uploads
//   the tracer's floats to a float texture and the screenshot reads them back through the same
//   encoder, and the tracer is deterministic bit for bit, so every code must be equal;
// - the raster view against `luz render --model phong`: test_viewer.cpp's (two GL contexts):
//   mean difference <= 0.5 code, 99.5% of values within 2 codes; against the viewer's own Phong
//   picture (same context): at most 1 code;
// - the dumped ray tree against `luz render --ray-tree`'s JSON: equal, number for number;
// - the ray tree drawn: at least 90% of the points sampled along its secondary rays (projected
//   with the scene camera, 4 pixels inside the picture) change by more than 24 codes within one
//   pixel of the point, and no pixel farther than 6 pixels from every ray changes by more than 1.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "io/gltf_loader.h"
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
using test::share_moved;

int largest_difference(const Codes& a, const Codes& b) {
  EXPECT_EQ(a.values.size(), b.values.size());
  int largest = 0;
  for (size_t i = 0; i < a.values.size() && i < b.values.size(); ++i)
    largest = std::max(largest, std::abs(a.values[i] - b.values[i]));
  return largest;
}

fs::path scene() { return test::scene_dir() / "whitted.gltf"; }

class ViewerWhitted : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
  static fs::path file(const std::string& name) { return run_dir / name; }
};

TEST_F(ViewerWhitted, BeforeATraceTheModelShowsTheRasterView) {
  EXPECT_LE(largest_difference(codes(file("raster.png")), codes(file("phong.png"))), 1);
  EXPECT_EQ(json_of(file("before.json"))["phase"], "raster");
}

TEST_F(ViewerWhitted, AFinishedTraceIsWhatLuzRenderMakes) {
  const Codes viewer = codes(file("traced.png"));
  test::ScratchDir dir;
  const fs::path out = dir / "render.png";
  const auto result = test::run_luz({"render", scene().string(), "--model", "whitted", "--size", viewer.size(),
                                     "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(largest_difference(viewer, codes(out)), 0);
  // And it is not the raster view: the spheres reflect and refract.
  EXPECT_GT(largest_difference(viewer, codes(file("raster.png"))), 64);

  const nlohmann::json traced = json_of(file("traced.json"));
  EXPECT_EQ(traced["phase"], "done");
  EXPECT_EQ(traced["tiles"][0], traced["tiles"][1]);
  EXPECT_EQ(traced["rays"]["primary"].get<long>(), long(viewer.width) * viewer.height);
  for (const char* kind : {"shadow", "reflected", "transmitted"}) EXPECT_GT(traced["rays"][kind].get<long>(), 0) << kind;
  // The same rays as `luz render`'s, every kind: which lights get a shadow ray does not depend on
  // the thread that traces (its flush-to-zero mode, hit_math.h's lights_the_hit).
  test::expect_rays_of_render(traced, result.output);
}

// A trace that ends with no input is drawn whole: the counters it adds lengthen the panel, and
// the scrollbar ImGui sizes from the frame before's contents is the one a later frame draws.
TEST_F(ViewerWhitted, TheEndOfATraceReachesTheScreenWithoutInput) {
  const Codes idle = codes(file("ended-idle-shown.png"));
  const Codes later = codes(file("ended-later-shown.png"));
  ASSERT_EQ(idle.width, later.width);
  ASSERT_EQ(idle.height, later.height);
  // Above the status line, whose message the first screenshot changed ("saved ...").
  int moved = 0;
  for (int y = 0; y < idle.height - 40; ++y)
    for (int x = 0; x < idle.width; ++x)
      for (int c = 0; c < 3; ++c) moved += std::abs(idle.at(x, y, c) - later.at(x, y, c)) > 2;
  EXPECT_EQ(moved, 0);
}

// `wait-until trace-done` (the traced view answers the condition) returns once every tile landed.
TEST_F(ViewerWhitted, WaitUntilTraceDoneWaitsForTheLastTile) {
  const nlohmann::json done = json_of(file("until-done.json"));
  EXPECT_EQ(done["phase"], "done");
  EXPECT_GT(done["tiles"][1].get<int>(), 0);
  EXPECT_EQ(done["tiles"][0], done["tiles"][1]);
}

// The script holds the trace (`trace --held`: no tile lands until it is cancelled), so on any
// machine the camera moves while it runs.
TEST_F(ViewerWhitted, MovingTheCameraCancelsTheTraceAndReturnsToTheRasterView) {
  const nlohmann::json running = json_of(file("running.json"));
  EXPECT_EQ(running["phase"], "tracing");
  EXPECT_EQ(running["tiles"][0], 0);
  EXPECT_GT(running["tiles"][1].get<int>(), 0);
  const nlohmann::json cancelled = json_of(file("cancelled.json"));
  EXPECT_EQ(cancelled["phase"], "raster");
  EXPECT_TRUE(cancelled["cancelled"].get<bool>());
  EXPECT_EQ(cancelled["tiles"][0], 0);
  EXPECT_EQ(cancelled["tiles"][1], running["tiles"][1]);

  // Back at the scene camera: the raster picture, which is `luz render --model phong`.
  const Codes after = codes(file("after-cancel.png"));
  EXPECT_LE(largest_difference(after, codes(file("raster.png"))), 1);
  test::ScratchDir dir;
  const fs::path out = dir / "phong.png";
  const auto result = test::run_luz({"render", scene().string(), "--model", "phong", "--size", after.size(), "-q",
                                     "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  test::expect_same_picture(codes(out), after);
}

TEST_F(ViewerWhitted, TheClickedPixelsRayTreeIsLuzRendersRayTree) {
  const nlohmann::json viewer = json_of(file("tree.json"));
  const int x = viewer["pixel"][0], y = viewer["pixel"][1];
  const int w = viewer["size"][0], h = viewer["size"][1];
  EXPECT_EQ(x, 520);  // whitted.txt's click-picture 520 330
  EXPECT_EQ(y, 330);
  test::ScratchDir dir;
  const fs::path out = dir / "w.png";
  const auto result = test::run_luz({"render", scene().string(), "--model", "whitted", "--size",
                                     std::to_string(w) + "x" + std::to_string(h), "--ray-tree",
                                     std::to_string(x) + "," + std::to_string(y), "-q", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const nlohmann::json render = json_of(dir / "w.ray-tree.json");
  EXPECT_EQ(viewer, render) << "viewer:\n" << viewer.dump(1) << "\nluz render:\n" << render.dump(1);
  EXPECT_GE(viewer["nodes"].size(), 3u);
}

TEST_F(ViewerWhitted, TheRayTreeIsDrawnAlongItsRays) {
  const Codes with = codes(file("tree.png")), without = codes(file("no-tree.png"));
  ASSERT_EQ(with.values.size(), without.values.size());
  const nlohmann::json tree = json_of(file("tree.json"));
  const Scene s = io::load_gltf(scene()).scene;
  const Camera& camera = s.cameras[0];  // the script clicked from the scene camera
  const glm::mat4 clip = camera.projection(float(with.width) / float(with.height), s.bounds()) * camera.view();
  const float size = glm::length(s.bounds().extent());

  auto differs = [&](int x, int y, int tolerance) {
    for (int c = 0; c < 3; ++c)
      if (std::abs(with.at(x, y, c) - without.at(x, y, c)) > tolerance) return true;
    return false;
  };
  std::vector<char> near(size_t(with.width) * with.height, 0);  // within 6 pixels of a ray
  int sampled = 0, seen = 0;
  for (const auto& node : tree["nodes"]) {
    const glm::vec3 o(node["origin"][0], node["origin"][1], node["origin"][2]);
    const glm::vec3 d(node["direction"][0], node["direction"][1], node["direction"][2]);
    const bool shadow = node["kind"] == "shadow";
    const float t = shadow ? node["distance"].get<float>() : node["hit"].is_null() ? size : node["hit"]["t"].get<float>();
    for (int i = 0; i <= 400; ++i) {
      const glm::vec4 p = clip * glm::vec4(o + (t * float(i) / 400.0f) * d, 1.0f);
      if (p.w <= 0.0f) continue;
      const float px = (p.x / p.w * 0.5f + 0.5f) * float(with.width), py = (0.5f - p.y / p.w * 0.5f) * float(with.height);
      const int x = int(std::floor(px)), y = int(std::floor(py));
      for (int dy = -6; dy <= 6; ++dy)
        for (int dx = -6; dx <= 6; ++dx)
          if (x + dx >= 0 && y + dy >= 0 && x + dx < with.width && y + dy < with.height)
            near[size_t(y + dy) * with.width + x + dx] = 1;
      if (node["kind"] == "primary" || x < 4 || y < 4 || x >= with.width - 4 || y >= with.height - 4) continue;
      ++sampled;
      bool changed = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) changed |= differs(x + dx, y + dy, 24);
      seen += changed;
    }
  }
  ASSERT_GE(sampled, 100) << "the secondary rays cross the picture";
  EXPECT_GE(double(seen) / sampled, 0.9) << seen << " of " << sampled << " points along the rays changed";
  int elsewhere = 0;
  for (int y = 0; y < with.height; ++y)
    for (int x = 0; x < with.width; ++x) elsewhere += !near[size_t(y) * with.width + x] && differs(x, y, 1);
  EXPECT_EQ(elsewhere, 0) << "pixels away from the rays changed";
}

}  // namespace
}  // namespace luz
