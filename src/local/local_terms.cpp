// The CPU twin of shaders/lighting.glsl. Each function here has the name of its GLSL original
// and the same steps, so that a change to one is easy to carry to the other (and
// tests/test_local_terms.cpp fails when they drift apart).
#include "local/local_terms.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace luz {
namespace {

constexpr float pi = 3.14159265358979f;

float angle_of(float cosine) { return std::acos(std::clamp(cosine, -1.0f, 1.0f)); }

// lighting.glsl cos_alpha(): Phong's R.V, or Blinn's N.H.
float cos_alpha(const glm::vec3& N, const glm::vec3& L, const glm::vec3& V, bool blinn) {
  if (blinn) return std::max(glm::dot(N, glm::normalize(L + V)), 0.0f);
  const glm::vec3 R = glm::reflect(-L, N);  // 2 (N.L) N - L
  return std::max(glm::dot(R, V), 0.0f);
}

// lighting.glsl add_light(): IL [kd cos(theta) + ks cos^n(alpha)], switches applied.
void add_light(TermValues& terms, LightTerm term, const Material& material, const glm::vec3& N,
               const glm::vec3& L, const glm::vec3& V, const LocalOptions& options) {
  const float cos_theta = glm::dot(N, L);
  term.theta = angle_of(cos_theta);
  const float cos_a = cos_alpha(N, L, V, options.blinn);
  term.alpha = angle_of(cos_a);
  term.lit = cos_theta > 0.0f;
  if (term.lit) {  // behind the surface: no diffuse, no highlight
    if (options.diffuse) term.diffuse = term.IL * material.kd * cos_theta;
    if (options.specular) term.specular = term.IL * material.ks * std::pow(cos_a, material.shininess);
  }
  terms.diffuse += term.diffuse;
  terms.specular += term.specular;
  terms.lights.push_back(std::move(term));
}

}  // namespace

TermValues evaluate_terms(const Scene& scene, const Material& material, const glm::vec3& P,
                          const glm::vec3& N, const glm::vec3& V, const LocalOptions& options,
                          std::span<const AreaLight> area_lights) {
  TermValues terms;
  if (options.ambient) terms.ambient = scene.ambient * material.ka;  // I_A = Ia ka

  // lighting.glsl punctual_IL(), for the first max_shader_lights enabled lights.
  int count = 0;
  for (const Light& light : scene.lights) {
    if (!light.enabled) continue;
    if (count++ == max_shader_lights) break;
    LightTerm term;
    term.name = light.name;
    glm::vec3 L;
    if (light.type == LightType::directional) {
      L = -glm::normalize(light.direction);
      term.IL = light.intensity / pi;  // IL = E_perp / pi
    } else {
      const glm::vec3 to_light = light.position - P;
      term.d = glm::length(to_light);
      L = to_light / term.d;
      term.f_att = light.attenuation.factor(term.d);
      term.spot = light.spot_factor(-L);
      term.IL = light.intensity * term.f_att * term.spot / pi;
    }
    add_light(terms, std::move(term), material, N, L, V, options);
  }

  // lighting.glsl area_IL(): an emitter as a point light of intensity Le A cos(theta_e), 1/d^2.
  for (size_t i = 0; i < area_lights.size(); ++i) {
    const AreaLight& light = area_lights[i];
    LightTerm term;
    term.name = fmt::format("emitter {}", i);
    const glm::vec3 to_light = light.centroid - P;
    term.d = glm::length(to_light);
    glm::vec3 L(0.0f);
    if (term.d >= 1e-6f) {  // else P is the light's own centroid: it adds nothing
      L = to_light / term.d;
      term.f_att = 1.0f / (term.d * term.d);
      term.spot = std::max(glm::dot(light.normal, -L), 0.0f);  // cos(theta_e): dark behind it
      term.IL = light.radiance * light.area * term.spot * term.f_att / pi;
    }
    add_light(terms, std::move(term), material, N, L, V, options);
  }
  return terms;
}

TermValues evaluate_terms(const Scene& scene, const Material& material, const glm::vec3& P,
                          const glm::vec3& N, const glm::vec3& V, const LocalOptions& options) {
  return evaluate_terms(scene, material, P, N, V, options, scene.area_lights);
}

Rgb radiance(const TermValues& terms, const Material& material, const LocalOptions& options,
             const Rgb& kd_texture_factor, bool emitting_side) {
  Rgb I = terms.ambient + terms.diffuse * kd_texture_factor + terms.specular;
  if (options.emission && emitting_side) I += material.emission;  // an emitter shows its own Le
  return I;
}

TermValues blend(const TermValues& a, const TermValues& b, const TermValues& c, const glm::vec3& w) {
  TermValues out = a;
  out.ambient = w.x * a.ambient + w.y * b.ambient + w.z * c.ambient;
  out.diffuse = w.x * a.diffuse + w.y * b.diffuse + w.z * c.diffuse;
  out.specular = w.x * a.specular + w.y * b.specular + w.z * c.specular;
  for (size_t i = 0; i < out.lights.size() && i < b.lights.size() && i < c.lights.size(); ++i) {
    LightTerm& t = out.lights[i];
    const LightTerm &tb = b.lights[i], &tc = c.lights[i];
    t.lit = t.lit || tb.lit || tc.lit;
    t.theta = w.x * t.theta + w.y * tb.theta + w.z * tc.theta;
    t.alpha = w.x * t.alpha + w.y * tb.alpha + w.z * tc.alpha;
    t.d = w.x * t.d + w.y * tb.d + w.z * tc.d;
    t.f_att = w.x * t.f_att + w.y * tb.f_att + w.z * tc.f_att;
    t.spot = w.x * t.spot + w.y * tb.spot + w.z * tc.spot;
    t.IL = w.x * t.IL + w.y * tb.IL + w.z * tc.IL;
    t.diffuse = w.x * t.diffuse + w.y * tb.diffuse + w.z * tc.diffuse;
    t.specular = w.x * t.specular + w.y * tb.specular + w.z * tc.specular;
  }
  return out;
}

}  // namespace luz
