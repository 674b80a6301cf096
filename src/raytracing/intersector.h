#pragma once
// "Determinar intersección con objeto más cercano" (slide 26), behind one interface with two
// implementations, so the class can compare them (slide 27, acceleration):
//   EmbreeIntersector      Embree's BVH (embree_scene.h)
//   BruteForceIntersector  every ray against every triangle, counting the tests (brute_force.h)
#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>

#include "raytracing/ray.h"

namespace luz::rt {

class Intersector {
public:
  virtual ~Intersector() = default;
  // The nearest hit with t in (0, ray.tfar); hit.found() is false when there is none.
  // `tests` grows by the ray-triangle tests made, where the implementation counts them.
  virtual Hit intersect(const Ray& ray, uint64_t& tests) const = 0;
  // True when anything lies along the ray with t in (0, ray.tfar): the shadow ray's question.
  virtual bool occluded(const Ray& ray, uint64_t& tests) const = 0;

  // The same for a batch of coherent rays (the primary rays of a tile, the shadow rays of those
  // hits toward one light). The default asks ray by ray; Embree traces them as a stream, as its
  // performance notes advise for coherent rays.
  virtual void intersect(std::span<const Ray> rays, std::span<Hit> hits, uint64_t& tests) const;
  virtual void occluded(std::span<const Ray> rays, std::span<bool> blocked, uint64_t& tests) const;
};

// The answers of a batch of shadow rays (blocked or not), in a buffer kept and reused from batch
// to batch: it grows to the largest batch and then allocates no more. (std::vector<bool> has no
// bool* to hand to occluded().)
class BlockedFlags {
public:
  std::span<bool> first(size_t n) {
    if (n > size_) {
      size_ = std::max(n, 2 * size_);
      flags_ = std::make_unique<bool[]>(size_);
    }
    return {flags_.get(), n};
  }

private:
  std::unique_ptr<bool[]> flags_;
  size_t size_ = 0;
};

}  // namespace luz::rt
