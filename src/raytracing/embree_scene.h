#pragma once
// Embree 3's BVH over the scene's triangles: one Embree geometry per Scene::meshes entry, so
// Embree's geomID is the mesh index and its primID the triangle index.
#include <memory>

#include "core/scene.h"
#include "raytracing/intersector.h"

namespace luz::rt {

class EmbreeIntersector final : public Intersector {
public:
  // Builds the BVH from the scene's geometry (copied: the scene may change afterwards; a
  // change of geometry needs a new intersector). Throws luz::Error when Embree fails.
  explicit EmbreeIntersector(const Scene& scene);
  ~EmbreeIntersector() override;
  EmbreeIntersector(const EmbreeIntersector&) = delete;
  EmbreeIntersector& operator=(const EmbreeIntersector&) = delete;

  Hit intersect(const Ray& ray, uint64_t& tests) const override;
  bool occluded(const Ray& ray, uint64_t& tests) const override;
  void intersect(std::span<const Ray> rays, std::span<Hit> hits, uint64_t& tests) const override;
  void occluded(std::span<const Ray> rays, std::span<bool> blocked, uint64_t& tests) const override;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace luz::rt
