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

#include "app/inspector.h"
#include "app/picking.h"
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

class CpuAndGpuAgree : public ::testing::TestWithParam<Case> {};

TEST_P(CpuAndGpuAgree, AtEveryPickedPixel) {
  const Case& c = GetParam();
  const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / (c.scene + ".gltf"));
  const Scene& scene = loaded.scene;
  const Camera& camera = scene.cameras.front();
  constexpr int width = 160, height = 120, step = 5;
  LocalOptions options;
  options.shading = c.shading;
  options.blinn = c.blinn;
  if (c.effects) {
    options.shadows.on = true;
    options.reflection.on = true;
    options.fog.mode = FogMode::linear;
    options.fog.near = 3.0f;
    options.fog.far = 12.0f;
  }
  LocalRenderer renderer(scene);
  const Image image = renderer.render(camera, width, height, options);
  const std::optional<ShadowLookup> shadows = renderer.shadow_lookup();
  ASSERT_EQ(shadows.has_value(), c.effects);
  float brightest = 0.0f;
  for (const Rgb& p : image.pixels) brightest = std::max({brightest, p.r, p.g, p.b});
  const float floor = 1e-4f * brightest;

  app::Picker picker(scene);
  int checked = 0, failed = 0, blocked = 0, reflecting = 0, fogged = 0;
  std::string first_failures;
  for (int y = step / 2; y < height; y += step)
    for (int x = step / 2; x < width; x += step) {
      const auto pick = picker.pick(camera, width, height, x, y);
      if (!pick) continue;
      app::DrawnLookups lookups;
      lookups.shadows = shadows ? &*shadows : nullptr;
      lookups.reflection = renderer.reflection_lookup(pick->mesh);
      const app::InspectorReading reading = app::read_terms(scene, renderer.area_lights(), *pick, options, lookups);
      if (c.effects) {
        for (const LightTerm& t : reading.terms.lights) blocked += t.lit && t.S == 0.0f;
        reflecting += reading.terms.reflection != Rgb(0.0f);
        fogged += reading.terms.fog < 1.0f;
      }
      ++checked;
      for (int ch = 0; ch < 3; ++ch) {
        const float gpu = image.at(x, y)[ch], cpu = reading.sum[ch];
        if (std::abs(gpu - cpu) > 0.01f * std::max(gpu, cpu) + floor) {
          if (failed++ < 5)
            first_failures += fmt::format("  pixel ({}, {}) channel {}: GPU {:.6g}, CPU {:.6g}\n", x, y, ch, gpu, cpu);
          break;
        }
      }
    }
  EXPECT_GT(checked, 200) << "too few pixels hit the scene";
  EXPECT_EQ(failed, 0) << failed << " of " << checked << " pixels disagree:\n" << first_failures;
  if (c.effects) {  // the effects were there to agree on
    EXPECT_GT(blocked, 20) << "lights blocked (S_i = 0) at the picked pixels";
    if (c.scene == "local_effects") {
      EXPECT_GT(reflecting, 5) << "pixels with a kr Ir term";
      EXPECT_GT(fogged, 100) << "pixels in fog";
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
  off.ambient = off.diffuse = off.specular = false;
  const TermValues none = evaluate_terms(scene, material, P, N, V, off);
  EXPECT_EQ(radiance(none, material, off, Rgb(1.0f), true), Rgb(0.0f));
  EXPECT_NEAR(none.lights[0].theta, 0.0f, 1e-3f);  // the angles are still shown
}

}  // namespace
}  // namespace luz
