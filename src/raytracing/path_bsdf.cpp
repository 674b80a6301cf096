#include "raytracing/path_bsdf.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "raytracing/optics.h"

namespace luz::rt {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float mean(const Rgb& c) { return std::max(0.0f, (c.r + c.g + c.b) / 3.0f); }

}  // namespace

glm::vec3 around(const glm::vec3& axis, float cos_theta, float phi) {
  // An orthonormal basis (t, b, axis) without a branch on the axis' direction: Duff et al.,
  // "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
  const float sign = std::copysign(1.0f, axis.z);
  const float a = -1.0f / (sign + axis.z);
  const float c = axis.x * axis.y * a;
  const glm::vec3 t(1.0f + sign * axis.x * axis.x * a, sign * c, -sign * axis.x);
  const glm::vec3 b(c, sign + axis.y * axis.y * a, -axis.y);
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  return glm::normalize(sin_theta * std::cos(phi) * t + sin_theta * std::sin(phi) * b +
                        cos_theta * axis);
}

Bsdf::Bsdf(const Rgb& kd, const Rgb& ks, float shininess, const Rgb& kr, const Rgb& kt, float ior,
           const glm::vec3& N, const glm::vec3& V, bool entering)
    : kd_(kd), ks_(ks), mirror_(kr), transmit_(0.0f), n_(shininess), N_(N), V_(V),
      eta_(entering ? 1.0f / ior : ior) {
  if (mean(kt) > 0.0f) {
    // The dielectric's Fresnel split (SCENES.md): reflection kr + kt F, transmission kt (1 - F),
    // F = 1 under total internal reflection.
    T_ = refract(-V, N, eta_);
    const float F = T_ ? fresnel_dielectric(std::max(glm::dot(V, N), 0.0f), eta_) : 1.0f;
    mirror_ += kt * F;
    transmit_ = kt * (1.0f - F);
  }
  // Lobes chosen in proportion to their mean reflectance, so bright lobes get most samples.
  const float total = mean(kd_) + mean(ks_) + mean(mirror_) + mean(transmit_);
  if (total <= 0.0f) return;
  p_diffuse_ = mean(kd_) / total;
  p_glossy_ = mean(ks_) / total;
  p_mirror_ = mean(mirror_) / total;
  p_transmit_ = T_ ? mean(transmit_) / total : 0.0f;
}

Rgb Bsdf::eval(const glm::vec3& L) const {
  if (glm::dot(N_, L) <= 0.0f || glm::dot(N_, V_) <= 0.0f) return Rgb(0.0f);
  Rgb f = kd_ / kPi;  // Lambert
  if (p_glossy_ > 0.0f) {
    const float cos_alpha = std::max(glm::dot(reflect(-L, N_), V_), 0.0f);
    f += ks_ * ((n_ + 2.0f) / (2.0f * kPi) * std::pow(cos_alpha, n_));  // normalised Phong
  }
  return f;
}

float Bsdf::pdf(const glm::vec3& L) const {
  const float cos_theta = glm::dot(N_, L);
  if (cos_theta <= 0.0f || glm::dot(N_, V_) <= 0.0f) return 0.0f;
  float pdf = p_diffuse_ * cos_theta / kPi;  // cosine-weighted
  if (p_glossy_ > 0.0f) {
    // cos^n around V's mirror direction, normalised over the sphere: (n + 1) / (2 pi) cos^n.
    // The lobe is symmetric: angle(L, mirror of V) = angle(mirror of L, V) = alpha.
    const float cos_alpha = std::max(glm::dot(reflect(-V_, N_), L), 0.0f);
    pdf += p_glossy_ * (n_ + 1.0f) / (2.0f * kPi) * std::pow(cos_alpha, n_);
  }
  return pdf;
}

std::optional<BsdfSample> Bsdf::sample(float u_lobe, float u1, float u2) const {
  BsdfSample s;
  if (u_lobe < p_diffuse_ + p_glossy_) {
    // The smooth part: one of its two lobes picks the direction, the mixture's density weighs it
    // (the one-sample model of Veach's thesis, 9.2.4), so f cos / pdf stays unbiased for both.
    if (u_lobe < p_diffuse_) s.direction = around(N_, std::sqrt(u1), 2.0f * kPi * u2);
    else s.direction = around(reflect(-V_, N_), std::pow(u1, 1.0f / (n_ + 1.0f)), 2.0f * kPi * u2);
    s.pdf = pdf(s.direction);
    if (s.pdf <= 0.0f) return std::nullopt;  // below the surface: the sample carries nothing
    s.weight = eval(s.direction) * glm::dot(N_, s.direction) / s.pdf;
    return s;
  }
  s.delta = true;
  if (u_lobe < p_diffuse_ + p_glossy_ + p_mirror_) {
    s.direction = reflect(-V_, N_);
    s.weight = mirror_ / p_mirror_;
    return s;
  }
  if (p_transmit_ <= 0.0f) return std::nullopt;  // the material absorbs the rest
  // Radiance is compressed by eta^2 crossing into a denser medium (Veach's thesis, 5.2): what a
  // camera ray brings back across is (n1/n2)^2 of what arrives on the far side. A ray that
  // enters and leaves an object has the factor cancel.
  s.direction = *T_;
  s.transmitted = true;
  s.weight = transmit_ * (eta_ * eta_) / p_transmit_;
  return s;
}

}  // namespace luz::rt
