#pragma once
// The optics of slide 26's reflected and transmitted rays: the law of reflection, Snell's law
// with total internal reflection, and Fresnel's reflectance of an unpolarised dielectric.
// All vectors are unit length; N faces the side the incident ray comes from (dot(d, N) <= 0).
// Inline, so that the wavefront's shading loops (hit_lanes.h) vectorise with them in; hence also
// the selects instead of early returns.
#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "raytracing/ray.h"

namespace luz::rt {

// The mirror direction of d about N: r = d - 2 (d.N) N.
inline glm::vec3 reflect(const glm::vec3& d, const glm::vec3& N) { return d - 2.0f * glm::dot(d, N) * N; }

// Snell's law n1 sin(theta_i) = n2 sin(theta_t) with eta = n1 / n2, the ratio of the refractive
// indices on the incident and the transmitted side: the transmitted direction, when there is no
// total internal reflection (sin(theta_t) would exceed 1; then `total` is set and the direction
// means nothing). Without branches, so that a loop over many hits vectorises.
inline glm::vec3 refract(const glm::vec3& d, const glm::vec3& N, float eta, bool& total) {
  const float cos_i = std::min(-glm::dot(d, N), 1.0f);
  // Snell: sin^2(theta_t) = eta^2 sin^2(theta_i).
  const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
  total = sin2_t > 1.0f;
  const float cos_t = std::sqrt(1.0f - sin2_t);
  // The tangential part of d scaled by eta, plus the normal part that makes it unit length.
  return glm::normalize(eta * d + (eta * cos_i - cos_t) * N);
}

// The same, as the transmitted direction or nothing under total internal reflection.
inline std::optional<glm::vec3> refract(const glm::vec3& d, const glm::vec3& N, float eta) {
  bool total = false;
  const glm::vec3 T = refract(d, N, eta, total);
  if (total) return std::nullopt;
  return T;
}

// Fresnel's equations for an unpolarised wave at a dielectric boundary, eta = n1 / n2 as above:
//   Rs = ((n1 cos_i - n2 cos_t) / (n1 cos_i + n2 cos_t))^2     (s-polarised)
//   Rp = ((n1 cos_t - n2 cos_i) / (n1 cos_t + n2 cos_i))^2     (p-polarised)
//   F  = (Rs + Rp) / 2, and 1 under total internal reflection.
// cos_i = cos(theta_i) >= 0. Without branches, as refract().
inline float fresnel_dielectric(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, 0.0f, 1.0f);
  const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
  const float cos_t = std::sqrt(1.0f - sin2_t);
  // With n1 = eta and n2 = 1 (only the ratio matters).
  const float rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const float rp = (eta * cos_t - cos_i) / (eta * cos_t + cos_i);
  const float F = 0.5f * (rs * rs + rp * rp);
  return sin2_t >= 1.0f ? 1.0f : F;  // 1: total internal reflection
}

// A shading normal is not the face's normal, so a direction computed from it (a reflected ray,
// a transmitted one, a sampled bounce) may point through the face it leaves and hit it again at
// once. Such a direction is bent to just graze the side it must leave on (unit normal n).
inline glm::vec3 keep_on_side(const glm::vec3& direction, const glm::vec3& n) {
  constexpr float graze = 1e-3f;
  const float c = glm::dot(direction, n);
  const glm::vec3 bent = glm::normalize(direction + (graze - c) * n);
  return select(c >= graze, direction, bent);
}

}  // namespace luz::rt
