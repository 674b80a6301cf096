#pragma once
// The arithmetic of slide 26's Color() at one hit, as inline functions of plain values. The
// recursion (whitted.cpp) calls them for one hit at a time; the wavefront's lanes (hit_lanes.h)
// call them in loops over many hits, which the compiler turns into vector instructions. Written
// once, so the two renderers cannot drift apart: the same operations in the same order give the
// same bits (no fused multiply-adds: the tracer is built with -ffp-contract=off, so neither the
// baseline nor the lanes' AVX2 and AVX-512 clones, vector_clones.h, fuse a*b+c).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/color.h"
#include "core/std_compat.h"
#include "raytracing/optics.h"
#include "raytracing/ray.h"

namespace luz::rt {

// Some channel above zero. (A bitwise or: no branches in the lanes' loops.)
inline bool positive(const Rgb& c) { return (c.x > 0.0f) | (c.y > 0.0f) | (c.z > 0.0f); }

// Whether a light's term at a hit, I_D + I_S, is above zero, told from its factors (cos(theta)
// and IL above zero already): kd for I_D (zero where the diffuse term is off), the highlight
// cos^n(alpha) of a shiny material for I_S. Their product falls below float's normal range far
// from a highlight (IL ks 2^-126 on a glass sphere, kd = 0), a subnormal that x86's flush-to-zero
// mode turns into 0: `luz render`'s tiles run with it on (Embree sets it while it builds its BVH,
// and oneTBB's threads keep it), the viewer's trace thread with it off, and WebAssembly keeps
// subnormals. Told from the factors, every light in front of a hit that its term can show gets
// the lecture's shadow ray, in the window, the page and `luz render` alike.
inline bool lights_the_hit(const Rgb& kd, bool shiny, float highlight) {
  return positive(kd) | (shiny & (highlight > 0.0f));
}

// "calcular la normal": where a ray of direction d meets triangle (p0, p1, p2), whose vertex
// normals are (n0, n1, n2), at barycentrics (u, v).
struct SurfaceGeometry {
  glm::vec3 position;   // from the barycentrics, not o + t d (see offset_origin)
  glm::vec3 geometric;  // unit face normal on the side the ray came from
  glm::vec3 N;          // unit shading normal (interpolated), turned to the ray's side
  bool front;           // the ray hit the counter-clockwise (glTF front) face
};

inline SurfaceGeometry surface_geometry(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                                        const glm::vec3& n0, const glm::vec3& n1, const glm::vec3& n2,
                                        float u, float v, const glm::vec3& d) {
  const float w = 1.0f - u - v;
  SurfaceGeometry g;
  // The hit point from the barycentrics: its error is a few ULPs of the vertices' coordinates,
  // which is what offset_origin's offsets are sized for (o + t d would add t's error).
  g.position = w * p0 + u * p1 + v * p2;
  const glm::vec3 face = glm::normalize(glm::cross(p1 - p0, p2 - p0));  // counter-clockwise front
  g.front = glm::dot(face, d) < 0.0f;
  g.geometric = select(g.front, face, -face);
  const glm::vec3 interpolated = w * n0 + u * n1 + v * n2;
  const float length = glm::length(interpolated);
  const glm::vec3 N = select(length > 0.0f, interpolated / length, face);
  // Two-sided lighting, as lighting.glsl: N is turned over when the viewer sees the side of the
  // face opposite to it.
  g.N = select(glm::dot(face, N) * glm::dot(face, -d) < 0.0f, -N, N);
  return g;
}

// cos(alpha) of the highlight I_S = IL ks cos^n(alpha): Phong's mirror direction of the light
// against the viewer, or Blinn's N.H. L toward the light, V toward the viewer.
inline float cos_alpha(const glm::vec3& N, const glm::vec3& L, const glm::vec3& V, bool blinn) {
  return blinn ? std::max(glm::dot(N, glm::normalize(L + V)), 0.0f)
               : std::max(glm::dot(reflect(-L, N), V), 0.0f);
}

// cos^n(alpha) of the highlight, for cos(alpha) in [0, 1] and n >= 0: 2^(n log2 x), with log2 and
// 2^y as short series in float arithmetic and no branch, so that a loop over many hits
// vectorises (std::pow is a call per hit). Within 3e-7 (1 + |n log2 x|) of the exact power
// (test_whitted, CosPowerIsPow); 0^n = 0 for n > 0 and x^0 = 1, as std::pow gives them.
inline float cos_power(float x, float n) {
  // log2 x = e + log2 m, where x = m 2^e and m lies in [sqrt(1/2), sqrt(2)).
  const int32_t bits = bit_cast<int32_t>(x);
  const float mantissa = bit_cast<float>((bits & 0x007fffff) | 0x3f800000);  // in [1, 2)
  const bool halve = mantissa > 1.41421356f;
  const float m = halve ? 0.5f * mantissa : mantissa;
  const int32_t e = ((bits >> 23) & 0xff) - 127 + (halve ? 1 : 0);
  // ln m = 2 atanh(t) = 2 (t + t^3/3 + t^5/5 + ...), t = (m - 1) / (m + 1); |t| <= 0.172, so the
  // terms after t^9 add under 1e-9.
  const float t = (m - 1.0f) / (m + 1.0f), t2 = t * t;
  const float ln_m =
      2.0f * t * (1.0f + t2 * (1.0f / 3.0f + t2 * (1.0f / 5.0f + t2 * (1.0f / 7.0f + t2 * (1.0f / 9.0f)))));
  // y = n log2 x, kept above -126 (2^y is then a normal float; the exact power lies below 1e-38).
  const float y = std::max(n * (float(e) + ln_m * 1.44269504f), -126.0f);
  // 2^y = 2^i e^(f ln 2): i the nearest integer (adding and taking away 1.5 2^23 rounds to it),
  // |f| <= 1/2, e^g by its series to g^7 (the next term is under 6e-9).
  const float i = (y + 12582912.0f) - 12582912.0f;
  const float g = (y - i) * 0.693147181f;
  const float series = 1.0f + g * (1.0f + g * (0.5f + g * (1.0f / 6.0f + g * (1.0f / 24.0f +
                                 g * (1.0f / 120.0f + g * (1.0f / 720.0f + g / 5040.0f))))));
  const float power = series * bit_cast<float>((int32_t(i) + 127) << 23);
  return n == 0.0f ? 1.0f : (x > 0.0f ? power : 0.0f);
}

// The shadow ray of a light in direction L at `distance` from a point (infinite: a directional
// light): from just off the surface on the light's side to just short of the light (an emitter's
// sample lies on the emitter, which must not block it).
inline Ray shadow_ray(const glm::vec3& position, const glm::vec3& geometric, const glm::vec3& L,
                      float distance) {
  const glm::vec3 side = select(glm::dot(L, geometric) >= 0.0f, geometric, -geometric);
  return Ray{offset_origin(position, side), L,
             std::isinf(distance) ? kInfinity : distance * (1.0f - 1e-4f)};
}

// How a hit splits the light it passes on (slide 26's kr and kt, SCENES.md): with Fresnel on,
// kr + kt F and kt (1 - F); without it kr and kt, and under total internal reflection kt's share
// goes to the reflected ray. The ray enters the object when it hits the front (counter-clockwise)
// face, glTF's outside: eta = n1/n2 = 1/ior; leaving, eta = ior.
struct Split {
  Rgb kr;
  Rgb kt;
  glm::vec3 T;     // the transmitted direction (Snell's law), when `refracts`
  bool refracts;   // kt > 0 and no total internal reflection
};

inline Split split_at(const Rgb& kr, const Rgb& kt, float ior, bool front, const glm::vec3& d,
                      const glm::vec3& N, bool fresnel) {
  const bool transmissive = positive(kt);
  const float inverse = 1.0f / ior;  // computed, then chosen: no branch (see select())
  const float eta = front ? inverse : ior;
  bool total = false;
  const glm::vec3 T = refract(d, N, eta, total);
  const float cos_i = std::max(glm::dot(-d, N), 0.0f);
  // The share of kt that reflects instead: 1 under total internal reflection.
  const float fresnel_F = fresnel_dielectric(cos_i, eta);
  const float without_fresnel = total ? 1.0f : 0.0f;
  const float share = fresnel ? fresnel_F : without_fresnel;
  const float F = transmissive ? share : 0.0f;
  // T component by component: a copy of the vector as a whole keeps GCC from vectorising a loop
  // over many hits.
  return Split{kr + kt * F, kt * (1.0f - F), glm::vec3(T.x, T.y, T.z), bool(transmissive & !total)};
}

}  // namespace luz::rt
