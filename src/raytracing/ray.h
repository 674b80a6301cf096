#pragma once
// A ray and what it hits: the two values every part of the tracer passes around; and where a ray
// leaving a surface starts.
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/std_compat.h"

namespace luz::rt {

// The kinds of ray of slide 24's ray tree (the counters and the ray tree name them so).
enum class RayKind : uint8_t { primary, shadow, reflected, transmitted };
inline constexpr int kRayKinds = 4;
const char* to_string(RayKind kind);

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// origin + t * direction for t in (0, tfar). direction is unit length.
struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0, 0, -1};
  float tfar = kInfinity;
};

// The nearest hit of a ray: which triangle of which mesh, where along the ray, and the
// barycentric coordinates (u, v) of the hit on triangle (p0, p1, p2): p = (1-u-v) p0 + u p1 + v p2.
struct Hit {
  float t = kInfinity;
  int mesh = -1;
  int triangle = -1;
  float u = 0.0f;
  float v = 0.0f;
  bool found() const { return mesh >= 0; }
};

// a where c holds, else b, chosen component by component: for a loop over many hits the compiler
// turns this into vector blends, where a ternary between two vectors becomes a copy through memory
// that stops it vectorising the loop.
inline glm::vec3 select(bool c, const glm::vec3& a, const glm::vec3& b) {
  return {c ? a.x : b.x, c ? a.y : b.y, c ? a.z : b.z};
}

// The origin of a ray leaving point p toward the side of unit normal n, moved off the surface far
// enough that the new ray cannot hit the surface it leaves, however large the coordinates: each
// coordinate moves by a number of float ULPs proportional to n (so the offset grows with the
// scene's scale), with a small fixed offset near the world origin where ULPs vanish. The method of
// Wachter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems
// (2019), chapter 6. Inline and without branches, so that loops over many hits vectorise.
inline glm::vec3 offset_origin(const glm::vec3& p, const glm::vec3& n) {
  constexpr float near_origin = 1.0f / 32.0f;  // below this, ULPs are too small to rely on
  constexpr float fixed_scale = 1.0f / 65536.0f;
  constexpr float ulp_scale = 256.0f;  // ULPs per unit of n: covers the hit point's rounding
  glm::vec3 moved;
  for (int i = 0; i < 3; ++i) {
    // Adding k to a positive float's bits moves it k ULPs away from zero (k ULPs toward zero
    // for a negative float), so the step follows the coordinate's magnitude.
    const int32_t ulps = int32_t(ulp_scale * n[i]);
    const int32_t bits = bit_cast<int32_t>(p[i]);
    const float stepped = bit_cast<float>(bits + (p[i] < 0.0f ? -ulps : ulps));
    moved[i] = std::abs(p[i]) < near_origin ? p[i] + fixed_scale * n[i] : stepped;
  }
  return moved;
}

}  // namespace luz::rt
