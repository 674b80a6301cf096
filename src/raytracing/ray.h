#pragma once
// A ray and what it hits: the two values every part of the tracer passes around.
#include <cstdint>
#include <limits>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

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

}  // namespace luz::rt
