// The Whitted tracer (src/raytracing) on scenes with known answers: closed forms worked here in
// double precision, and properties every picture must have (no acne, no self-intersection,
// energy never grows along a path, determinism, the two intersectors agree).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <span>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#if LUZ_PARALLEL_TBB && defined(__SSE__)
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>
#include <xmmintrin.h>
#endif

#include "core/image.h"
#include "io/gltf_loader.h"
#include "raytracing/embree_scene.h"
#include "raytracing/renderer.h"
#include "support.h"
#include "whitted_fixtures.h"

namespace luz::rt {
namespace {

using dvec3 = glm::dvec3;
constexpr double pi = std::numbers::pi;

Scene shipped(const std::string& name) {
  return io::load_gltf(test::scene_dir() / (name + ".gltf")).scene;
}

// ---- A mirror of kr = k facing a diffuse wall shows the wall times k ---------------------------
// Wall z = 0 (kd 0.5, facing +z), mirror z = 2 (kr = k, nothing else, facing -z), point light at
// (0.3, 0.2, 1.5), camera at (0, 0, 1) looking at the mirror. A pixel's ray reflects off the
// mirror onto the wall at w; the closed form there is kd/pi * I cos(theta) / d^2, times k.
// The viewer uploads finished tiles as joined rectangles: every pixel of the tiles given, once,
// and none other; a whole picture's tiles are one rectangle, a row's run one per row of tiles.
TEST(WhittedTiles, JoinedTilesCoverTheSamePixelsOnce) {
  const int width = 100, height = 70;
  const std::vector<rt::Tile> all = rt::make_tiles(width, height, 16);
  std::vector<rt::Tile> some;
  for (size_t i = 0; i < all.size(); ++i)
    if (i % 5 != 2 && i != 13) some.push_back(all[all.size() - 1 - i]);  // out of order, with holes
  std::vector<rt::Tile> one_missing = all;  // whole rows of the picture above and below a partial one
  one_missing.erase(one_missing.begin() + 10);
  for (const std::vector<rt::Tile>* tiles : std::vector<const std::vector<rt::Tile>*>{&all, &some, &one_missing}) {
    std::vector<int> wanted(size_t(width * height), 0), covered(size_t(width * height), 0);
    for (const rt::Tile& t : *tiles)
      for (int y = t.y0; y < t.y1; ++y)
        for (int x = t.x0; x < t.x1; ++x) ++wanted[size_t(y * width + x)];
    for (const rt::Tile& r : rt::joined_tiles(*tiles, width))
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) ++covered[size_t(y * width + x)];
    EXPECT_EQ(covered, wanted);
  }
  const std::vector<rt::Tile> whole = rt::joined_tiles(all, width);
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_EQ(whole[0].x1, width);
  EXPECT_EQ(whole[0].y1, height);
  const std::vector<rt::Tile> run = rt::joined_tiles({all[10], all[9], all[8]}, width);  // row 1: x 16 to 64
  ASSERT_EQ(run.size(), 1u);
  EXPECT_EQ(run[0].x0, 16);
  EXPECT_EQ(run[0].x1, 64);
  EXPECT_EQ(run[0].y0, 16);
}

TEST(WhittedTracer, MirrorShowsTheWallTimesKr) {
  const double k = 0.6, kd = 0.5, I = 10.0;
  const dvec3 light(0.3, 0.2, 1.5);
  Scene scene;
  scene.materials.push_back(test::matte(Rgb(float(kd))));
  Material mirror = test::matte(Rgb(0.0f));
  mirror.kr = Rgb(float(k));
  scene.materials.push_back(mirror);
  scene.meshes.push_back(test::quad("wall", {-20, -20, 0}, {40, 0, 0}, {0, 40, 0}, 0));
  scene.meshes.push_back(test::quad("mirror", {-20, -20, 2}, {0, 40, 0}, {40, 0, 0}, 1));
  Light point;
  point.position = glm::vec3(light);
  point.intensity = Rgb(float(I));
  scene.lights.push_back(point);
  const Camera camera = test::look_at({0, 0, 1}, {0, 0, 2}, 1.0f);

  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.max_depth = 2;
  const int size = 24;
  const Image image = tracer.render(camera, size, size, options);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const Ray ray = primary_ray(camera, size, size, {float(x) + 0.5f, float(y) + 0.5f});
      const dvec3 o(ray.origin), d(ray.direction);
      const dvec3 m = o + ((2.0 - o.z) / d.z) * d;    // on the mirror
      const dvec3 r(d.x, d.y, -d.z);                  // reflected about the mirror's normal
      const dvec3 w = m + (m.z / -r.z) * r;           // on the wall
      const dvec3 to_light = light - w;
      const double dist = glm::length(to_light);
      const double wall = kd / pi * I * (to_light.z / dist) / (dist * dist);
      EXPECT_NEAR(image.at(x, y).g, k * wall, 1e-4 * k * wall) << x << "," << y;
    }
}

// ---- A ray through a glass slab comes out parallel to itself ------------------------------------
// Slab z in [-1, 0], ior 1.5, kt 1, nothing else; the ray hits it at 40 degrees. The ray tree's
// last transmitted ray keeps the primary direction, shifted sideways by
// t sin(ti - tt) / cos(tt) (t = 1, the thickness).
TEST(WhittedTracer, GlassSlabShiftsARayParallelToItself) {
  Scene scene;
  Material glass = test::matte(Rgb(0.0f));
  glass.kt = Rgb(1.0f);
  glass.ior = 1.5f;
  scene.materials.push_back(glass);
  scene.meshes.push_back(test::box("slab", {-50, -50, -1}, {50, 50, 0}, 0));
  const double ti = 40.0 * pi / 180;
  const glm::vec3 eye(0.0f, 0.0f, 2.0f);
  const Camera camera = test::look_at(eye, eye + glm::vec3(float(std::sin(ti)), 0, float(-std::cos(ti))));

  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.max_depth = 5;
  const RayTree tree = tracer.trace_pixel(camera, 9, 9, 4, 4, options);
  ASSERT_EQ(tree.nodes.size(), 3u) << tree.to_json();  // primary, into the glass, out of it
  const RayTreeNode& in = tree.nodes[0];
  const RayTreeNode& out = tree.nodes[2];
  EXPECT_EQ(tree.nodes[1].kind, RayKind::transmitted);
  EXPECT_EQ(out.kind, RayKind::transmitted);
  EXPECT_FALSE(out.hit);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(out.direction[i], in.direction[i], 1e-5f) << i;
  const double tt = std::asin(std::sin(ti) / 1.5);
  const double shift = std::sin(ti - tt) / std::cos(tt);
  // Distance between the two parallel lines.
  const dvec3 d(in.direction), gap = dvec3(out.origin) - dvec3(in.origin);
  EXPECT_NEAR(glm::length(gap - glm::dot(gap, d) * d), shift, 1e-4);
}

// ---- Total internal reflection moves kt's share to the reflected ray ----------------------------
// A camera inside a glass cube looks at its +z face at 20 and at 60 degrees (critical: 41.8).
TEST(WhittedTracer, TotalInternalReflectionGivesKtToTheReflectedRay) {
  Scene scene;
  Material glass = test::matte(Rgb(0.0f));
  glass.kr = Rgb(0.05f);
  glass.kt = Rgb(0.9f);
  glass.ior = 1.5f;
  scene.materials.push_back(glass);
  scene.meshes.push_back(test::box("cube", {-1, -1, -1}, {1, 1, 1}, 0));
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.max_depth = 2;
  const auto children = [&](double deg) {
    const double t = deg * pi / 180;
    const glm::vec3 eye(-0.9f, 0.0f, 0.0f);  // so that every ray below meets the z = 1 face
    const Camera camera = test::look_at(eye, eye + glm::vec3(float(std::sin(t)), 0, float(std::cos(t))));
    return tracer.trace_pixel(camera, 3, 3, 1, 1, options);
  };
  const RayTree below = children(20);
  ASSERT_EQ(below.nodes.size(), 3u);
  EXPECT_EQ(below.nodes[1].kind, RayKind::reflected);
  EXPECT_NEAR(below.nodes[1].weight.r, 0.05f, 1e-6f);
  EXPECT_EQ(below.nodes[2].kind, RayKind::transmitted);
  EXPECT_NEAR(below.nodes[2].weight.r, 0.9f, 1e-6f);
  const RayTree beyond = children(60);
  ASSERT_EQ(beyond.nodes.size(), 2u) << "no transmitted ray under total internal reflection";
  EXPECT_EQ(beyond.nodes[1].kind, RayKind::reflected);
  EXPECT_NEAR(beyond.nodes[1].weight.r, 0.95f, 1e-6f);
  // With Fresnel the reflected ray takes kr + kt*F and the transmitted one kt*(1 - F).
  options.fresnel = true;
  const RayTree fresnel = children(0);
  ASSERT_EQ(fresnel.nodes.size(), 3u);
  EXPECT_NEAR(fresnel.nodes[1].weight.r, 0.05f + 0.9f * 0.04f, 1e-5f);
  EXPECT_NEAR(fresnel.nodes[2].weight.r, 0.9f * 0.96f, 1e-5f);
}

// ---- With Fresnel, the reflected share at oblique incidence is Fresnel's formula ----------------
// A glass slab (kr 0.05, kt 0.9, ior 1.5) seen from outside at 60 and 85 degrees, and a glass
// cube seen from inside at 30 degrees (below the critical 41.8): the reflected ray weighs
// kr + kt F(theta) and the transmitted one kt (1 - F(theta)), F from the sine and tangent forms
// worked here in double precision (F(60) = 0.089, F(85) = 0.61: far from F(0) = 0.04).
double fresnel_sines(double ti, double n1, double n2) {
  const double tt = std::asin(n1 * std::sin(ti) / n2);
  const double rs = std::pow(std::sin(ti - tt) / std::sin(ti + tt), 2);
  const double rp = std::pow(std::tan(ti - tt) / std::tan(ti + tt), 2);
  return 0.5 * (rs + rp);
}

TEST(WhittedTracer, FresnelSplitsKtByTheAngleOfIncidence) {
  Scene scene;
  Material glass = test::matte(Rgb(0.0f));
  glass.kr = Rgb(0.05f);
  glass.kt = Rgb(0.9f);
  glass.ior = 1.5f;
  scene.materials.push_back(glass);
  scene.meshes.push_back(test::box("slab", {-50, -50, -1}, {50, 50, 0}, 0));
  scene.meshes.push_back(test::box("cube", {-1, -1, 10}, {1, 1, 12}, 0));
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.max_depth = 2;
  options.fresnel = true;
  const auto expect_split = [&](const glm::vec3& eye, const glm::vec3& direction, double F) {
    // The centre pixel of a 3x3 image looks exactly along the camera's axis.
    const RayTree tree = tracer.trace_pixel(test::look_at(eye, eye + direction), 3, 3, 1, 1, options);
    ASSERT_EQ(tree.nodes.size(), 3u) << tree.to_json();
    EXPECT_EQ(tree.nodes[1].kind, RayKind::reflected);
    EXPECT_NEAR(tree.nodes[1].weight.r, 0.05 + 0.9 * F, 1e-5);
    EXPECT_EQ(tree.nodes[2].kind, RayKind::transmitted);
    EXPECT_NEAR(tree.nodes[2].weight.r, 0.9 * (1.0 - F), 1e-5);
  };
  for (const double deg : {60.0, 85.0}) {
    SCOPED_TRACE(testing::Message() << "outside, " << deg << " degrees");
    const double t = deg * pi / 180;
    expect_split({0, 0, 2}, {float(std::sin(t)), 0, float(-std::cos(t))}, fresnel_sines(t, 1.0, 1.5));
  }
  SCOPED_TRACE("inside, 30 degrees");
  const double t = 30.0 * pi / 180;
  expect_split({-0.5f, 0, 11}, {float(std::sin(t)), 0, float(std::cos(t))}, fresnel_sines(t, 1.5, 1.0));
}

// ---- Energy never grows along a path ------------------------------------------------------------
// In every ray tree of the shipped scenes, with and without Fresnel: a hit's secondary rays
// weigh at most 1 together, so each ray's share of the pixel is at most its parent's.
TEST(WhittedTracer, EnergyNeverGrowsAlongAPath) {
  for (const char* name : {"whitted", "cornell_box"}) {
    const Scene scene = shipped(name);
    WhittedRenderer tracer(scene);
    for (bool fresnel : {false, true}) {
      WhittedOptions options;
      options.fresnel = fresnel;
      options.max_depth = 8;
      int secondary = 0;
      for (int y = 0; y < 30; y += 2)
        for (int x = 0; x < 40; x += 2) {
          const RayTree tree = tracer.trace_pixel(scene.cameras[0], 40, 30, x, y, options);
          std::vector<Rgb> children_weight(tree.nodes.size(), Rgb(0.0f)), share(tree.nodes.size());
          for (const RayTreeNode& n : tree.nodes) {
            share[size_t(n.id)] = (n.parent >= 0 ? share[size_t(n.parent)] : Rgb(1.0f)) * n.weight;
            if (n.parent < 0 || n.kind == RayKind::shadow) continue;
            ++secondary;
            children_weight[size_t(n.parent)] += n.weight;
            for (int c = 0; c < 3; ++c)
              EXPECT_LE(share[size_t(n.id)][c], share[size_t(n.parent)][c] + 1e-6f) << name;
          }
          for (const Rgb& w : children_weight)
            for (int c = 0; c < 3; ++c) EXPECT_LE(w[c], 1.0f + 1e-6f) << name;
        }
      if (std::string(name) == "whitted") {
        EXPECT_GT(secondary, 50) << "the test saw secondary rays";
      }
    }
  }
}

// ---- No acne, no self-intersection ---------------------------------------------------------------
// A plane far from the origin (coordinates near 1000, where a float's ULP is 6e-5) under a
// directional light at 60 degrees: every pixel must show the closed form kd/pi E cos(theta), none
// darkened by its own shadow ray hitting the plane it leaves.
TEST(WhittedTracer, NoShadowAcneOnAFlatSurfaceFarFromTheOrigin) {
  for (const glm::vec3 at : {glm::vec3(0.0f), glm::vec3(1000.0f, 1000.0f, -1000.0f)}) {
    Scene scene;
    scene.materials.push_back(test::matte(Rgb(0.5f)));
    scene.meshes.push_back(test::quad("plane", at + glm::vec3(-50, 0, -50), {0, 0, 100}, {100, 0, 0}, 0));
    Light sun;
    sun.type = LightType::directional;
    sun.direction = glm::normalize(glm::vec3(std::sin(1.0472f), -std::cos(1.0472f), 0.0f));
    sun.intensity = Rgb(3.0f);
    scene.lights.push_back(sun);
    const Camera camera = test::look_at(at + glm::vec3(0, 3, 6), at);
    WhittedRenderer tracer(scene);
    const Image image = tracer.render(camera, 64, 48, WhittedOptions{});
    const float expected = float(0.5 / pi * 3.0 * 0.5);  // cos(60 degrees) = 0.5
    int plane = 0;
    for (const Rgb& p : image.pixels)
      if (p.r > 0.0f) {
        ++plane;
        EXPECT_NEAR(p.r, expected, 1e-4f * expected);
      }
    EXPECT_GT(plane, 64 * 48 / 3) << "the plane fills the lower part of the picture";
    const int dark_on_plane = int(std::count_if(image.pixels.begin() + 64 * 30, image.pixels.end(),
                                                 [](const Rgb& p) { return p.r == 0.0f; }));
    EXPECT_EQ(dark_on_plane, 0) << "no speckles of shadow acne";
  }
}

// On curved glass and mirrors (the shipped scene's tessellated spheres, smooth normals), no
// secondary ray hits the surface it leaves: every hit is farther than a hundredth of the
// spheres' radius, and rays inside the glass sphere cross it (their hit is on the far side).
TEST(WhittedTracer, SecondaryRaysNeverHitTheSurfaceTheyLeave) {
  const Scene scene = shipped("whitted");
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.max_depth = 6;
  int inside = 0;
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 80; ++x) {
      const RayTree tree = tracer.trace_pixel(scene.cameras[0], 80, 60, x, y, options);
      for (const RayTreeNode& n : tree.nodes) {
        if (n.kind == RayKind::shadow || n.kind == RayKind::primary || !n.hit) continue;
        EXPECT_GT(n.t, 0.005f) << "pixel " << x << "," << y << " node " << n.id;
        const RayTreeNode& parent = tree.nodes[size_t(n.parent)];
        if (n.kind == RayKind::transmitted && parent.mesh == "glass_sphere" && n.mesh == "glass_sphere") {
          ++inside;
          EXPECT_GT(n.t, 0.05f);  // a chord of a 0.5 m sphere, not a graze of the entry point
        }
      }
    }
  EXPECT_GT(inside, 100);
}

// ---- Slide 26's shadow ray: S_i = 0 when anything lies between the point and the light -------
// A floor (kd 0.5, ka 0.4, ambient 0.1) under a point light 2 m up, a 0.4 m square 1 m up
// between them: the point below the square shows Ia ka alone; a point 1 m to the side, clear
// of the square's shadow (which reaches 0.4 m from the centre), shows Ia ka + kd/pi I cos / d^2.
TEST(WhittedTracer, ABlockedShadowRayLeavesOnlyTheAmbientTerm) {
  const double kd = 0.5, ka = 0.4, Ia = 0.1, I = 8.0;
  Scene scene;
  Material floor = test::matte(Rgb(float(kd)));
  floor.ka = Rgb(float(ka));
  scene.materials.push_back(floor);
  scene.materials.push_back(test::matte(Rgb(0.0f)));
  scene.ambient = Rgb(float(Ia));
  scene.meshes.push_back(test::quad("floor", {-50, 0, 50}, {100, 0, 0}, {0, 0, -100}, 0));
  scene.meshes.push_back(test::quad("blocker", {-0.2f, 1, 0.2f}, {0.4f, 0, 0}, {0, 0, -0.4f}, 1));
  Light point;
  point.position = {0, 2, 0};
  point.intensity = Rgb(float(I));
  scene.lights.push_back(point);
  WhittedRenderer tracer(scene);
  const auto seen = [&](glm::vec3 at) {
    const RayTree tree = tracer.trace_pixel(test::look_at(at + glm::vec3(0.3f, 0.5f, 0.3f), at), 3, 3, 1, 1, {});
    EXPECT_EQ(tree.nodes[0].mesh, "floor");
    return double(tree.pixel.g);
  };
  EXPECT_NEAR(seen({0, 0, 0}), Ia * ka, 1e-6) << "in the square's shadow";
  const double d = std::sqrt(1.0 + 4.0), cos_theta = 2.0 / d;
  EXPECT_NEAR(seen({1, 0, 0}), Ia * ka + kd / pi * I * cos_theta / (d * d), 1e-5) << "in the light";
}

// ---- An emitter sampled N times gives the light of the whole emitter, not N times it -----------
// A 10 cm lamp (Le 50) 10 m above a floor (kd 0.5): at the point below it the floor shows
// kd/pi * Le A / d^2 (SCENES.md), to the 1e-4 that the lamp's extent changes cos/d^2, whether the
// lamp is taken at its centroid or as 16 samples each standing for A/16.
TEST(WhittedTracer, AreaLightSamplesEachStandForTheirShareOfTheArea) {
  const double kd = 0.5, Le = 50.0, side = 0.1, d = 10.0;
  Scene scene;
  scene.materials.push_back(test::matte(Rgb(float(kd))));
  Material lamp = test::matte(Rgb(0.0f));
  lamp.emission = Rgb(float(Le));
  scene.materials.push_back(lamp);
  scene.meshes.push_back(test::quad("floor", {-50, 0, 50}, {100, 0, 0}, {0, 0, -100}, 0));
  const float h = float(side / 2);
  scene.meshes.push_back(test::quad("lamp", {-h, float(d), -h}, {float(side), 0, 0}, {0, 0, float(side)}, 1));
  scene.find_area_lights();
  ASSERT_EQ(scene.area_lights.size(), 2u);
  ASSERT_LT(scene.area_lights[0].normal.y, -0.99f) << "the lamp faces the floor";
  WhittedRenderer tracer(scene);
  const Camera camera = test::look_at({0, 1, 1}, {0, 0, 0});
  const double expected = kd / pi * Le * side * side / (d * d);
  for (const int samples : {1, 16}) {
    WhittedOptions options;
    options.light_samples = samples;
    const RayTree tree = tracer.trace_pixel(camera, 3, 3, 1, 1, options);
    ASSERT_NEAR(tree.nodes[0].hit_point.x, 0.0f, 1e-5f);
    ASSERT_NEAR(tree.nodes[0].hit_point.z, 0.0f, 1e-5f);
    EXPECT_NEAR(tree.pixel.g, expected, 1e-4 * expected) << samples << " samples per triangle";
  }
}

// ---- An emitter seen from the front shows Le; from the back, nothing ------------------------------
// A lamp (Le = (2, 3, 4)) that fills the view, with no ambient term and nothing else to light it
// (an emitter cannot light itself): every pixel is Le from its front and black from its back,
// with both renderers (the wavefront's lanes then all hit one mesh).
TEST(WhittedTracer, AnEmitterShowsLeOnItsFrontOnly) {
  Scene scene;
  Material lamp = test::matte(Rgb(0.5f));
  lamp.emission = Rgb(2.0f, 3.0f, 4.0f);
  scene.materials.push_back(lamp);
  scene.meshes.push_back(test::quad("lamp", {-50, -50, 0}, {100, 0, 0}, {0, 100, 0}, 0));  // front: +z
  scene.find_area_lights();
  WhittedRenderer tracer(scene);
  for (const RendererKind renderer : {RendererKind::wavefront, RendererKind::recursive}) {
    WhittedOptions options;
    options.renderer = renderer;
    for (const float side : {1.0f, -1.0f}) {
      const Image image = tracer.render(test::look_at({0, 0, 5 * side}, {0, 0, 0}), 24, 16, options);
      const Rgb expected = side > 0 ? lamp.emission : Rgb(0.0f);
      for (const Rgb& pixel : image.pixels)
        ASSERT_EQ(pixel, expected) << (side > 0 ? "front" : "back") << ", renderer " << int(renderer);
    }
  }
}

// ---- The picture is deterministic; the ray tree agrees with the render -------------------------
TEST(WhittedTracer, SameSettingsGiveTheSameImageBitForBit) {
  const Scene scene = shipped("cornell_box");
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.spp = 4;
  options.light_samples = 4;
  const Image a = tracer.render(scene.cameras[0], 48, 48, options);
  const Image b = tracer.render(scene.cameras[0], 48, 48, options);
  WhittedRenderer again(scene);
  const Image c = again.render(scene.cameras[0], 48, 48, options);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  EXPECT_TRUE(std::equal(a.pixels.begin(), a.pixels.end(), b.pixels.begin()));
  EXPECT_TRUE(std::equal(a.pixels.begin(), a.pixels.end(), c.pixels.begin()));
  // The soft shadows really are sampled (N-rooks), not N copies of the centroid.
  options.light_samples = 1;
  const Image hard = tracer.render(scene.cameras[0], 48, 48, options);
  EXPECT_FALSE(std::equal(a.pixels.begin(), a.pixels.end(), hard.pixels.begin()));
}

// The tracer's threads may flush subnormal floats to zero or keep them (oneTBB's tasks ran with
// x86's FTZ and DAZ set, the viewer's own thread and the page without): the same picture casts
// the same shadow rays either way. Whitted's glass sphere (ks 0.1, n 200) has highlight terms of
// about 1e-39 over most of its surface, which flushing turns to zero.
#if LUZ_PARALLEL_TBB && defined(__SSE__)
TEST(WhittedTracer, ShadowRaysDoNotDependOnFlushingSubnormals) {
  const Scene scene = shipped("whitted");
  WhittedRenderer tracer(scene);
  constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;  // MXCSR's FTZ and DAZ
  const auto traced = [&](const WhittedOptions& options, bool flush) {
    // A oneTBB context with fp_settings takes the calling thread's mode to every task of the
    // render's loops, on whichever thread runs them.
    const unsigned mode = _mm_getcsr();
    _mm_setcsr(flush ? mode | kFlushToZero | kDenormalsAreZero : mode & ~(kFlushToZero | kDenormalsAreZero));
    tbb::task_group_context context(tbb::task_group_context::isolated, tbb::task_group_context::fp_settings);
    _mm_setcsr(mode);
    Image image;
    tbb::parallel_for(0, 1, [&](int) { image = tracer.render(scene.cameras[0], 128, 128, options); }, context);
    return std::pair{image, tracer.counters()};
  };
  // The lanes decide for every generation in the wavefront; the recursion (whitted.cpp) for the
  // rays below the first in the recursive renderer.
  for (const RendererKind kind : {RendererKind::wavefront, RendererKind::recursive}) {
    WhittedOptions options;
    options.renderer = kind;
    const auto [kept, kept_counts] = traced(options, false);
    const auto [flushed, flushed_counts] = traced(options, true);
    EXPECT_GT(kept_counts[RayKind::shadow], 1000u);
    EXPECT_EQ(kept_counts[RayKind::shadow], flushed_counts[RayKind::shadow]) << int(kind);
    EXPECT_EQ(kept_counts.total_rays(), flushed_counts.total_rays()) << int(kind);
    ASSERT_EQ(kept.pixels.size(), flushed.pixels.size());
    EXPECT_TRUE(std::equal(kept.pixels.begin(), kept.pixels.end(), flushed.pixels.begin())) << int(kind);
  }
}
#endif

TEST(WhittedTracer, RayTreeSumsToTheRenderedPixel) {
  const Scene scene = shipped("whitted");
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.spp = 4;
  const Image image = tracer.render(scene.cameras[0], 40, 30, options);
  for (const auto& [x, y] : {std::pair{12, 10}, std::pair{25, 14}, std::pair{5, 25}, std::pair{30, 2}}) {
    const RayTree tree = tracer.trace_pixel(scene.cameras[0], 40, 30, x, y, options);
    Rgb sum(0.0f);
    int primaries = 0;
    for (const RayTreeNode& n : tree.nodes)
      if (n.parent < 0) {
        sum += n.contribution;
        ++primaries;
      }
    EXPECT_EQ(primaries, 4);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(sum[c], image.at(x, y)[c], 1e-5f + 1e-5f * image.at(x, y)[c]);
      EXPECT_NEAR(tree.pixel[c], image.at(x, y)[c], 1e-5f + 1e-5f * image.at(x, y)[c]);
    }
    // Each node's contribution is its radiance times the weights down the tree; a hit's
    // radiance is its local colour plus its secondary rays' weighted radiance.
    for (const RayTreeNode& n : tree.nodes) {
      if (!n.hit || n.kind == RayKind::shadow) continue;
      Rgb expected = n.local;
      for (const RayTreeNode& child : tree.nodes)
        if (child.parent == n.id && child.kind != RayKind::shadow) expected += child.weight * child.radiance;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(n.radiance[c], expected[c], 1e-5f + 1e-5f * expected[c]);
    }
    // A node's share of the pixel: its radiance times the product of the weights on the path
    // from its primary ray down to it, its own included.
    for (const RayTreeNode& n : tree.nodes) {
      Rgb path(1.0f);
      for (int k = n.id; k >= 0; k = tree.nodes[size_t(k)].parent) path *= tree.nodes[size_t(k)].weight;
      const Rgb share = path * n.radiance;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(n.contribution[c], share[c], 1e-6f + 1e-5f * share[c]) << n.id;
    }
  }
}

// ---- A ray through the edge two triangles share hits one of them ----------------------------------
// A square of two triangles, and rays that cross it exactly on their shared diagonal, one at a
// time and as a stream, straight down and slanted: none may pass through the crack between them
// (a surface seen square-on from a framing camera puts a row of pixel centres on such an edge).
TEST(WhittedTracer, ARayThroughTheEdgeTwoTrianglesShareHitsOneOfThem) {
  Scene scene;
  Mesh square;
  square.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  square.indices = {0, 1, 3, 1, 2, 3};  // the diagonal from (1, -1) to (-1, 1)
  scene.meshes.push_back(square);
  const EmbreeIntersector embree(scene);
  std::vector<Ray> rays;
  for (int i = 1; i < 4000; ++i) {
    const float a = -1.0f + float(i) / 2000.0f;  // (a, -a) lies on the diagonal
    const glm::vec3 on_edge(a, -a, 0.0f);
    for (const glm::vec3 slant : {glm::vec3(0, 0, -1), glm::vec3(0.3f, 0.1f, -1), glm::vec3(-0.2f, 0.25f, -1)})
      rays.push_back({on_edge - 2.0f * slant, slant});
  }
  std::vector<Hit> hits(rays.size());
  const std::unique_ptr<bool[]> blocked = std::make_unique<bool[]>(rays.size());
  uint64_t tests = 0;
  embree.intersect(rays, hits, tests);
  embree.occluded(rays, std::span<bool>(blocked.get(), rays.size()), tests);
  int missed = 0, missed_alone = 0, unblocked = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    missed += !hits[i].found();
    missed_alone += !embree.intersect(rays[i], tests).found();
    unblocked += !blocked[i];
  }
  EXPECT_EQ(missed, 0) << "of " << rays.size() << " rays traced as a stream";
  EXPECT_EQ(missed_alone, 0) << "of " << rays.size() << " rays traced one at a time";
  EXPECT_EQ(unblocked, 0) << "of " << rays.size() << " shadow rays";
}

// ---- Slide 27: the brute-force intersector sees the same picture, at a counted cost --------------
TEST(WhittedTracer, BruteForceAgreesWithEmbreeAndCountsItsTests) {
  const Scene scene = shipped("whitted");
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  const Image bvh = tracer.render(scene.cameras[0], 32, 24, options);
  const Counters bvh_counters = tracer.counters();
  options.brute_force = true;
  const Image brute = tracer.render(scene.cameras[0], 32, 24, options);
  const Counters& brute_counters = tracer.counters();
  int differ = 0;
  for (size_t i = 0; i < bvh.pixels.size(); ++i)
    differ += glm::length(bvh.pixels[i] - brute.pixels[i]) > 1e-3f;
  EXPECT_LE(differ, 2) << "at most a pixel or two where a ray grazes an edge";
  EXPECT_EQ(bvh_counters.intersection_tests, 0u);
  // Every ray is tested against every triangle (shadow rays may stop at their first occluder).
  const uint64_t triangles = scene.triangle_count();
  const uint64_t nearest = brute_counters[RayKind::primary] + brute_counters[RayKind::reflected] +
                           brute_counters[RayKind::transmitted];
  EXPECT_GE(brute_counters.intersection_tests, nearest * triangles);
  EXPECT_LE(brute_counters.intersection_tests, brute_counters.total_rays() * triangles);
}

// A uniformly lit plane filling the view (a directional light, Lambert: the same radiance at
// every point) has no corners that differ, so the adaptive sampler traces the tiles' corner
// grids and nothing else: (16 + 1)^2 points for each of the 4 x 3 tiles of 64 x 48.
TEST(WhittedTracer, AdaptiveSupersamplingTracesOnlyTheCornersOfAFlatPicture) {
  Scene scene;
  scene.materials.push_back(test::matte(Rgb(0.5f)));
  scene.meshes.push_back(test::quad("plane", {-500, 0, -500}, {0, 0, 1000}, {1000, 0, 0}, 0));
  Light sun;
  sun.type = LightType::directional;
  sun.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  sun.intensity = Rgb(2.0f);
  scene.lights.push_back(sun);
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.sampling = Sampling::adaptive;
  options.tile_size = 16;
  const Image image = tracer.render(test::look_at({0, 5, 0}, {0, 0, -1}), 64, 48, options);
  for (const Rgb& p : image.pixels) ASSERT_NEAR(p.r, float(0.5 / pi * 2.0), 1e-6f) << "the plane fills the view";
  EXPECT_EQ(tracer.counters().samples, uint64_t(12 * 17 * 17));
}

// ---- Cancellation and the per-tile callback ------------------------------------------------------
TEST(WhittedTracer, TilesAreReportedAndCancellationStopsTheRender) {
  const Scene scene = shipped("whitted");
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.tile_size = 8;
  int reported = 0, last_done = 0;
  tracer.render(scene.cameras[0], 64, 48, options, [&](const TileDone& t) {
    ++reported;
    EXPECT_EQ(t.done, last_done + 1);  // the calls are serialised
    last_done = t.done;
    EXPECT_EQ(t.total, 48);
  });
  EXPECT_EQ(reported, 48);

  std::atomic<bool> cancel{false};
  reported = 0;
  std::vector<Tile> rendered;
  const Image cut = tracer.render(scene.cameras[0], 64, 48, options, [&](const TileDone& t) {
    ++reported;
    rendered.push_back(t.tile);
    cancel = true;  // the viewer's camera moved
  }, &cancel);
  EXPECT_LT(reported, 48);
  EXPECT_LT(tracer.counters()[RayKind::primary], uint64_t(64 * 48));
  // The tiles never rendered are black, not what the memory held (the picture is not cleared
  // before the tiles write it; the first render's pixels were freed just before).
  const auto in_rendered = [&](int x, int y) {
    return std::any_of(rendered.begin(), rendered.end(), [&](const Tile& t) { return x >= t.x0 && x < t.x1 && y >= t.y0 && y < t.y1; });
  };
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      if (in_rendered(x, y)) continue;
      ASSERT_EQ(cut.at(x, y), Rgb(0.0f)) << x << "," << y;
    }
  cancel = true;
  reported = 0;
  tracer.render(scene.cameras[0], 64, 48, options, [&](const TileDone&) { ++reported; }, &cancel);
  EXPECT_EQ(reported, 0);
}

// ---- Slide 27: adaptive supersampling spends rays only where the picture changes -----------------
TEST(WhittedTracer, AdaptiveSupersamplingSubdividesOnlyAtEdges) {
  const Scene scene = shipped("whitted");
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.spp = 16;
  const Image reference = tracer.render(scene.cameras[0], 64, 48, options);
  const uint64_t uniform = tracer.counters().samples;
  options.sampling = Sampling::adaptive;
  const Image adaptive = tracer.render(scene.cameras[0], 64, 48, options);
  const uint64_t corners = 65 * 49;
  EXPECT_GT(tracer.counters().samples, corners + 5 * 64) << "edges were subdivided";
  // The method's promise rather than a measurement (about 43% here): a pixel costs 1 sample
  // where the picture is flat and 5 or 25 more where it splits, so under half of the uniform
  // 16 means most of the picture was not split (the flat plane below checks "not split" exactly).
  EXPECT_LT(tracer.counters().samples, uniform / 2) << "flat regions were not";
  // Close to the 4x4 stratified picture: mean difference under 2% of the mean radiance.
  double diff = 0, mean = 0;
  for (size_t i = 0; i < adaptive.pixels.size(); ++i) {
    diff += glm::length(adaptive.pixels[i] - reference.pixels[i]);
    mean += glm::length(reference.pixels[i]);
  }
  EXPECT_LT(diff / mean, 0.02);
}

}  // namespace
}  // namespace luz::rt
