#pragma once
// The scattering of slide 13-14's complete model at one surface point, as SCENES.md's "Path
// tracer" section states it:
//
//   f(L -> V) = kd / pi + ks (n + 2) / (2 pi) cos^n(alpha)     the BRDF's smooth part
//               + kr  x  a perfect mirror                      (a delta lobe)
//               + kt  x  a smooth dielectric of index eta      (delta lobes: Fresnel's F of
//                        kt reflects, adding to kr; 1 - F is transmitted)
//
// alpha is the angle between the mirror direction of L and V (the energy-normalised Phong lobe).
// The smooth part is evaluated for next-event estimation and sampled for the next ray; the
// delta lobes can only be sampled. Every vector is unit length and N faces the viewer's side.
#include <optional>

#include <glm/vec3.hpp>

#include "core/color.h"

namespace luz::rt {

struct BsdfSample {
  glm::vec3 direction{0.0f};
  Rgb weight{0.0f};   // f cos(theta) / pdf for the smooth part, the lobe's share / its probability
                      // for a delta lobe: the factor the path's throughput takes
  float pdf = 0.0f;   // solid-angle density of the smooth part (with its selection probability);
                      // 0 for a delta lobe
  bool delta = false;
  bool transmitted = false;
};

class Bsdf {
public:
  // kd, ks, n, kr, kt and ior of the material at a point seen from V with shading normal N;
  // `entering`: V is on the front (glTF's outside) of the surface, so eta = 1/ior there.
  Bsdf(const Rgb& kd, const Rgb& ks, float shininess, const Rgb& kr, const Rgb& kt, float ior,
       const glm::vec3& N, const glm::vec3& V, bool entering);

  // The smooth part f(L -> V) (zero when L is below the surface).
  Rgb eval(const glm::vec3& L) const;
  // The density with which sample() picks L through the smooth part.
  float pdf(const glm::vec3& L) const;
  // One direction for the next ray from three uniform numbers in [0, 1): a lobe is chosen with
  // probability proportional to its mean reflectance, then a direction within it (cosine-
  // weighted for Lambert, cos^n around V's mirror direction for the Phong lobe). Nothing when the
  // material absorbs everything.
  std::optional<BsdfSample> sample(float u_lobe, float u1, float u2) const;

  bool has_smooth_part() const { return p_diffuse_ + p_glossy_ > 0.0f; }

private:
  Rgb kd_, ks_, mirror_, transmit_;
  float n_;
  glm::vec3 N_, V_;
  std::optional<glm::vec3> T_;  // the transmitted direction (none under total internal reflection)
  float eta_;                   // n1 / n2 across the boundary, viewer's side first
  float p_diffuse_ = 0, p_glossy_ = 0, p_mirror_ = 0, p_transmit_ = 0;
};

// A unit vector at polar angle acos(cos_theta) and azimuth phi around unit `axis`.
glm::vec3 around(const glm::vec3& axis, float cos_theta, float phi);

}  // namespace luz::rt
