// The local renderer keeps its shadow and reflection maps between frames and draws them again
// only when what they show changes. A renderer that has drawn frames before an edit (a light
// moved, a light switched off, a material changed) or a camera move must give exactly the picture
// of a fresh renderer that never saw the old state.
#include <algorithm>
#include <functional>

#include <gtest/gtest.h>

#include "core/image.h"
#include "io/gltf_loader.h"
#include "local/local_renderer.h"
#include "support.h"

namespace luz {
namespace {

constexpr int width = 160, height = 120;

LocalOptions every_effect(Shading shading) {
  LocalOptions options;
  options.shading = shading;
  options.shadows.on = true;
  options.shadows.map_size = 256;
  options.reflection.on = true;
  options.reflection.resolution = 64;
  options.transparency.on = true;
  options.fog.mode = FogMode::linear;
  return options;
}

bool same(const Image& a, const Image& b) {
  return a.pixels.size() == b.pixels.size() && std::equal(a.pixels.begin(), a.pixels.end(), b.pixels.begin());
}

void expect_follows(const std::string& scene_name, const std::function<void(Scene&, Camera&)>& edit) {
  for (Shading shading : {Shading::flat, Shading::phong}) {
    Scene scene = io::load_gltf(test::scene_dir() / (scene_name + ".gltf")).scene;
    Camera camera = scene.cameras.front();
    const LocalOptions options = every_effect(shading);
    LocalRenderer kept(scene);
    const Image before = kept.render(camera, width, height, options);
    kept.render(camera, width, height, options);  // a second frame from the kept maps
    edit(scene, camera);
    const Image after = kept.render(camera, width, height, options);
    LocalRenderer fresh(scene);
    const Image expected = fresh.render(camera, width, height, options);
    EXPECT_FALSE(same(before, expected)) << scene_name << ": the edit should show";
    EXPECT_TRUE(same(after, expected)) << scene_name << " " << to_string(shading);
  }
}

TEST(LocalMapsFollow, ALightMoves) {
  expect_follows("local_effects", [](Scene& scene, Camera&) { scene.lights[0].position += glm::vec3(0.4f, 0.0f, 0.3f); });
}

TEST(LocalMapsFollow, ALightIsSwitchedOff) {
  expect_follows("local_effects", [](Scene& scene, Camera&) { scene.lights[0].enabled = false; });
}

TEST(LocalMapsFollow, AMaterialChanges) {
  // The mirror's cube map shows the other objects: one of them changes colour.
  expect_follows("local_effects", [](Scene& scene, Camera&) {
    for (Material& m : scene.materials) m.kd = glm::vec3(m.kd.g, m.kd.b, m.kd.r);
  });
}

TEST(LocalMapsFollow, TheCameraMoves) {
  expect_follows("cornell_spheres", [](Scene&, Camera& camera) {
    camera.to_world[3] += glm::vec4(0.05f, 0.02f, 0.0f, 0.0f);
  });
}

}  // namespace
}  // namespace luz
