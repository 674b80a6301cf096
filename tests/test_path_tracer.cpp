// The path tracer (slide 14's equation by Monte Carlo) against closed forms and against the
// Whitted tracer where both models are exact. Every comparison is statistical: the tracer
// reports the standard error of its own mean, and a test fails when the difference is more
// than a stated number of those errors (a t-test; the seed is fixed, so the outcome is too).
//
// - The white furnace: inside a closed box whose walls all emit Le and reflect rho, the
//   radiance is Le / (1 - rho) everywhere (SCENES.md's units: exitance E = pi Le, radiosity
//   B = E / (1 - rho), radiance B / pi). With a Lambert wall, a mirror wall and a mix of both.
// - Direct light (depth 1, ks = 0): equal to Whitted's depth 1 for point, spot (smooth cone
//   and Warn), directional lights, classroom attenuation and an emissive quad.
// - Mirror and glass under a point light: the specular chains (camera -> mirror -> wall, camera
//   -> glass -> glass -> floor) equal Whitted's with Fresnel, pixel by pixel.
// - The film's mean and standard error, and determinism for a seed however samples are split.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "raytracing/path_bsdf.h"
#include "raytracing/path_tracer.h"
#include "raytracing/renderer.h"
#include "raytracing/tiles.h"
#include "raytracing/whitted.h"
#include "whitted_fixtures.h"

namespace luz::rt {
namespace {

constexpr double pi = std::numbers::pi;

// Two-sided 99.9% bound of a standard normal: a correct tracer fails one such check in 1000.
constexpr double kZ999 = 3.29;

// A box [lo, hi] seen from inside: the fixture's box with its faces turned inward (winding and
// normals), so its front faces, the emitting sides, face the interior.
Mesh inward_box(glm::vec3 lo, glm::vec3 hi, int material) {
  Mesh mesh = test::box("furnace", lo, hi, material);
  for (size_t t = 0; t < mesh.triangle_count(); ++t) std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
  for (glm::vec3& n : mesh.normals) n = -n;
  return mesh;
}

// The mean over the image of the pixel means, and the standard error of that mean (pixels are
// independent, so the variances add).
struct Estimate {
  glm::dvec3 mean{0.0}, error{0.0};
};
Estimate image_estimate(const PathFilm& film) {
  const Image mean = film.mean(), error = film.standard_error();
  Estimate e;
  for (size_t i = 0; i < mean.pixels.size(); ++i) {
    e.mean += glm::dvec3(mean.pixels[i]);
    e.error += glm::dvec3(error.pixels[i]) * glm::dvec3(error.pixels[i]);
  }
  const double n = double(mean.pixels.size());
  e.mean /= n;
  e.error = glm::sqrt(e.error) / n;
  return e;
}

// ---- The white furnace --------------------------------------------------------------------------
// A 2 m box, the camera inside. Each channel is its own t-test at 99.9% (Bonferroni over the
// three channels: a correct tracer fails this test with probability below 0.3%).
void expect_furnace(const Material& wall, const Rgb& Le, const Rgb& rho, int max_depth) {
  Scene scene;
  Material m = wall;
  m.emission = Le;
  scene.materials.push_back(m);
  scene.meshes.push_back(inward_box({-1, -1, -1}, {1, 1, 1}, 0));
  scene.find_area_lights();
  const Camera camera = test::look_at({0.1f, -0.2f, 0.3f}, {0.7f, 0.4f, -1.0f}, 1.2f);
  PathOptions options;
  options.max_depth = max_depth;
  PathRenderer tracer(scene);
  PathFilm film(24, 18);
  tracer.add_samples(film, camera, options, 64);
  const Estimate e = image_estimate(film);
  for (int c = 0; c < 3; ++c) {
    // Depth D counts D - 1 bounces after the first hit, plus the light sample at the last hit:
    // Le (1 + rho + ... + rho^D); D = 64 makes rho^D negligible.
    const double expected = double(Le[c]) * (1.0 - std::pow(double(rho[c]), max_depth + 1)) / (1.0 - double(rho[c]));
    ASSERT_GT(e.error[c], 0.0);
    EXPECT_LT(std::abs(e.mean[c] - expected), kZ999 * e.error[c])
        << "channel " << c << ": " << e.mean[c] << " +- " << e.error[c] << ", expected " << expected;
    // The test has power: the error is far below the effect of a missing 1/pi or a lost bounce.
    EXPECT_LT(e.error[c], 0.01 * expected);
  }
}

TEST(PathTracer, WhiteFurnaceLambert) {
  expect_furnace(test::matte(Rgb(0.5f, 0.7f, 0.9f)), Rgb(1.0f, 0.5f, 0.25f), Rgb(0.5f, 0.7f, 0.9f), 64);
}

TEST(PathTracer, WhiteFurnaceMirrorAndLambertMixed) {
  Material m = test::matte(Rgb(0.3f, 0.1f, 0.5f));
  m.kr = Rgb(0.4f, 0.2f, 0.3f);  // rho = kd + kr
  expect_furnace(m, Rgb(0.5f), Rgb(0.7f, 0.3f, 0.8f), 64);
}

TEST(PathTracer, WhiteFurnaceAtShallowDepthKeepsOnlyItsBounces) {
  // Depth 3 with rho = 0.8: Le (1 + 0.8 + 0.64 + 0.512), far from Le / 0.2; Russian roulette
  // (from depth 2 here) must not bias it either.
  expect_furnace(test::matte(Rgb(0.8f)), Rgb(1.0f), Rgb(0.8f), 3);
}

// A lossless glass sphere in the furnace: from outside it cannot be seen (the radiance is still
// Le / (1 - rho)), and inside it the radiance is n^2 times larger (radiance over n^2 is what a
// lossless boundary conserves). The camera sits at the sphere's centre, so its rays leave at
// normal incidence and none is trapped by total internal reflection.
TEST(PathTracer, WhiteFurnaceWithGlassSphereScalesRadianceByNSquaredInside) {
  const float rho = 0.5f, Le = 1.0f, n = 1.5f;
  Scene scene;
  Material wall = test::matte(Rgb(rho));
  wall.emission = Rgb(Le);
  scene.materials.push_back(wall);
  Material glass = test::matte(Rgb(0.0f));
  glass.kt = Rgb(1.0f);
  glass.ior = n;
  scene.materials.push_back(glass);
  scene.meshes.push_back(inward_box({-1, -1, -1}, {1, 1, 1}, 0));
  scene.meshes.push_back(test::sphere("glass", {0.0f, 0.0f, 0.0f}, 0.5f, 1, 48, 96));
  scene.find_area_lights();
  PathOptions options;
  options.max_depth = 64;
  PathRenderer tracer(scene);
  const double outside = double(Le) / (1.0 - double(rho));
  for (const auto& [eye, expected] : {std::pair{glm::vec3(0.0f, 0.0f, 0.0f), double(n * n) * outside},
                                      std::pair{glm::vec3(0.2f, 0.7f, 0.8f), outside}}) {
    const Camera camera = test::look_at(eye, {0.1f, 0.05f, -1.0f}, 1.0f);
    PathFilm film(16, 12);
    tracer.add_samples(film, camera, options, 64);
    const Estimate e = image_estimate(film);
    EXPECT_LT(std::abs(e.mean.g - expected), kZ999 * e.error.g)
        << e.mean.g << " +- " << e.error.g << ", expected " << expected;
  }
}

// ---- Direct light equals Whitted's depth 1 ------------------------------------------------------
// A floor with a block on it, lit by a point light (physical 1/d^2), a spot with the smooth cone,
// a Warn spot with classroom attenuation, a directional light and an emissive quad facing down.
Scene direct_light_scene() {
  Scene scene;
  scene.materials.push_back(test::matte(Rgb(0.7f, 0.6f, 0.5f)));
  scene.materials.push_back(test::matte(Rgb(0.3f, 0.5f, 0.8f)));
  Material lamp = test::matte(Rgb(0.0f));
  lamp.emission = Rgb(4.0f, 3.0f, 2.0f);
  scene.materials.push_back(lamp);
  scene.meshes.push_back(test::quad("floor", {-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0));
  scene.meshes.push_back(test::box("block", {-0.4f, 0, -0.4f}, {0.4f, 0.8f, 0.4f}, 1));
  // Wound so that a x b points down: the lamp emits toward the floor.
  scene.meshes.push_back(test::quad("lamp", {0.5f, 2.0f, -1.0f}, {0.6f, 0, 0}, {0, 0, 0.6f}, 2));
  Light point;
  point.position = {-1.5f, 2.0f, 1.0f};
  point.intensity = Rgb(3.0f);
  Light spot;
  spot.type = LightType::spot;
  spot.position = {1.5f, 2.5f, 1.5f};
  spot.direction = glm::normalize(glm::vec3(-0.5f, -1.0f, -0.5f));
  spot.inner_cone = 0.2f;
  spot.outer_cone = 0.5f;
  spot.intensity = Rgb(6.0f, 5.0f, 4.0f);
  Light warn = spot;
  warn.position = {-1.0f, 2.0f, -1.5f};
  warn.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.5f));
  warn.warn_exponent = 8.0f;
  warn.outer_cone = 1.0f;
  warn.attenuation.classroom = true;
  warn.attenuation.c = {0.5f, 0.3f, 0.2f};
  Light sun;
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  sun.intensity = Rgb(0.3f, 0.3f, 0.4f);
  scene.lights = {point, spot, warn, sun};
  scene.find_area_lights();
  return scene;
}

// The Whitted picture (pixel centres) against the path tracer's mean along the same rays, with
// the path tracer's standard error. Whitted's own estimate is exact for the punctual lights and
// an N-rooks estimate (N = light_samples) for the emitters; its error is left in `slack`.
struct RayComparison {
  int pixels = 0, outside = 0;
  double sum_difference = 0.0, sum_variance = 0.0;
};
RayComparison compare_with_whitted(const Scene& scene, const Camera& camera, int w, int h,
                                   const WhittedOptions& whitted, const PathOptions& path,
                                   int samples, double slack,
                                   const std::vector<int>& only_meshes = {}) {
  WhittedRenderer reference(scene);
  const Image expected = reference.render(camera, w, h, whitted);
  PathRenderer tracer(scene);
  const PrimaryRays rays(camera, w, h);
  RayComparison result;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Ray ray = rays.through({float(x) + 0.5f, float(y) + 0.5f});
      if (!only_meshes.empty()) {
        const int mesh = reference.primary_hit(camera, w, h, {float(x) + 0.5f, float(y) + 0.5f}, whitted).mesh;
        if (std::find(only_meshes.begin(), only_meshes.end(), mesh) == only_meshes.end()) continue;
      }
      glm::dvec3 sum(0.0), squares(0.0);
      for (int k = 0; k < samples; ++k) {
        Random random(y * w + x, 7, k);
        const glm::dvec3 L(tracer.radiance(ray, path, random));
        sum += L;
        squares += L * L;
      }
      const glm::dvec3 mean = sum / double(samples);
      const glm::dvec3 variance = glm::max((squares - double(samples) * mean * mean) / double(samples - 1), glm::dvec3(0.0));
      const glm::dvec3 error = glm::sqrt(variance / double(samples));
      const glm::dvec3 W(expected.at(x, y));
      ++result.pixels;
      for (int c = 0; c < 3; ++c) {
        const double d = mean[c] - W[c];
        // Per pixel and channel: within 4.5 standard errors (a normal variable leaves that
        // band with probability 7e-6, so over the ~3000 checks here a correct tracer fails
        // with probability about 2%... kept rare by counting failures, not asserting each).
        if (std::abs(d) > 4.5 * error[c] + slack * (1.0 + W[c])) ++result.outside;
        result.sum_difference += d;
        result.sum_variance += error[c] * error[c];
      }
    }
  return result;
}

TEST(PathTracer, DepthOneEqualsWhittedsDirectLight) {
  const Scene scene = direct_light_scene();
  const Camera camera = test::look_at({0.0f, 3.0f, 4.0f}, {0.0f, 0.3f, 0.0f}, 0.9f);
  WhittedOptions whitted;
  whitted.max_depth = 1;
  whitted.terms.ambient = false;
  whitted.light_samples = 4096;  // N-rooks over the lamp: its own error ~1e-4 here
  PathOptions path;
  path.max_depth = 1;
  ASSERT_EQ(scene.area_lights.size(), size_t(2));
  ASSERT_LT(scene.area_lights[0].normal.y, 0.0f);  // the lamp faces the floor
  const RayComparison r = compare_with_whitted(scene, camera, 24, 18, whitted, path, 256, 2e-3);
  ASSERT_EQ(r.pixels, 24 * 18);
  // At most 3 of the 1296 pixel-channels outside 4.5 errors (expected: fewer than 0.01).
  EXPECT_LE(r.outside, 3);
  // And the whole picture: the mean difference within 3.29 of its standard error.
  EXPECT_LT(std::abs(r.sum_difference), kZ999 * std::sqrt(r.sum_variance) + 2e-3 * r.pixels);
}

// ---- Mirror and glass under a point light -------------------------------------------------------
// A floor, a mirror standing on it and a glass sphere, one point light. At depth 3 the chains
// camera -> mirror -> floor -> light and camera -> glass -> glass -> floor -> light are exact in
// both models (Whitted with Fresnel), and nothing else reaches the pixels that see the mirror or
// the glass first: a diffuse bounce from the floor meets only the plane it leaves, the mirror or
// the glass, none of which the depth limit lets light again. Pixels that see the floor directly
// differ at that same depth: there the path tracer adds the light that reaches the floor through
// the mirror (floor -> mirror -> floor -> light), the lecture's "interreflexión difusa".
TEST(PathTracer, SpecularChainsEqualWhittedWithFresnel) {
  Scene scene;
  scene.materials.push_back(test::matte(Rgb(0.7f, 0.7f, 0.6f)));  // 0 floor
  Material mirror = test::matte(Rgb(0.0f));
  mirror.kr = Rgb(0.9f, 0.9f, 0.8f);
  scene.materials.push_back(mirror);                               // 1 mirror
  Material glass = test::matte(Rgb(0.0f));
  glass.kt = Rgb(1.0f);
  glass.ior = 1.5f;
  scene.materials.push_back(glass);                                // 2 glass
  scene.meshes.push_back(test::quad("floor", {-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0));
  scene.meshes.push_back(test::quad("mirror", {-1.6f, 0.0f, 1.5f}, {0.3f, 0, -2.5f}, {0, 1.8f, 0}, 1));
  scene.meshes.push_back(test::sphere("glass", {0.5f, 0.6f, 0.0f}, 0.6f, 2));
  Light light;
  light.position = {0.8f, 2.5f, 1.5f};
  light.intensity = Rgb(8.0f);
  scene.lights = {light};
  scene.find_area_lights();
  const Camera camera = test::look_at({0.6f, 1.4f, 4.0f}, {-0.2f, 0.6f, 0.0f}, 0.9f);

  WhittedOptions whitted;
  whitted.max_depth = 3;
  whitted.terms.ambient = false;
  whitted.fresnel = true;
  PathOptions path;
  path.max_depth = 3;
  const RayComparison r = compare_with_whitted(scene, camera, 32, 24, whitted, path, 256, 1e-4, {1, 2});
  ASSERT_GT(r.pixels, 60);  // the mirror and the sphere fill a good part of the picture
  EXPECT_LE(r.outside, 3) << "of " << 3 * r.pixels;
  EXPECT_LT(std::abs(r.sum_difference), kZ999 * std::sqrt(r.sum_variance) + 1e-4 * r.pixels);

  // The floor pixels: the path tracer is brighter, by far more than its noise.
  const RayComparison floor = compare_with_whitted(scene, camera, 32, 24, whitted, path, 64, 1e-4, {0});
  EXPECT_GT(floor.sum_difference, kZ999 * std::sqrt(floor.sum_variance));
}

// ---- The BSDF -----------------------------------------------------------------------------------
// Its sampling density integrates to the probability of the smooth part, and its weights are
// f cos / pdf: the average weight over many samples is the directional albedo, which for
// Lambert alone is kd exactly.
TEST(PathBsdf, LambertAlbedoIsKd) {
  const glm::vec3 N(0, 0, 1), V = glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f));
  const Bsdf bsdf(Rgb(0.6f), Rgb(0.0f), 1.0f, Rgb(0.0f), Rgb(0.0f), 1.5f, N, V, true);
  Random random(1);
  glm::dvec3 sum(0.0);
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const auto s = bsdf.sample(random.next(), random.next(), random.next());
    ASSERT_TRUE(s);
    // Every sample of pure Lambert weighs exactly kd: f cos / pdf = (kd/pi) cos / (cos/pi).
    EXPECT_NEAR(s->weight.r, 0.6f, 1e-4f);
    sum += glm::dvec3(s->weight);
  }
  EXPECT_NEAR(sum.r / n, 0.6, 1e-4);
}

TEST(PathBsdf, PhongLobeDensityIntegratesToOne) {
  // Integrate pdf over the hemisphere numerically (midpoint rule in cos(theta) and phi).
  const glm::vec3 N(0, 0, 1), V = glm::normalize(glm::vec3(0.0f, 0.0f, 1.0f));
  const Bsdf bsdf(Rgb(0.0f), Rgb(0.5f), 20.0f, Rgb(0.0f), Rgb(0.0f), 1.5f, N, V, true);
  double integral = 0.0;
  const int steps = 400;
  for (int i = 0; i < steps; ++i)
    for (int j = 0; j < steps; ++j) {
      const double mu = (i + 0.5) / steps, phi = 2 * pi * (j + 0.5) / steps;
      const double s = std::sqrt(1 - mu * mu);
      const glm::vec3 L(float(s * std::cos(phi)), float(s * std::sin(phi)), float(mu));
      integral += double(bsdf.pdf(L)) * (1.0 / steps) * (2 * pi / steps);
    }
  // Seen from the normal the whole lobe lies above the surface: the density integrates to 1.
  EXPECT_NEAR(integral, 1.0, 2e-3);
}

TEST(PathBsdf, NormalisedPhongLobeReflectsKsAtNormalIncidence) {
  // The energy-normalised lobe ks (n+2)/(2 pi) cos^n: seen along the normal, alpha = theta, and
  // the integral of (n+2)/(2 pi) cos^n cos over the hemisphere is 1, so the albedo is ks.
  const glm::vec3 N(0, 0, 1);
  const Bsdf bsdf(Rgb(0.0f), Rgb(0.5f), 30.0f, Rgb(0.0f), Rgb(0.0f), 1.5f, N, N, true);
  Random random(3);
  double sum = 0.0;
  const int n = 40000;
  for (int i = 0; i < n; ++i)
    if (const auto s = bsdf.sample(random.next(), random.next(), random.next())) sum += s->weight.r;
  EXPECT_NEAR(sum / n, 0.5, 0.005);
}

// ---- The film, determinism ----------------------------------------------------------------------
TEST(PathFilm, MeanAndStandardErrorOfKnownSamples) {
  PathFilm film(2, 1);
  for (float v : {1.0f, 2.0f, 3.0f, 6.0f}) film.add(0, 0, Rgb(v));
  film.add(1, 0, Rgb(5.0f));
  const Image mean = film.mean(), error = film.standard_error();
  EXPECT_FLOAT_EQ(mean.at(0, 0).r, 3.0f);
  // s^2 = ((1-3)^2 + (2-3)^2 + 0 + (6-3)^2) / 3 = 14/3; SE = sqrt(14/3 / 4).
  EXPECT_NEAR(error.at(0, 0).g, std::sqrt(14.0 / 12.0), 1e-6);
  EXPECT_EQ(error.at(1, 0).r, 0.0f);  // one sample: no estimate of the noise
  EXPECT_EQ(film.min_samples(), 1);
}

TEST(PathRenderer, SameSeedSameFilmHoweverTheSamplesAreSplit) {
  const Scene scene = direct_light_scene();
  const Camera camera = test::look_at({0.0f, 3.0f, 4.0f}, {0.0f, 0.3f, 0.0f}, 0.9f);
  PathOptions options;
  options.seed = 5;
  PathRenderer tracer(scene);
  PathFilm once(20, 15), split(20, 15), other(20, 15);
  tracer.add_samples(once, camera, options, 6);
  tracer.add_samples(split, camera, options, 2);
  tracer.add_samples(split, camera, options, 4);
  EXPECT_EQ(once.mean().pixels, split.mean().pixels);
  EXPECT_EQ(once.standard_error().pixels, split.standard_error().pixels);
  options.seed = 6;
  tracer.add_samples(other, camera, options, 6);
  EXPECT_NE(once.mean().pixels, other.mean().pixels);
}

// A pass in steps of a few tiles (the page without threads, between its frames): the same film
// as the whole pass, bit for bit; a range past the last tile adds nothing.
TEST(PathRenderer, APassInStepsOfTilesIsTheWholePass) {
  const Scene scene = direct_light_scene();
  const Camera camera = test::look_at({0.0f, 3.0f, 4.0f}, {0.0f, 0.3f, 0.0f}, 0.9f);
  PathOptions options;
  options.tile_size = 8;
  PathRenderer tracer(scene);
  PathFilm whole(20, 15), stepped(20, 15);
  tracer.add_samples(whole, camera, options, 2);
  const size_t tiles = make_tiles(20, 15, options.tile_size).size();
  ASSERT_EQ(tiles, 6u);
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t first = 0; first < tiles; first += 4) {
      int reported = 0;
      tracer.add_samples(stepped, camera, options, 1, first, 4, [&](const Tile&, int, int total) {
        ++reported;
        EXPECT_EQ(total, int(std::min<size_t>(4, tiles - first)));
      });
      EXPECT_EQ(reported, int(std::min<size_t>(4, tiles - first)));
      if (pass == 0 && first == 0) {
        EXPECT_EQ(stepped.min_samples(), 0);  // two tiles still without
      }
    }
  }
  tracer.add_samples(stepped, camera, options, 1, tiles, 4);
  EXPECT_EQ(whole.mean().pixels, stepped.mean().pixels);
  EXPECT_EQ(whole.standard_error().pixels, stepped.standard_error().pixels);
  EXPECT_EQ(stepped.min_samples(), 2);
}

}  // namespace
}  // namespace luz::rt
