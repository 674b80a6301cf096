#pragma once
// The optics of slide 26's reflected and transmitted rays: the law of reflection, Snell's law
// with total internal reflection, and Fresnel's reflectance of an unpolarised dielectric.
// All vectors are unit length; N faces the side the incident ray comes from (dot(d, N) <= 0).
#include <optional>

#include <glm/vec3.hpp>

namespace luz::rt {

// The mirror direction of d about N: r = d - 2 (d.N) N.
glm::vec3 reflect(const glm::vec3& d, const glm::vec3& N);

// Snell's law n1 sin(theta_i) = n2 sin(theta_t) with eta = n1 / n2, the ratio of the refractive
// indices on the incident and the transmitted side. The transmitted direction, or nothing under
// total internal reflection (sin(theta_t) would exceed 1).
std::optional<glm::vec3> refract(const glm::vec3& d, const glm::vec3& N, float eta);

// Fresnel's equations for an unpolarised wave at a dielectric boundary, eta = n1 / n2 as above:
//   Rs = ((n1 cos_i - n2 cos_t) / (n1 cos_i + n2 cos_t))^2     (s-polarised)
//   Rp = ((n1 cos_t - n2 cos_i) / (n1 cos_t + n2 cos_i))^2     (p-polarised)
//   F  = (Rs + Rp) / 2, and 1 under total internal reflection.
// cos_i = cos(theta_i) >= 0.
float fresnel_dielectric(float cos_i, float eta);

}  // namespace luz::rt
