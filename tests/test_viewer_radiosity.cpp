// Radiosity in a real window: tests/viewer/radiosity.txt is played on
// scenes/cornell_box.gltf by the `viewer_radiosity_script` CTest fixture (Xvfb, Mesa's software
// GL, as tests/viewer/run_viewer_script.sh does for the classroom script); these tests check what
// it left. Skipped only when xvfb-run is missing (setup.sh installs it).
//
// Tolerances, in 8-bit sRGB codes:
// - "the picture changes": more than 10% of the values move by more than 8 codes;
// - "more light on the ceiling": the mean code of two ceiling patches of the picture, either
//   side of the lamp, rises by more than 20 (it is near black while only the lamp has shot);
// - the converged picture against `luz render --model radiosity` with the same patch size,
//   hemicube and stopping rule: the same number of shots (the solver is deterministic, its
//   hemicube turns are seeded), then test_viewer.cpp's two-GL-contexts tolerance: mean
//   difference <= 0.5 code, 99.5% of values within 2 codes;
// - the dumped patch: E = pi Le and rho = kd of the scene's material, and at shot 0 slide 39's
//   step 1 (radiosity 0, unshot = B = E, B/pi = Le), to float rounding (1e-6 relative);
// - the plot: more than 1% of the pixels of its frame differ by more than 8 codes between 5 and 300
//   shots (the frame, its scale and decade labels stay: only the curve can differ).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/common.hpp>

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

// The mean code over a rectangle of the picture [x0, x1) x [y0, y1).
double mean_code(const Codes& c, int x0, int y0, int x1, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int k = 0; k < 3; ++k) sum += c.at(x, y, k);
  return sum / (3.0 * (x1 - x0) * (y1 - y0));
}

fs::path scene() { return test::scene_dir() / "cornell_box.gltf"; }

// The mean code of a piece of the ceiling (the plane at the box's top, x0..x1 by z0..z1 in
// metres): its corners projected with the scene camera into a picture of this size, and the
// middle half of their bounding box taken, clear of the walls and of the lamp's edge.
double ceiling_piece(const Codes& c, float x0, float x1, float z0, float z1) {
  const Scene s = io::load_gltf(scene()).scene;
  const Camera& camera = s.cameras[0];
  const glm::mat4 clip = camera.projection(float(c.width) / float(c.height), s.bounds()) * camera.view();
  const float y = s.bounds().max.y;
  glm::vec2 low(1e9f), high(-1e9f);
  for (const float x : {x0, x1})
    for (const float z : {z0, z1}) {
      const glm::vec4 p = clip * glm::vec4(x, y, z, 1.0f);
      const glm::vec2 pixel((p.x / p.w * 0.5f + 0.5f) * float(c.width), (0.5f - p.y / p.w * 0.5f) * float(c.height));
      low = glm::min(low, pixel);
      high = glm::max(high, pixel);
    }
  const glm::vec2 quarter = 0.25f * (high - low);
  const glm::ivec2 a(low + quarter), b(high - quarter);
  EXPECT_GT(b.x - a.x, 10);
  EXPECT_GT(b.y - a.y, 3);
  EXPECT_GE(a.x, 0);
  EXPECT_GE(a.y, 0);
  EXPECT_LE(b.x, c.width);
  EXPECT_LE(b.y, c.height);
  return mean_code(c, a.x, a.y, b.x, b.y);
}

// Two pieces of the ceiling either side of the lamp (which spans x 0.213..0.343 m, z 0.227..0.332 m).
double ceiling(const Codes& c) {
  return 0.5 * (ceiling_piece(c, 0.03f, 0.19f, 0.15f, 0.40f) + ceiling_piece(c, 0.37f, 0.53f, 0.15f, 0.40f));
}

const Material& material_named(const Scene& s, const std::string& name) {
  for (const Material& m : s.materials)
    if (m.name == name) return m;
  ADD_FAILURE() << "no material " << name;
  return s.materials.front();
}

void expect_rgb_near(const nlohmann::json& value, const Rgb& expected, const char* what) {
  for (int c = 0; c < 3; ++c) {
    const float v = value[c];
    EXPECT_NEAR(v, expected[c], 1e-6f * std::max(1.0f, std::abs(expected[c]))) << what << " channel " << c;
  }
}

class ViewerRadiosity : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
  static fs::path file(const std::string& name) { return run_dir / name; }
};

// T on textured.gltf: a square lit from above its middle, its texture's dark texel on the left
// (u = 0.25 at x = -0.5 m) and its light one on the right (u = 0.75 at x = 0.5 m). The two points
// get the same light, so the picture's ratio between them is the texels' (sRGB 64 against 224:
// 0.07 in radiance) with the texture, and 1 without it, where the solution started over.
TEST_F(ViewerRadiosity, TSwitchesTheTextureOffAndStartsTheSolutionOver) {
  EXPECT_EQ(json_of(file("textured.json"))["shots"], 20);
  EXPECT_EQ(json_of(file("untextured.json"))["shots"], 10) << "the solution started over";
  const Scene square = io::load_gltf(file("textured.gltf")).scene;
  const Camera& camera = square.cameras.at(0);
  const auto at = [&](const Codes& c, float x) {  // the mean code about (x, 0, 0)
    const glm::mat4 clip = camera.projection(float(c.width) / float(c.height), square.bounds()) * camera.view();
    const glm::vec4 p = clip * glm::vec4(x, 0.0f, 0.0f, 1.0f);
    const int px = int((p.x / p.w * 0.5f + 0.5f) * float(c.width)), py = int((0.5f - p.y / p.w * 0.5f) * float(c.height));
    return mean_code(c, px - 3, py - 3, px + 4, py + 4);
  };
  const Codes textured = codes(file("textured.png")), untextured = codes(file("untextured.png"));
  EXPECT_GT(at(textured, 0.5f) - at(textured, -0.5f), 100.0) << "the texture's two texels";
  EXPECT_NEAR(at(untextured, 0.5f), at(untextured, -0.5f), 3.0) << "no texture";
  EXPECT_GT(at(untextured, -0.5f), at(textured, -0.5f) + 50.0) << "kd 1 where the texture was dark";
}

// `wait-shots` past the stopping rule, one shot a frame: the shot that meets the rule is its
// frame's last, and the wait ends on it (the script went on to dump it), the solver done and
// paused where the untextured solution stood at 10 shots.
TEST_F(ViewerRadiosity, WaitShotsPastTheRuleEndsOnAFramesLastShot) {
  const nlohmann::json met = json_of(file("rule-met.json"));
  EXPECT_TRUE(met["done"].get<bool>());
  EXPECT_FALSE(met["running"].get<bool>());
  EXPECT_LT(met["unshot_fraction"].get<double>(), 0.005);
  EXPECT_GT(met["shots"].get<int>(), 10);
  EXPECT_LT(met["shots"].get<int>(), 100000);
}

// Before its first shot radiosity shows the emitters alone, white against black: a scene opened in
// radiosity has its exposure checked once a shot has brought light, so the Cornell box's lamp
// alone does not make it look over-exposed. bright.gltf (a Blender-style lamp in candela) does
// get the warning, after its lamp's shot.
TEST_F(ViewerRadiosity, TheExposureIsCheckedOnceAShotHasBroughtLight) {
  const auto exposure_warnings = [](const nlohmann::json& state) {
    int n = 0;
    for (const auto& w : state["warnings"]) n += w.get<std::string>().find("over-exposed") != std::string::npos;
    return n;
  };
  EXPECT_EQ(exposure_warnings(json_of(file("start-state.json"))), 0) << "at shot 0";
  EXPECT_EQ(exposure_warnings(json_of(file("later-state.json"))), 0) << "after 300 shots";
  EXPECT_EQ(exposure_warnings(json_of(file("bright-before.json"))), 0) << "bright.gltf before its lamp's shot";
  EXPECT_EQ(exposure_warnings(json_of(file("bright-after.json"))), 1) << "bright.gltf after it";
}

TEST_F(ViewerRadiosity, AnotherModelShownPausesTheLoopTheHybridKeepsIt) {
  EXPECT_TRUE(json_of(file("switched-to-hybrid.json"))["radiosity_drive"]["running"].get<bool>());
  EXPECT_FALSE(json_of(file("switched-away.json"))["radiosity_drive"]["running"].get<bool>());
  // Shown again, it stays where it was paused until it is run.
  const nlohmann::json back = json_of(file("back.json")), later = json_of(file("back-later.json"));
  EXPECT_FALSE(back["done"].get<bool>()) << "a solution still to converge, or a pause proves nothing";
  EXPECT_FALSE(back["running"].get<bool>());
  EXPECT_EQ(later["shots"], back["shots"]);
}

TEST_F(ViewerRadiosity, WaitShotsPausesAtExactlyThatCount) {
  EXPECT_EQ(json_of(file("start.json"))["shots"], 0);
  const nlohmann::json early = json_of(file("early.json")), later = json_of(file("later.json"));
  EXPECT_EQ(early["shots"], 5);
  EXPECT_EQ(later["shots"], 300);
  EXPECT_FALSE(later["running"].get<bool>());
  EXPECT_EQ(later["patches"], 884);  // `radiosity patch-size 0.1` remeshed the box
  EXPECT_LT(later["unshot_fraction"].get<double>(), early["unshot_fraction"].get<double>());
  // One point per shot, shot 0 included.
  EXPECT_EQ(later["plot_points"], 301);
  // Key '.' shoots once more; key 0 is slide 39's step 1 again.
  EXPECT_EQ(json_of(file("one-more.json"))["shots"], 301);
  const nlohmann::json reset = json_of(file("reset.json"));
  EXPECT_EQ(reset["shots"], 0);
  // Nothing shot: unshot = E. The two powers are the same elements' sums added in another order
  // (by shooting patch and over the whole mesh), so they agree to rounding, not bit for bit.
  EXPECT_NEAR(reset["unshot_fraction"].get<double>(), 1.0, 1e-12);
  EXPECT_EQ(reset["plot_points"], 1);
}

TEST_F(ViewerRadiosity, TheLightSpreadsAsTheShotsGoOn) {
  const Codes early = codes(file("early.png")), later = codes(file("later.png"));
  EXPECT_GT(share_moved(early, later, 8), 0.10);
  const double before = ceiling(early), after = ceiling(later);
  EXPECT_GT(after, before + 20.0) << "ceiling after 5 shots " << before << ", after 300 " << after;
  // Back at shot 0 only the lamp shows: darker than after five shots of it.
  EXPECT_LT(mean_code(codes(file("reset.png")), 0, 0, early.width, early.height),
            mean_code(early, 0, 0, early.width, early.height));
  // The heat map is another picture altogether.
  EXPECT_GT(share_moved(later, codes(file("heat.png")), 8), 0.5);
}

// `radiosity meshing uniform` and `radiosity form-factors hemicube` (a lesson's slide-40 and
// slide-37 steps) start a solution on the mesh as built, by the hemicube.
TEST_F(ViewerRadiosity, MeshingAndFormFactorsCanBeChosenFromAScript) {
  const nlohmann::json uniform = json_of(file("uniform.json"));
  const nlohmann::json start = json_of(file("start.json"));
  EXPECT_GE(uniform["shots"].get<int>(), 100);
  EXPECT_EQ(uniform["refined_elements"].get<size_t>(), 0u);
  EXPECT_EQ(uniform["elements"], start["elements"]);
  const std::string options = uniform["options"].get<std::string>();
  EXPECT_EQ(options.find("adaptive"), std::string::npos) << options;
  EXPECT_NE(options.find("hemicube form factors"), std::string::npos) << options;
  EXPECT_NE(json_of(file("converged.json"))["options"].get<std::string>().find("rays ("), std::string::npos);
}

// The viewer draws each frame once; `luz render` then draws one sample per pixel too.
TEST_F(ViewerRadiosity, ConvergedItIsWhatLuzRenderMakes) {
  const nlohmann::json converged = json_of(file("converged.json"));
  EXPECT_TRUE(converged["done"].get<bool>());
  EXPECT_LT(converged["unshot_fraction"].get<double>(), 0.005);

  const Codes viewer = codes(file("converged.png"));
  test::ScratchDir dir;
  const fs::path out = dir / "render.png";
  const auto result = test::run_luz({"render", scene().string(), "--model", "radiosity", "--patch-size", "0.1",
                                     "--hemicube-res", "128", "--size",
                                     viewer.size(), "--pixel-samples", "1", "--out",
                                     out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::smatch shots;
  ASSERT_TRUE(std::regex_search(result.output, shots, std::regex("(\\d+) shots"))) << result.output;
  EXPECT_EQ(converged["shots"].get<int>(), std::stoi(shots[1])) << result.output;
  // Adaptive subdivision (the default) cut elements while the class watched, and the command's
  // mesh is the same one.
  const nlohmann::json start = json_of(file("start.json"));
  EXPECT_GE(converged["refinement_passes"].get<int>(), 1);
  EXPECT_EQ(converged["elements"].get<size_t>(),
            start["elements"].get<size_t>() + converged["refined_elements"].get<size_t>());
  EXPECT_GT(converged["refined_elements"].get<size_t>(), 0u);
  EXPECT_EQ(json_of(file("reset.json"))["elements"], start["elements"]) << "reset: the mesh as built";

  test::expect_same_picture(codes(out), viewer);
}

// The status line names the mesh as it was built: its patches (the shooters) and elements.
TEST_F(ViewerRadiosity, TheStatusLineCountsPatchesAndElements) {
  const nlohmann::json start = json_of(file("start.json"));
  ASSERT_LT(start["patches"].get<size_t>(), start["elements"].get<size_t>());
  EXPECT_EQ(json_of(file("start-state.json"))["note"].get<std::string>(),
            "radiosity: " + std::to_string(start["patches"].get<size_t>()) + " patches of " +
                std::to_string(start["elements"].get<size_t>()) + " elements, hemicube " +
                std::to_string(start["hemicube_res"].get<int>()));
}

TEST_F(ViewerRadiosity, TheClickedPatchShowsSlide39sQuantities) {
  const Scene s = io::load_gltf(scene()).scene;
  for (const char* name : {"lamp.json", "wall.json"}) {
    const nlohmann::json p = json_of(file(name));
    SCOPED_TRACE(name);
    EXPECT_EQ(p["shots"], 300);
    const Material& m = material_named(s, p["material"]);
    expect_rgb_near(p["E"], std::numbers::pi_v<float> * m.emission, "E = pi Le");
    expect_rgb_near(p["rho"], m.kd, "rho = kd");
    EXPECT_GT(p["area"].get<float>(), 0.0f);
  }
  // Shot 0 (after key 0): unshot = E everywhere, nothing shot, and what step 3 shows is E.
  for (const char* name : {"lamp-reset.json", "wall-reset.json"}) {
    const nlohmann::json p = json_of(file(name));
    SCOPED_TRACE(name);
    EXPECT_EQ(p["shots"], 0);
    const Material& m = material_named(s, p["material"]);
    const Rgb E = std::numbers::pi_v<float> * m.emission;
    expect_rgb_near(p["radiosity"], Rgb(0.0f), "nothing shot");
    expect_rgb_near(p["unshot"], E, "unshot = E");
    expect_rgb_near(p["B"], E, "B = E");
    expect_rgb_near(p["B_over_pi"], m.emission, "B / pi = Le");
  }
  EXPECT_EQ(json_of(file("lamp-reset.json"))["patch"], json_of(file("lamp.json"))["patch"]);  // the same patches
  EXPECT_EQ(json_of(file("wall-reset.json"))["patch"], json_of(file("wall.json"))["patch"]);
  const nlohmann::json lamp = json_of(file("lamp.json")), wall = json_of(file("wall.json"));
  EXPECT_EQ(lamp["material"], "light");
  EXPECT_GT(lamp["E"][0].get<float>(), 1.0f);  // it emits
  EXPECT_EQ(wall["material"], "red");
  EXPECT_EQ(wall["E"][0].get<float>(), 0.0f);
  EXPECT_GT(wall["radiosity"][0].get<float>(), 0.0f);  // it has shot what the lamp gave it
}

TEST_F(ViewerRadiosity, ThePanelPlotsTheUnshotPowerAndTheItemBufferIsShown) {
  const Codes early = codes(file("early-panel.png")), later = codes(file("later-panel.png"));
  const nlohmann::json state = json_of(file("later.json"));
  const int x0 = state["plot_rect"][0], y0 = state["plot_rect"][1], x1 = state["plot_rect"][2], y1 = state["plot_rect"][3];
  ASSERT_GT(x1 - x0, 100);
  ASSERT_GT(y1 - y0, 40);
  EXPECT_EQ(json_of(file("early.json"))["plot_rect"], state["plot_rect"]);  // the same frame
  // The scale is the same (down to below the 1% stop), so only the curve can change.
  size_t differ = 0, pixels = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x, ++pixels)
      for (int c = 0; c < 3; ++c)
        if (std::abs(early.at(x, y, c) - later.at(x, y, c)) > 8) {
          ++differ;
          break;
        }
  EXPECT_GT(double(differ) / double(pixels), 0.01) << differ << " of " << pixels;

  // The item buffer's cross: many false colours, one per patch seen. Paused, it is the last
  // shooter's (running, it may be an earlier one's, and says so by its title).
  ASSERT_TRUE(state["item_view_shown"].get<bool>());
  EXPECT_EQ(state["item_view_shooter"], state["shooter"]);
  EXPECT_EQ(state["shooter"].get<std::string>().rfind("patch ", 0), 0u) << state["shooter"];
  const nlohmann::json reset = json_of(file("reset.json"));
  EXPECT_FALSE(reset["item_view_shown"].get<bool>());
  EXPECT_EQ(reset["item_view_shooter"], "");
  const int ix0 = state["item_view_rect"][0], iy0 = state["item_view_rect"][1];
  const int ix1 = state["item_view_rect"][2], iy1 = state["item_view_rect"][3];
  ASSERT_GT(ix1 - ix0, 50);
  std::set<int> colours;
  for (int y = iy0; y < iy1; ++y)
    for (int x = ix0; x < ix1; ++x) colours.insert((later.at(x, y, 0) << 16) | (later.at(x, y, 1) << 8) | later.at(x, y, 2));
  EXPECT_GT(colours.size(), 100u);
}

}  // namespace
}  // namespace luz
