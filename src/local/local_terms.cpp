// The CPU twin of shaders/lighting.glsl. Each function here has the name of its GLSL original
// and the same steps, so that a change to one is easy to carry to the other (and
// tests/test_local_terms.cpp fails when they drift apart).
#include "local/local_terms.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "core/i18n.h"

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

// lighting.glsl add_light(): S_i IL [kd cos(theta) + ks cos^n(alpha)], switches applied.
void add_light(TermValues& terms, LightTerm term, const ShadowView* shadow, const ShadowLookup* shadows,
               const Material& material, const glm::vec3& P, const glm::vec3& N, const glm::vec3& L,
               const glm::vec3& V, const LocalOptions& options) {
  const float cos_theta = glm::dot(N, L);
  term.theta = angle_of(cos_theta);
  const float cos_a = cos_alpha(N, L, V, options.terms.blinn);
  term.alpha = angle_of(cos_a);
  term.lit = cos_theta > 0.0f;
  if (term.lit) {  // behind the surface: no diffuse, no highlight
    if (options.shadows.on && shadows && shadow)
      term.S = shadow_factor(*shadows, *shadow, P, N, cos_theta);
    if (options.terms.diffuse) term.diffuse = term.S * term.IL * material.kd * cos_theta;
    if (options.terms.specular)
      term.specular = term.S * term.IL * material.ks * std::pow(cos_a, material.shininess);
  }
  terms.diffuse += term.diffuse;
  terms.specular += term.specular;
  terms.lights.push_back(std::move(term));
}

}  // namespace

TermValues evaluate_terms(const Scene& scene, const Material& material, const glm::vec3& P,
                          const glm::vec3& N, const glm::vec3& V, const LocalOptions& options,
                          std::span<const AreaLight> area_lights, const ShadowLookup* shadows) {
  // The shadow view of shader light i / emitter i, when the maps have one.
  auto view_of = [shadows](const std::vector<ShadowView>* views, size_t i) -> const ShadowView* {
    return shadows && i < views->size() ? &(*views)[i] : nullptr;
  };
  TermValues terms;
  if (options.terms.ambient) terms.ambient = scene.ambient * material.ka;  // I_A = Ia ka

  // lighting.glsl punctual_IL(), for the first max_shader_lights enabled lights.
  int count = 0;
  for (const Light& light : scene.lights) {
    if (!light.enabled) continue;
    if (count == max_shader_lights) break;
    const size_t index = size_t(count++);
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
    add_light(terms, std::move(term), view_of(shadows ? &shadows->lights : nullptr, index), shadows,
              material, P, N, L, V, options);
  }

  // lighting.glsl area_IL(): an emitter as a point light of intensity Le A cos(theta_e), 1/d^2.
  for (size_t i = 0; i < area_lights.size(); ++i) {
    const AreaLight& light = area_lights[i];
    LightTerm term;
    term.name = i18n::trf("emitter {}", i);
    const glm::vec3 to_light = light.centroid - P;
    term.d = glm::length(to_light);
    glm::vec3 L(0.0f);
    if (term.d >= 1e-6f) {  // else P is the light's own centroid: it adds nothing
      L = to_light / term.d;
      term.f_att = 1.0f / (term.d * term.d);
      term.spot = std::max(glm::dot(light.normal, -L), 0.0f);  // cos(theta_e): dark behind it
      term.IL = light.radiance * light.area * term.spot * term.f_att / pi;
    }
    add_light(terms, std::move(term), view_of(shadows ? &shadows->area_lights : nullptr, i), shadows,
              material, P, N, L, V, options);
  }
  return terms;
}

TermValues evaluate_terms(const Scene& scene, const Material& material, const glm::vec3& P,
                          const glm::vec3& N, const glm::vec3& V, const LocalOptions& options) {
  return evaluate_terms(scene, material, P, N, V, options, scene.area_lights);
}

float fog_factor(const Fog& fog, float d) {
  switch (fog.mode) {
    case FogMode::off: return 1.0f;
    case FogMode::linear: return std::clamp((fog.far - d) / std::max(fog.far - fog.near, 1e-6f), 0.0f, 1.0f);
    case FogMode::exponential: return std::exp(-fog.density * d);
  }
  return 1.0f;
}

void add_reflection_and_fog(TermValues& terms, const Material& material, const LocalOptions& options,
                            const ReflectionLookup& reflection, const glm::vec3& R, float d) {
  const bool reflects = material.kr.r > 0.0f || material.kr.g > 0.0f || material.kr.b > 0.0f;
  if (options.reflection.on && reflects) terms.reflection = material.kr * reflected_radiance(reflection, R);
  terms.fog = fog_factor(options.fog, d);
  terms.fog_colour = options.fog.colour;
}

Rgb radiance(const TermValues& terms, const Material& material, const LocalOptions& options,
             const Rgb& kd_texture_factor, bool emitting_side) {
  Rgb I = terms.ambient + terms.diffuse * kd_texture_factor + terms.specular;
  if (options.terms.emission && emitting_side) I += material.emission;  // an emitter shows its own Le
  I += terms.reflection;                                          // + kr Ir
  return terms.fog * I + (1.0f - terms.fog) * terms.fog_colour;   // depth cueing
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
    t.S = w.x * t.S + w.y * tb.S + w.z * tc.S;
    t.IL = w.x * t.IL + w.y * tb.IL + w.z * tc.IL;
    t.diffuse = w.x * t.diffuse + w.y * tb.diffuse + w.z * tc.diffuse;
    t.specular = w.x * t.specular + w.y * tb.specular + w.z * tc.specular;
  }
  return out;
}

}  // namespace luz
