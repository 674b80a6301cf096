// The shipped scenes: each loads without a warning, has a camera, and holds what its plate is
// for (SCENES.md materials read back from the files the generator wrote).
#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "io/gltf_loader.h"
#include "support.h"

namespace luz {
namespace {

io::LoadedScene load(const std::string& name) { return io::load_gltf(test::scene_dir() / (name + ".gltf")); }

const Material& material_named(const Scene& scene, const std::string& name) {
  const auto found = std::find_if(scene.materials.begin(), scene.materials.end(),
                                  [&](const Material& m) { return m.name == name; });
  if (found == scene.materials.end()) throw std::runtime_error("no material " + name);
  return *found;
}

TEST(ShippedScenes, LoadWithoutWarningsAndHaveTheirOwnCamera) {
  for (const char* name : {"cornell_box", "phong_spheres", "whitted"}) {
    const io::LoadedScene loaded = load(name);
    EXPECT_TRUE(loaded.warnings.empty()) << name << ": " << (loaded.warnings.empty() ? "" : loaded.warnings[0]);
    ASSERT_FALSE(loaded.scene.cameras.empty()) << name;
    EXPECT_NE(loaded.scene.cameras[0].name, "framing") << name << " should ship its own camera";
    EXPECT_GT(loaded.scene.triangle_count(), 0u) << name;
    for (const Material& m : loaded.scene.materials)
      for (int c = 0; c < 3; ++c) EXPECT_LE(m.kd[c] + m.kr[c] + m.kt[c], 1.0f + 1e-6f) << name << " " << m.name;
  }
}

// The path tracer's BRDF is kd/pi plus the normalised Phong lobe ks (n + 2)/(2 pi) cos^n, which
// reflects at most ks of the light arriving (all of it at normal incidence; Lafortune and
// Willems 1994), with kr and kt on top: kd + ks + kr + kt <= 1 per channel keeps the reference
// from giving back more light than a surface receives. Every scene in the folder, so a new one
// is held to it too.
TEST(ShippedScenes, EveryMaterialConservesEnergy) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::scene_dir())) {
    if (entry.path().extension() != ".gltf") continue;
    ++scenes;
    const Scene scene = io::load_gltf(entry.path()).scene;
    for (const Material& m : scene.materials) {
      const Rgb total = m.kd + m.ks + m.kr + m.kt;
      for (int c = 0; c < 3; ++c)
        EXPECT_LE(total[c], 1.0f + 1e-6f) << entry.path().filename() << " " << m.name << " channel " << c;
    }
  }
  EXPECT_GE(scenes, 5);  // the folder was found and read
}

TEST(ShippedScenes, CornellBoxIsLitByItsLampOnly) {
  const Scene scene = load("cornell_box").scene;
  EXPECT_TRUE(scene.lights.empty());
  ASSERT_EQ(scene.area_lights.size(), 2u);  // the lamp quad
  float area = 0.0f;
  for (const AreaLight& lamp : scene.area_lights) {
    area += lamp.area;
    EXPECT_NEAR(lamp.normal.y, -1.0f, 1e-4f);  // facing down into the room
    EXPECT_NEAR(lamp.radiance.r, 17.0f, 1e-3f);
  }
  EXPECT_NEAR(area, 0.130f * 0.105f, 1e-5f);  // 130 mm x 105 mm in the Cornell data
  EXPECT_NEAR(scene.cameras[0].yfov, 2.0f * std::atan(12.5f / 35.0f), 1e-5f);
}

TEST(ShippedScenes, PhongSpheresRiseInKsAndN) {
  const Scene scene = load("phong_spheres").scene;
  EXPECT_FLOAT_EQ(material_named(scene, "ks0.00_n5").ks.r, 0.0f);
  EXPECT_FLOAT_EQ(material_named(scene, "ks0.80_n320").ks.r, 0.8f);
  EXPECT_FLOAT_EQ(material_named(scene, "ks0.80_n320").shininess, 320.0f);
}

TEST(ShippedScenes, WhittedHasAMirrorAndAGlassSphere) {
  const Scene scene = load("whitted").scene;
  EXPECT_GT(material_named(scene, "mirror").kr.r, 0.7f);
  const Material& glass = material_named(scene, "glass");
  EXPECT_GT(glass.kt.r, 0.8f);
  EXPECT_FLOAT_EQ(glass.ior, 1.5f);
  EXPECT_GT(scene.background.b, scene.background.r);  // a blue sky
}

}  // namespace
}  // namespace luz
