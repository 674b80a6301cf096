// Two implementations of the lecture's formula must agree: the CPU one of local/local_terms.h
// (what the viewer's inspector shows) and the GLSL one of shaders/lighting.glsl (what the class
// sees). For pixels on a grid over the shipped scenes, the viewer's pick (GL id pass + ray)
// finds the surface, the inspector's read_terms() evaluates it as the shading model does, and
// the sum must be the rendered pixel within 1% (plus 1e-4 of the picture's brightest value for
// the near-black tails, where 1% means nothing).
#include <algorithm>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "app/viewer/inspector.h"
#include "app/viewer/picking.h"
#include "distant_scene.h"
#include "gltf_fixture.h"
#include "io/gltf_loader.h"
#include "local/local_renderer.h"
#include "local/local_terms.h"
#include "support.h"

namespace luz {
namespace {

struct Case {
  std::string scene;
  Shading shading;
  bool blinn;
  bool effects = false;  // slide 19: shadows, reflection map and linear fog on (transparency off:
                         // the pixel behind a pane is the GPU's, not a term at the point)
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.scene << " " << to_string(c.shading) << (c.blinn ? " blinn" : "") << (c.effects ? " effects" : "");
}

std::string name_of(const ::testing::TestParamInfo<Case>& info) {
  return fmt::format("{}_{}{}{}", info.param.scene, to_string(info.param.shading), info.param.blinn ? "_blinn" : "",
                     info.param.effects ? "_effects" : "");
}

// What a grid of picked pixels found: how many agree, and how many exercised each effect.
struct Agreement {
  int checked = 0, failed = 0, blocked = 0, reflecting = 0, fogged = 0, vertex_coloured = 0;
  std::string first_failures;
};

Agreement agree_at_grid(const Scene& scene, const LocalOptions& options) {
  const Camera& camera = scene.cameras.front();
  constexpr int width = 160, height = 120, step = 5;
  LocalRenderer renderer(scene);
  const Image image = renderer.render(camera, width, height, options);
  const std::optional<ShadowLookup> shadows = renderer.shadow_lookup();
  EXPECT_EQ(shadows.has_value(), options.shadows.on);
  float brightest = 0.0f;
  for (const Rgb& p : image.pixels) brightest = std::max({brightest, p.r, p.g, p.b});
  const float floor = 1e-4f * brightest;

  app::Picker picker(scene);
  Agreement a;
  for (int y = step / 2; y < height; y += step)
    for (int x = step / 2; x < width; x += step) {
      const auto pick = picker.pick(camera, width, height, x, y);
      if (!pick) continue;
      app::DrawnLookups lookups;
      lookups.shadows = shadows ? &*shadows : nullptr;
      lookups.reflection = renderer.reflection_lookup(pick->mesh);
      const app::InspectorReading reading = app::read_terms(scene, renderer.area_lights(), *pick, options, lookups);
      for (const LightTerm& t : reading.terms.lights) a.blocked += t.lit && t.S == 0.0f;
      a.reflecting += reading.terms.reflection != Rgb(0.0f);
      a.fogged += reading.terms.fog < 1.0f;
      a.vertex_coloured += reading.vertex_colour != Rgb(1.0f);
      ++a.checked;
      for (int ch = 0; ch < 3; ++ch) {
        const float gpu = image.at(x, y)[ch], cpu = reading.sum[ch];
        if (std::abs(gpu - cpu) > 0.01f * std::max(gpu, cpu) + floor) {
          if (a.failed++ < 5)
            a.first_failures += fmt::format("  pixel ({}, {}) channel {}: GPU {:.6g}, CPU {:.6g}\n", x, y, ch, gpu, cpu);
          break;
        }
      }
    }
  return a;
}

class CpuAndGpuAgree : public ::testing::TestWithParam<Case> {};

TEST_P(CpuAndGpuAgree, AtEveryPickedPixel) {
  const Case& c = GetParam();
  const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / (c.scene + ".gltf"));
  LocalOptions options;
  options.shading = c.shading;
  options.terms.blinn = c.blinn;
  if (c.effects) {
    options.shadows.on = true;
    options.reflection.on = true;
    options.fog.mode = FogMode::linear;
    options.fog.near = 3.0f;
    options.fog.far = 12.0f;
  }
  const Agreement a = agree_at_grid(loaded.scene, options);
  EXPECT_GT(a.checked, 200) << "too few pixels hit the scene";
  EXPECT_EQ(a.failed, 0) << a.failed << " of " << a.checked << " pixels disagree:\n" << a.first_failures;
  if (c.effects) {  // the effects were there to agree on
    EXPECT_GT(a.blocked, 20) << "lights blocked (S_i = 0) at the picked pixels";
    if (c.scene == "local_effects") {
      EXPECT_GT(a.reflecting, 5) << "pixels with a kr Ir term";
      EXPECT_GT(a.fogged, 100) << "pixels in fog";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, CpuAndGpuAgree,
                         ::testing::Values(Case{"phong_spheres", Shading::phong, false},
                                           Case{"phong_spheres", Shading::phong, true},
                                           Case{"phong_spheres", Shading::gouraud, false},
                                           Case{"phong_spheres", Shading::flat, false},
                                           Case{"cornell_box", Shading::phong, false},
                                           Case{"cornell_box", Shading::gouraud, false},
                                           Case{"whitted", Shading::phong, false},
                                           Case{"cornell_box", Shading::phong, false, true},
                                           Case{"local_effects", Shading::phong, false, true},
                                           Case{"local_effects", Shading::gouraud, false, true},
                                           Case{"local_effects", Shading::flat, false, true},
                                           Case{"whitted", Shading::phong, false, true}),
                         name_of);

// COLOR_0 multiplies kd (SCENES.md) in the inspector as in the shaders, read where each shading
// model reads it: at the pixel (Phong, Gouraud) or at the centroid (flat). A square with a red,
// green, blue and white corner fills the picture.
class VertexColours : public ::testing::TestWithParam<Shading> {};

TEST_P(VertexColours, MultiplyKdInTheInspectorAsInTheShaders) {
  test::GltfBuilder b;
  const int material = b.material({{"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}}});
  test::Primitive square;
  square.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  square.normals.assign(4, glm::vec3(0, 0, 1));
  square.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  square.indices = {0, 1, 2, 0, 2, 3};
  square.material = material;
  b.node({{"mesh", b.mesh({square})}});
  const nlohmann::json bulb = {{"KHR_lights_punctual", {{"light", b.light({{"type", "point"}, {"intensity", 20}})}}}};
  b.node({{"extensions", bulb}, {"translation", {0.3, 0.2, 1.5}}});
  const nlohmann::json lens = {{"yfov", 0.5}, {"znear", 0.1}};
  b.node({{"camera", b.camera({{"type", "perspective"}, {"perspective", lens}})}, {"translation", {0, 0, 3}}});
  test::ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  LocalOptions options;
  options.shading = GetParam();
  const Agreement a = agree_at_grid(loaded.scene, options);
  EXPECT_GT(a.checked, 600) << "the square should fill the picture";
  EXPECT_GT(a.vertex_coloured, a.checked / 2) << "pixels where COLOR_0 is not white";
  EXPECT_EQ(a.failed, 0) << a.failed << " of " << a.checked << " pixels disagree:\n" << a.first_failures;
}

INSTANTIATE_TEST_SUITE_P(EveryShading, VertexColours,
                         ::testing::Values(Shading::flat, Shading::gouraud, Shading::phong),
                         [](const ::testing::TestParamInfo<Shading>& shading) { return to_string(shading.param); });

// A switched-off term is zero in the CPU evaluation as in the shader (and the sum follows).
TEST(LocalTerms, SwitchedOffTermsAreZero) {
  Scene scene;
  Light light;
  light.name = "lamp";
  light.position = {0, 0, 2};
  light.intensity = Rgb(8.0f);
  scene.lights.push_back(light);
  scene.ambient = Rgb(0.1f);
  Material material;
  material.ks = Rgb(0.5f);
  material.shininess = 10;
  const glm::vec3 P(0.0f), N(0, 0, 1), V(0, 0, 1);
  LocalOptions on;
  const TermValues all = evaluate_terms(scene, material, P, N, V, on);
  ASSERT_EQ(all.lights.size(), 1u);
  // Straight overhead: cos(theta) = cos(alpha) = 1, d = 2, IL = 8 / 4 / pi.
  const float IL = 8.0f / 4.0f / 3.14159265f;
  EXPECT_NEAR(all.lights[0].d, 2.0f, 1e-6f);
  EXPECT_NEAR(all.lights[0].f_att, 0.25f, 1e-6f);
  EXPECT_NEAR(all.diffuse.r, IL * 0.8f, 1e-6f);
  EXPECT_NEAR(all.specular.r, IL * 0.5f, 1e-6f);
  EXPECT_NEAR(all.ambient.r, 0.08f, 1e-6f);
  LocalOptions off;
  off.terms.ambient = off.terms.diffuse = off.terms.specular = false;
  const TermValues none = evaluate_terms(scene, material, P, N, V, off);
  EXPECT_EQ(radiance(none, material, off, Rgb(1.0f), true), Rgb(0.0f));
  EXPECT_NEAR(none.lights[0].theta, 0.0f, 1e-3f);  // the angles are still shown
}

// The inspector's pick on test::distant_faces_scene: the id buffer orders depths as the pictures
// do, so a click anywhere on the lit face inspects the face, never the plate a metre behind it.
TEST(LocalTerms, APickOnADistantSceneFindsTheFrontFace) {
  const Scene scene = test::distant_faces_scene(0.0f);
  app::Picker picker(scene);
  constexpr int width = 64, height = 64;
  int picked = 0, behind = 0;
  for (int y = 0; y < height; y += 3)
    for (int x = 0; x < width; x += 3) {
      const auto pick = picker.pick(scene.cameras[0], width, height, x, y);
      ASSERT_TRUE(pick.has_value()) << x << ", " << y;
      ++picked;
      behind += pick->mesh != test::distant_lit_face;
    }
  EXPECT_EQ(behind, 0) << "of " << picked << " picks found the plate";
}

}  // namespace
}  // namespace luz
