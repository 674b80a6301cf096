// Slide 27's two intersectors give the same hits on every shipped scene: Embree's BVH (one ray at
// a time and as a stream) against the brute-force loop over every triangle, which shares no code
// with it. The rays are the camera's through each pixel centre and, from each surface they reach,
// one in a direction drawn at random, so that walls are also seen edge-on and from behind. The
// same test runs in node on the web build's Embree (tests/web), so it also holds that build to the
// desktop's answers.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "io/gltf_loader.h"
#include "raytracing/brute_force.h"
#include "raytracing/embree_scene.h"
#include "raytracing/whitted.h"
#include "support.h"

namespace luz::rt {
namespace {

constexpr int kWidth = 32, kHeight = 24;

// A unit direction drawn uniformly over the sphere.
glm::vec3 random_direction(std::mt19937& random) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (;;) {
    const glm::vec3 d(unit(random), unit(random), unit(random));
    const float length = glm::length(d);
    if (length > 1e-3f && length <= 1.0f) return d / length;
  }
}

// The camera's rays, then one random ray from each point they hit (found by brute force).
std::vector<Ray> rays_into(const Scene& scene, const BruteForceIntersector& brute) {
  std::vector<Ray> rays;
  const PrimaryRays primary(scene.cameras.at(0), kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) rays.push_back(primary.through({float(x) + 0.5f, float(y) + 0.5f}));
  std::mt19937 random(27);
  uint64_t tests = 0;
  const size_t camera_rays = rays.size();
  for (size_t i = 0; i < camera_rays; ++i) {
    const Hit hit = brute.intersect(rays[i], tests);
    if (!hit.found()) continue;
    Ray ray;
    ray.origin = rays[i].origin + hit.t * 0.999f * rays[i].direction;  // just short of the surface
    ray.direction = random_direction(random);
    rays.push_back(ray);
  }
  return rays;
}

// The point of `scene` at barycentrics (u, v) of the hit's triangle.
glm::vec3 point_of(const Scene& scene, const Hit& hit) {
  const Mesh& mesh = scene.meshes.at(size_t(hit.mesh));
  const size_t first = 3 * size_t(hit.triangle);
  const glm::vec3& p0 = mesh.positions.at(mesh.indices.at(first));
  const glm::vec3& p1 = mesh.positions.at(mesh.indices.at(first + 1));
  const glm::vec3& p2 = mesh.positions.at(mesh.indices.at(first + 2));
  return (1.0f - hit.u - hit.v) * p0 + hit.u * p1 + hit.v * p2;
}

// The same point at the same distance, to single precision's rounding of the distance: on the
// same triangle (its barycentrics giving that point; on a ray almost along the triangle they move
// a long way for a small change of t), or, where the ray meets an edge or a vertex that several
// triangles share, on another of them.
bool same_hit(const Scene& scene, const Hit& a, const Hit& b) {
  if (a.found() != b.found()) return false;
  if (!a.found()) return true;
  const float close = 1e-5f * std::max(1.0f, a.t);
  if (std::abs(a.t - b.t) > close) return false;
  return glm::length(point_of(scene, a) - point_of(scene, b)) <= close;
}

class IntersectorsAgree : public testing::TestWithParam<std::string> {};

TEST_P(IntersectorsAgree, EmbreeGivesTheBruteForceHits) {
  const Scene scene = io::load_gltf(test::scene_dir() / (GetParam() + ".gltf")).scene;
  const BruteForceIntersector brute(scene);
  const EmbreeIntersector embree(scene);
  const std::vector<Ray> rays = rays_into(scene, brute);
  ASSERT_GT(rays.size(), size_t(kWidth * kHeight));

  uint64_t tests = 0;
  std::vector<Hit> stream(rays.size());
  embree.intersect(rays, stream, tests);
  std::vector<bool> blocked_reference(rays.size());
  std::vector<Ray> shadow_rays = rays;
  int found = 0, differ_alone = 0, differ_stream = 0, differ_occluded = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const Hit reference = brute.intersect(rays[i], tests);
    found += reference.found();
    differ_alone += !same_hit(scene, embree.intersect(rays[i], tests), reference);
    differ_stream += !same_hit(scene, stream[i], reference);
    // A shadow ray that stops halfway to the hit (or at a distance of 1 where there is none).
    shadow_rays[i].tfar = reference.found() ? reference.t * 0.5f : 1.0f;
    blocked_reference[i] = brute.occluded(shadow_rays[i], tests);
    differ_occluded += embree.occluded(shadow_rays[i], tests) != blocked_reference[i];
  }
  BlockedFlags blocked;
  const std::span<bool> blocked_stream = blocked.first(rays.size());
  embree.occluded(shadow_rays, blocked_stream, tests);
  int differ_occluded_stream = 0;
  for (size_t i = 0; i < rays.size(); ++i) differ_occluded_stream += blocked_stream[i] != blocked_reference[i];

  EXPECT_GT(found, kWidth * kHeight / 2) << "the camera sees the scene";
  EXPECT_EQ(differ_alone, 0) << "of " << rays.size() << " rays traced one at a time";
  EXPECT_EQ(differ_stream, 0) << "of " << rays.size() << " rays traced as a stream";
  EXPECT_EQ(differ_occluded, 0) << "of " << rays.size() << " shadow rays one at a time";
  EXPECT_EQ(differ_occluded_stream, 0) << "of " << rays.size() << " shadow rays as a stream";
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, IntersectorsAgree,
                         testing::Values("cornell_box", "whitted", "phong_spheres", "local_effects",
                                         "cornell_spheres"));

}  // namespace
}  // namespace luz::rt
