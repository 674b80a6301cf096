#pragma once
// What a render counts: rays of each kind of slide 24, intersection tests where the intersector
// can count them (the brute-force one; Embree's BVH does not report its tests), and time.
#include <array>
#include <cstdint>
#include <string>

#include "raytracing/ray.h"

namespace luz::rt {

struct Counters {
  std::array<uint64_t, kRayKinds> rays{};  // indexed by RayKind
  uint64_t intersection_tests = 0;         // ray-triangle tests; 0 when not counted (Embree)
  uint64_t samples = 0;                    // primary samples taken (adaptive sampling varies it)
  double seconds = 0.0;

  uint64_t& operator[](RayKind kind) { return rays[size_t(kind)]; }
  uint64_t operator[](RayKind kind) const { return rays[size_t(kind)]; }
  uint64_t total_rays() const;
  double rays_per_second() const { return seconds > 0.0 ? double(total_rays()) / seconds : 0.0; }
  Counters& operator+=(const Counters& other);
  // One line per figure, in the current language, for the command's summary.
  std::string to_string() const;
};

}  // namespace luz::rt
