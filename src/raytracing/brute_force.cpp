#include "raytracing/brute_force.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace luz::rt {

BruteForceIntersector::BruteForceIntersector(const Scene& scene) {
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      const glm::vec3& p0 = mesh.positions[mesh.indices[3 * t]];
      const glm::vec3& p1 = mesh.positions[mesh.indices[3 * t + 1]];
      const glm::vec3& p2 = mesh.positions[mesh.indices[3 * t + 2]];
      triangles_.push_back({p0, p1 - p0, p2 - p0, int(m), int(t)});
    }
  }
}

namespace {

// Moller & Trumbore, "Fast, Minimum Storage Ray/Triangle Intersection" (1997): solve
// o + t d = p0 + u e1 + v e2 by Cramer's rule. Returns t, or a negative value for a miss.
float hit_distance(const glm::vec3& o, const glm::vec3& d, const glm::vec3& p0,
                   const glm::vec3& e1, const glm::vec3& e2, float& u, float& v) {
  const glm::vec3 p = glm::cross(d, e2);
  const float det = glm::dot(e1, p);
  if (std::abs(det) < 1e-12f) return -1.0f;  // the ray is parallel to the triangle's plane
  const float inv_det = 1.0f / det;
  const glm::vec3 s = o - p0;
  u = glm::dot(s, p) * inv_det;
  if (u < 0.0f || u > 1.0f) return -1.0f;
  const glm::vec3 q = glm::cross(s, e1);
  v = glm::dot(d, q) * inv_det;
  if (v < 0.0f || u + v > 1.0f) return -1.0f;
  return glm::dot(e2, q) * inv_det;
}

}  // namespace

Hit BruteForceIntersector::intersect(const Ray& ray, uint64_t& tests) const {
  Hit nearest;
  nearest.t = ray.tfar;
  for (const Triangle& tri : triangles_) {
    float u = 0, v = 0;
    const float t = hit_distance(ray.origin, ray.direction, tri.p0, tri.e1, tri.e2, u, v);
    if (t > 0.0f && t < nearest.t) nearest = Hit{t, tri.mesh, tri.index, u, v};
  }
  tests += triangles_.size();
  if (!nearest.found()) nearest.t = kInfinity;
  return nearest;
}

bool BruteForceIntersector::occluded(const Ray& ray, uint64_t& tests) const {
  for (const Triangle& tri : triangles_) {
    ++tests;
    float u = 0, v = 0;
    const float t = hit_distance(ray.origin, ray.direction, tri.p0, tri.e1, tri.e2, u, v);
    if (t > 0.0f && t < ray.tfar) return true;  // any occluder will do
  }
  return false;
}

}  // namespace luz::rt
