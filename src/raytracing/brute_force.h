#pragma once
// The intersector with no acceleration structure: every ray is tested against every triangle
// (Moller & Trumbore 1997), and the tests are counted. Slide 27's first problem, made visible:
// the cost grows with rays x triangles, where Embree's BVH grows with rays x log(triangles).
#include <vector>

#include <glm/vec3.hpp>

#include "core/scene.h"
#include "raytracing/intersector.h"

namespace luz::rt {

class BruteForceIntersector final : public Intersector {
public:
  explicit BruteForceIntersector(const Scene& scene);  // copies the triangles

  Hit intersect(const Ray& ray, uint64_t& tests) const override;
  bool occluded(const Ray& ray, uint64_t& tests) const override;
  using Intersector::intersect;
  using Intersector::occluded;

private:
  struct Triangle {
    glm::vec3 p0, e1, e2;  // p0 and the edges p1 - p0, p2 - p0
    int mesh, index;
  };
  std::vector<Triangle> triangles_;
};

}  // namespace luz::rt
