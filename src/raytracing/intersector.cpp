#include "raytracing/intersector.h"

#include <cassert>

namespace luz::rt {

void Intersector::intersect(std::span<const Ray> rays, std::span<Hit> hits, uint64_t& tests) const {
  assert(rays.size() == hits.size());
  for (size_t i = 0; i < rays.size(); ++i) hits[i] = intersect(rays[i], tests);
}

void Intersector::occluded(std::span<const Ray> rays, std::span<bool> blocked,
                           uint64_t& tests) const {
  assert(rays.size() == blocked.size());
  for (size_t i = 0; i < rays.size(); ++i) blocked[i] = occluded(rays[i], tests);
}

}  // namespace luz::rt
