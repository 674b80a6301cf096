#include "raytracing/optics.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace luz::rt {

glm::vec3 reflect(const glm::vec3& d, const glm::vec3& N) { return d - 2.0f * glm::dot(d, N) * N; }

std::optional<glm::vec3> refract(const glm::vec3& d, const glm::vec3& N, float eta) {
  const float cos_i = std::min(-glm::dot(d, N), 1.0f);
  // Snell: sin^2(theta_t) = eta^2 sin^2(theta_i).
  const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
  if (sin2_t > 1.0f) return std::nullopt;  // total internal reflection
  const float cos_t = std::sqrt(1.0f - sin2_t);
  // The tangential part of d scaled by eta, plus the normal part that makes it unit length.
  return glm::normalize(eta * d + (eta * cos_i - cos_t) * N);
}

float fresnel_dielectric(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, 0.0f, 1.0f);
  const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
  if (sin2_t >= 1.0f) return 1.0f;  // total internal reflection
  const float cos_t = std::sqrt(1.0f - sin2_t);
  // With n1 = eta and n2 = 1 (only the ratio matters).
  const float rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const float rp = (eta * cos_t - cos_i) / (eta * cos_t + cos_i);
  return 0.5f * (rs * rs + rp * rp);
}

}  // namespace luz::rt
