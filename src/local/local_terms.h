#pragma once
// The lecture's local formula evaluated on the CPU, term by term, for one surface point:
//   I = I_A + sum_i S_i (I_D,i + I_S,i)  (+ Le)  + kr Ir,  then the fog: f I + (1 - f) C_fog
// It mirrors shaders/lighting.glsl line for line, so the viewer's inspector can show the class
// what each term contributes at a clicked pixel, and a test can hold the two implementations
// against each other (tests/test_local_terms.cpp).
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/color.h"
#include "core/material.h"
#include "core/scene.h"
#include "local/local_options.h"
#include "local/reflection_maps.h"
#include "local/shadow_maps.h"

namespace luz {

// One light's share at the point: S_i * IL_i * [kd cos(theta) + ks cos^n(alpha)].
struct LightTerm {
  std::string name;      // the light's name, or "emitter N" for an emissive triangle
  bool lit = false;      // cos(theta) > 0: the light is in front of the surface
  float theta = 0.0f;    // angle between N and L, radians
  float alpha = 0.0f;    // angle between R and V (Phong) or N and H (Blinn), radians
  float d = 0.0f;        // distance to the light (0 for a directional light)
  float f_att = 1.0f;    // distance attenuation f_att(d) (1 for a directional light)
  float spot = 1.0f;     // the spot's angular factor (1 for other lights)
  float S = 1.0f;        // the shadow factor S_i: 0 when something blocks the light (shadow maps)
  Rgb IL{0.0f};          // the light's IL at the point
  Rgb diffuse{0.0f};     // I_D,i = S_i IL kd cos(theta)      (0 when the term is off)
  Rgb specular{0.0f};    // I_S,i = S_i IL ks cos^n(alpha)    (0 when the term is off)
};

struct TermValues {
  Rgb ambient{0.0f};              // I_A = Ia ka
  std::vector<LightTerm> lights;  // punctual lights first, then emissive triangles
  Rgb diffuse{0.0f};              // sum of I_D,i (kd before its texture)
  Rgb specular{0.0f};             // sum of I_S,i
  Rgb reflection{0.0f};           // kr Ir from the reflection map (0 when it is off)
  float fog = 1.0f;               // the fog factor f at the point (1 without fog)
  Rgb fog_colour{0.0f};
};

// The punctual lights the shaders take (lighting.glsl MAX_LIGHTS; LocalRenderer drops the rest).
inline constexpr int max_shader_lights = 16;

// lighting.glsl's local_model(): the terms at world point P with unit normal N (already turned
// toward the viewer's side) seen from the unit direction V toward the eye. `area_lights` are the
// emitters as the renderer draws them (LocalRenderer::area_lights(); the scene's own list when it
// has no more than the shaders' 64). `shadows`: the renderer's shadow maps
// (LocalRenderer::shadow_lookup()), or nullptr for S_i = 1.
TermValues evaluate_terms(const Scene& scene, const Material& material, const glm::vec3& P,
                          const glm::vec3& N, const glm::vec3& V, const LocalOptions& options,
                          std::span<const AreaLight> area_lights, const ShadowLookup* shadows = nullptr);
// The same with the scene's own emitters.
TermValues evaluate_terms(const Scene& scene, const Material& material, const glm::vec3& P,
                          const glm::vec3& N, const glm::vec3& V, const LocalOptions& options);

// lighting.glsl fog_factor(): the share of radiance that crosses distance d of fog.
float fog_factor(const Fog& fog, float d);

// lighting.glsl write_fragment()'s two additions, for a point at distance d from the eye with the
// mirror direction R: terms.reflection = kr Ir (when the reflection map is on) and the fog.
void add_reflection_and_fog(TermValues& terms, const Material& material, const LocalOptions& options,
                            const ReflectionLookup& reflection, const glm::vec3& R, float d);

// lighting.glsl's write_fragment(): I = I_A + I_D * texture + I_S (+ Le on an emitter's front
// side) + kr Ir, then f I + (1 - f) C_fog.
Rgb radiance(const TermValues& terms, const Material& material, const LocalOptions& options,
             const Rgb& kd_texture_factor, bool emitting_side);

// w0 a + w1 b + w2 c, field by field (Gouraud: the vertices' terms interpolated). The three must
// come from the same scene and options, so their light lists line up.
TermValues blend(const TermValues& a, const TermValues& b, const TermValues& c, const glm::vec3& w);

}  // namespace luz
