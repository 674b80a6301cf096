// The viewer in a real window: tests/viewer/classroom.txt is played by the `viewer_classroom_script` CTest
// fixture (tests/viewer/run_viewer_script.sh: Xvfb, Mesa's software GL); these tests check what
// it left behind: screenshots with and without the panel, and the inspector's values as JSON.
// They are skipped only when xvfb-run is missing (setup.sh installs it, so CI runs them).
//
// Tolerances, in 8-bit sRGB codes: "the same picture" allows 1 code (one rounding); the viewer
// against `luz render` (two GL contexts, GLX and OSMesa, both llvmpipe) a mean difference of
// at most 0.5 code with 99.5% of the values within 2 codes. The inspector's terms against slide
// 15's formula worked out here in double precision from the scene file, at the dumped point and
// normal: 1e-5 relative (the inspector works in floats, about 1e-7 an operation, and cos^5
// multiplies the cosine's relative error by five).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

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
using nlohmann::json;

class ViewerRun : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
  static fs::path file(const std::string& name) { return run_dir / name; }
};

// The picture's rectangle in the window, as the viewer dumped it: x0, y0, x1, y1.
std::vector<int> picture_rect() {
  return json_of(run_dir / "windows.json")["view"].get<std::vector<int>>();
}

// The fraction of the window's picture area (right of the panel) that differs by more than
// `codes` from `picture`.
double differing_in_picture_area(const Codes& window, const Codes& picture, int tolerance) {
  const int left = picture_rect()[0];
  size_t differing = 0;
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x)
      for (int c = 0; c < 3; ++c)
        if (std::abs(window.at(left + x, y, c) - picture.at(x, y, c)) > tolerance) {
          ++differing;
          break;
        }
  return double(differing) / (double(picture.width) * picture.height);
}

size_t count_colour(const Codes& image, int r, int g, int b) {
  size_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (std::abs(image.at(x, y, 0) - r) <= 3 && std::abs(image.at(x, y, 1) - g) <= 3 &&
          std::abs(image.at(x, y, 2) - b) <= 3)
        ++n;
  return n;
}

TEST_F(ViewerRun, ThePanelIsBesideThePictureNotOverIt) {
  const Codes window = codes(file("phong-panel.png"));
  const Codes picture = codes(file("phong.png"));
  const std::vector<int> view = picture_rect();
  // The picture fills the window right of the panel, above the status line: the screenshot
  // without the panel is that rectangle, pixel for pixel.
  ASSERT_EQ(picture.width, view[2] - view[0]);
  ASSERT_EQ(picture.height, view[3] - view[1]);
  ASSERT_EQ(view[2], window.width);
  ASSERT_EQ(view[1], 0);
  ASSERT_GT(view[0], 0);                     // the panel takes the left part
  ASSERT_LT(view[3], window.height);         // the status line the bottom
  // The window's picture area is the scene-only screenshot (no panel, no inspector yet).
  EXPECT_LT(differing_in_picture_area(window, picture, 1), 0.001);
  // Every named widget lies in the panel, none over the picture.
  const nlohmann::json widgets = json_of(file("widgets.json"))["widgets"];
  ASSERT_GT(widgets.size(), 20u);
  for (const auto& w : widgets) EXPECT_LE(w["rect"][2].get<float>(), float(view[0])) << w["label"];

  // The panel area looks like a panel: mostly one flat background, with light text on it.
  const int panel_width = view[0];
  std::map<int, size_t> colours;
  size_t text = 0;
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < panel_width; ++x) {
      const int r = window.at(x, y, 0), g = window.at(x, y, 1), b = window.at(x, y, 2);
      ++colours[(r << 16) | (g << 8) | b];
      if (r > 180 && g > 180 && b > 180) ++text;
    }
  size_t most = 0;
  for (const auto& [colour, n] : colours) most = std::max(most, n);
  const double area = double(panel_width) * picture.height;
  EXPECT_GT(double(most) / area, 0.4) << "no flat panel background";
  EXPECT_GT(double(text) / area, 0.005) << "no text on the panel";
}

TEST_F(ViewerRun, SwitchingOffTheSpecularTermTakesTheHighlightsAway) {
  const Codes with = codes(file("phong.png")), without = codes(file("no-specular.png"));
  ASSERT_EQ(with.values.size(), without.values.size());
  size_t darker = 0, brighter = 0;
  for (size_t i = 0; i < with.values.size(); ++i) {
    if (without.values[i] > with.values[i] + 1) ++brighter;
    if (without.values[i] < with.values[i] - 10) ++darker;
  }
  EXPECT_EQ(brighter, 0u);  // a term only adds light
  EXPECT_GT(double(darker) / double(with.values.size()), 0.005);  // the highlights are gone

  // The panel shows it too: the specular term is greyed in the formula and its box unticked.
  const Codes panel_with = codes(file("phong-panel.png")), panel_without = codes(file("no-specular-panel.png"));
  const int panel_width = picture_rect()[0];
  size_t changed = 0;
  for (int y = 0; y < with.height; ++y)
    for (int x = 0; x < panel_width; ++x)
      if (panel_with.at(x, y, 0) != panel_without.at(x, y, 0)) ++changed;
  EXPECT_GT(changed, 100u);
}

// Slide 15 at the inspected point, from the scene file: I_A = Ia ka and, for each light,
// IL = I f_att / pi with f_att = 1 / d^2, I_D = IL kd cos(theta), I_S = IL ks cos^n(alpha) with
// cos(alpha) = R.V (Phong) or N.H (Blinn). The point P and the normal N are the inspector's.
void expect_slide_15(const nlohmann::json& r, bool blinn) {
  const Scene s = io::load_gltf(test::scene_dir() / "phong_spheres.gltf").scene;
  const Material* m = nullptr;
  for (const Material& candidate : s.materials)
    if (candidate.name == r["material"].get<std::string>()) m = &candidate;
  ASSERT_NE(m, nullptr) << r["material"];
  const glm::dvec3 P(r["P"][0].get<double>(), r["P"][1].get<double>(), r["P"][2].get<double>());
  const glm::dvec3 N = glm::normalize(glm::dvec3(r["N"][0].get<double>(), r["N"][1].get<double>(), r["N"][2].get<double>()));
  const glm::dvec3 V = glm::normalize(glm::dvec3(s.cameras[0].position()) - P);  // the scene camera
  auto near = [](const nlohmann::json& value, double expected, const std::string& what) {
    EXPECT_NEAR(value.get<double>(), expected, 1e-5 * std::abs(expected) + 1e-7) << what;
  };
  ASSERT_EQ(r["lights"].size(), s.lights.size());
  double diffuse[3] = {0, 0, 0}, specular[3] = {0, 0, 0};
  for (size_t i = 0; i < s.lights.size(); ++i) {
    const Light& light = s.lights[i];
    const nlohmann::json& t = r["lights"][i];
    const glm::dvec3 to_light = glm::dvec3(light.position) - P;
    const double d = glm::length(to_light);
    const glm::dvec3 L = to_light / d;
    const double cos_theta = std::max(glm::dot(N, L), 0.0);
    const glm::dvec3 R = 2.0 * glm::dot(N, L) * N - L;
    const double cos_alpha = std::max(blinn ? glm::dot(N, glm::normalize(L + V)) : glm::dot(R, V), 0.0);
    near(t["d"], d, light.name + " d");
    near(t["theta_deg"], glm::degrees(std::acos(glm::dot(N, L))), light.name + " theta");
    for (int c = 0; c < 3; ++c) {
      const double IL = double(light.intensity[c]) / (d * d) / std::numbers::pi;
      const double I_D = IL * m->kd[c] * cos_theta, I_S = IL * m->ks[c] * std::pow(cos_alpha, double(m->shininess));
      near(t["I_D"][c], I_D, light.name + " I_D");
      near(t["I_S"][c], I_S, light.name + " I_S");
      diffuse[c] += I_D;
      specular[c] += I_S;
    }
  }
  for (int c = 0; c < 3; ++c) {
    const double ambient = double(s.ambient[c]) * m->ka[c];
    near(r["I_A"][c], ambient, "I_A");
    near(r["I_D"][c], diffuse[c], "I_D");
    near(r["I_S"][c], specular[c], "I_S");
    near(r["sum"][c], ambient + diffuse[c] + specular[c], "sum");
  }
}

TEST_F(ViewerRun, TheInspectorShowsEachTermAndTheirSum) {
  const nlohmann::json r = json_of(file("inspector.json"));
  EXPECT_EQ(r["shading"], "phong");
  EXPECT_EQ(r["material"].get<std::string>(), "ks0.60_n5");  // the 4th sphere of the top row
  ASSERT_EQ(r["lights"].size(), 2u);
  EXPECT_EQ(r["lights"][0]["name"], "key_light");
  EXPECT_EQ(r["lights"][1]["name"], "fill_light");
  for (const auto& light : r["lights"]) {
    const double d = light["d"], f_att = light["f_att"];
    EXPECT_NEAR(f_att, 1.0 / (d * d), 1e-5 * f_att);  // the scene's physical attenuation
  }
  expect_slide_15(r, false);
  // The CPU formula and the GPU's pixel agree.
  for (int c = 0; c < 3; ++c) {
    const double sum = r["sum"][c].get<double>();
    EXPECT_NEAR(r["gl_pixel"][c].get<double>(), sum, 0.01 * sum);
  }
  EXPECT_GT(r["I_S"][0].get<double>(), 0.05);  // the click was on a highlight

  // The inspector window is drawn over the picture (in the window only, not in the picture).
  const Codes window = codes(file("inspector-panel.png")), picture = codes(file("phong.png"));
  EXPECT_GT(differing_in_picture_area(window, picture, 8), 0.05);
}

TEST_F(ViewerRun, AClickOnThePanelSwitchesToBlinn) {
  const nlohmann::json phong = json_of(file("inspector.json")), blinn = json_of(file("blinn.json"));
  const auto& a = phong["lights"][0];
  const auto& b = blinn["lights"][0];
  EXPECT_NEAR(a["theta_deg"].get<double>(), b["theta_deg"].get<double>(), 1e-3);  // the same point
  // N.H's angle is about half R.V's near the mirror direction.
  EXPECT_LT(b["alpha_deg"].get<double>(), a["alpha_deg"].get<double>() - 1.0);
  EXPECT_GT(blinn["I_S"][0].get<double>(), phong["I_S"][0].get<double>());
  expect_slide_15(blinn, true);  // the highlight is now Blinn's (N.H)^n
}

TEST_F(ViewerRun, OrbitingMovesTheView) {
  const Codes before = codes(file("phong.png")), moved = codes(file("moved.png"));
  ASSERT_EQ(before.values.size(), moved.values.size());
  size_t differing = 0;
  for (size_t i = 0; i < before.values.size(); ++i)
    if (std::abs(before.values[i] - moved.values[i]) > 8) ++differing;
  EXPECT_GT(double(differing) / double(before.values.size()), 0.05);
}

// The state the script left (scene camera after an orbit and C, Gouraud, no diffuse term) is what
// `luz render --model gouraud --no-diffuse` draws at the screenshot's size.
TEST_F(ViewerRun, TheScreenshotIsWhatLuzRenderMakesWithTheSameSettings) {
  const Codes viewer = codes(file("gouraud-no-diffuse.png"));
  test::ScratchDir dir;
  const fs::path out = dir / "render.png";
  const auto result = test::run_luz({"render", (test::scene_dir() / "phong_spheres.gltf").string(),
                                     "--model", "gouraud", "--no-diffuse", "--size",
                                     viewer.size(),
                                     "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const Codes render = codes(out);
  test::expect_same_picture(render, viewer);
  const double n = double(render.values.size());

  // And the comparison can tell settings apart: the Phong screenshot is another picture.
  const Codes phong = codes(file("phong.png"));
  double phong_total = 0;
  for (size_t i = 0; i < render.values.size(); ++i) phong_total += std::abs(render.values[i] - phong.values[i]);
  EXPECT_GT(phong_total / n, 2.0);
}

TEST_F(ViewerRun, ABrokenFileShowsItsErrorAndKeepsThePreviousScene) {
  const Codes before = codes(file("phong.png")), after = codes(file("after-broken.png"));
  ASSERT_EQ(before.values.size(), after.values.size());
  size_t differing = 0;
  for (size_t i = 0; i < before.values.size(); ++i)
    if (std::abs(before.values[i] - after.values[i]) > 1) ++differing;
  EXPECT_LT(double(differing) / double(before.values.size()), 0.001);

  // The error window's red title bar (0.6, 0.1, 0.1 in viewer.cpp) is in the window.
  const size_t red_after = count_colour(codes(file("after-broken-panel.png")), 153, 25, 25);
  const size_t red_before = count_colour(codes(file("phong-panel.png")), 153, 25, 25);
  EXPECT_GT(red_after, red_before + 1000);
  std::ifstream log(file("viewer.log"));
  const std::string text((std::istreambuf_iterator<char>(log)), {});
  EXPECT_NE(text.find("broken.gltf"), std::string::npos) << text;
}

// A file from Blender with its lights in candela (run_viewer_script.sh writes bright.gltf): the
// first picture is white and a warning in the window says why and what to press; K fits the
// exposure (and the warning goes), which is then the log-average luminance of the picture's lit pixels shown as middle
// grey (Reinhard et al. 2002), computed here from `luz render`'s EXR of the same view.
TEST_F(ViewerRun, KFitsTheExposureOfAFileWhoseLightsAreInCandela) {
  const json loaded = json_of(file("bright-loaded.json"));
  EXPECT_EQ(loaded["exposure"].get<double>(), 0.0);
  std::string warning;
  for (const json& w : loaded["warnings"])
    if (w.get<std::string>().find("over-exposed") != std::string::npos) warning = w.get<std::string>();
  EXPECT_EQ(warning.rfind("bright.gltf: at +0 EV the picture is over-exposed: 100% of its lit pixels are white", 0), 0u)
      << loaded["warnings"].dump();
  EXPECT_NE(warning.find("Blender I/O v3.4.50 writes lights in candela"), std::string::npos) << warning;
  EXPECT_NE(warning.find("K fits the exposure"), std::string::npos) << warning;

  const test::ScratchDir scratch;
  const auto exr = scratch / "bright.exr";
  const auto rendered = test::run_luz({"render", file("bright.gltf").string(), "--out", exr.string(), "--size", "400x300"});
  ASSERT_EQ(rendered.exit_code, 0) << rendered.output;
  double log_sum = 0.0;
  size_t lit = 0;
  for (const Rgb& c : io::read_image(exr).pixels) {
    const double y = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    if (y > 0.0) log_sum += std::log(y), ++lit;
  }
  ASSERT_GT(lit, 1000u);
  const double expected = std::log2(0.18 / std::exp(log_sum / double(lit)));
  const json fitted = json_of(file("bright-fitted.json"));
  EXPECT_LT(expected, -8.0);  // the lamp is 683 times too bright: about -9.4 EV off, light falloff aside
  EXPECT_NEAR(fitted["exposure"].get<double>(), expected, 0.15);
  // The warning is answered: it leaves the window.
  for (const json& w : fitted["warnings"]) EXPECT_EQ(w.get<std::string>().find("over-exposed"), std::string::npos) << w;
  // A script's (or a lesson's) `set exposure auto` fits it as K does.
  EXPECT_EQ(json_of(file("bright-set-auto.json"))["exposure"], fitted["exposure"]);

  // The triangle white at +0 EV, a grey at the fitted exposure.
  const auto triangle_codes = [](const Codes& picture) {
    std::vector<int> lit_codes;
    for (int y = 0; y < picture.height; ++y)
      for (int x = 0; x < picture.width; ++x)
        if (picture.at(x, y, 1) > 0) lit_codes.push_back(picture.at(x, y, 1));
    std::sort(lit_codes.begin(), lit_codes.end());
    return lit_codes;
  };
  const std::vector<int> white = triangle_codes(codes(file("bright-loaded.png")));
  const std::vector<int> grey = triangle_codes(codes(file("bright-fitted.png")));
  ASSERT_GT(white.size(), 1000u);
  ASSERT_GT(grey.size(), 1000u);
  EXPECT_EQ(white[white.size() / 2], 255);
  EXPECT_GT(grey[grey.size() / 2], 60);
  EXPECT_LT(grey[grey.size() / 2], 200);
}

}  // namespace
}  // namespace luz
