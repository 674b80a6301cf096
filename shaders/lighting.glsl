// lighting.glsl: the lecture's local illumination model (slides 15-19), shared by the flat,
// Gouraud and Phong programs (spliced in after each stage's #version line).
//
//   I = I_A + sum_i (I_D,i + I_S,i)  (+ Le)
//   I_A = Ia * ka                       ambient            (slide 15)
//   I_D = IL * kd * cos(theta)          Lambert            (slide 16)
//   I_S = IL * ks * cos^n(alpha)        Phong's highlight  (slide 17)
//   IL  = I * f_att(d) * spot / pi      point and spot lights, attenuated (slide 18)
//   IL  = E_perp / pi                   directional lights
// The 1/pi makes the diffuse term Lambert's law in radiance, kd/pi * E (SCENES.md), so this
// picture agrees with the ray tracer and radiosity.
//
// Sections: [limits and uniforms] [lights] [the formula] [two-sided lighting]

// ---- [limits and uniforms] --------------------------------------------------------------------
// Must match LocalRenderer's constants (local_renderer.cpp), which merge or drop extra lights.
#define MAX_LIGHTS 16
#define MAX_AREA_LIGHTS 64

const float PI = 3.14159265358979;
const int POINT = 0;
const int SPOT = 1;
const int DIRECTIONAL = 2;

struct PunctualLight {
  int type;             // POINT, SPOT or DIRECTIONAL
  vec3 intensity;       // I in W/sr (point, spot), E_perp in W/m^2 (directional)
  vec3 position;        // world space (point, spot)
  vec3 direction;       // unit, the way the light travels (spot, directional)
  bool classroom;       // f_att = 1/(c0 + c1 d + c2 d^2) instead of 1/d^2
  vec3 attenuation;     // c0, c1, c2
  float cos_inner;      // spot cone (glTF smooth falloff between inner and outer)
  float cos_outer;
  float warn_exponent;  // > 0: Warn's cos^p spot inside the outer cone
};

// An emissive triangle as a point light at its centroid (SCENES.md): I = Le * A * cos(theta_e).
struct AreaLight {
  vec3 position;  // the triangle's centroid ("centroid" is a GLSL keyword)
  vec3 normal;  // unit, the side it emits from
  vec3 power;   // Le * A
};

uniform int u_light_count;
uniform PunctualLight u_lights[MAX_LIGHTS];
uniform int u_area_light_count;
uniform AreaLight u_area_lights[MAX_AREA_LIGHTS];

uniform vec3 u_eye;      // camera position, world space
uniform vec3 u_ambient;  // Ia

// The material (core/material.h).
uniform vec3 u_ka;
uniform vec3 u_kd;
uniform vec3 u_ks;
uniform float u_shininess;  // n
uniform vec3 u_emission;    // Le
uniform bool u_has_kd_texture;
uniform sampler2D u_kd_texture;  // baseColorTexture, linear texels

// The switches of LocalOptions, one per term.
uniform bool u_ambient_on;
uniform bool u_diffuse_on;
uniform bool u_specular_on;
uniform bool u_emission_on;
uniform bool u_blinn;

// ---- [lights] ----------------------------------------------------------------------------------
// f_att(d) as core/light.cpp Attenuation::factor.
float attenuation(PunctualLight light, float d) {
  if (!light.classroom) return 1.0 / (d * d);
  return 1.0 / (light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d * d);
}

// The spot's angular factor, as core/light.cpp Light::spot_factor.
float spot_factor(PunctualLight light, vec3 light_to_point) {
  if (light.type != SPOT) return 1.0;
  float cos_angle = dot(light.direction, light_to_point);
  if (light.warn_exponent > 0.0)
    return cos_angle >= light.cos_outer ? pow(max(cos_angle, 0.0), light.warn_exponent) : 0.0;
  // KHR_lights_punctual's smooth falloff: a squared linear ramp in cos(angle).
  float scale = 1.0 / max(0.001, light.cos_inner - light.cos_outer);
  float t = clamp((cos_angle - light.cos_outer) * scale, 0.0, 1.0);
  return t * t;
}

// IL and the unit direction L from P toward light i.
vec3 punctual_IL(int i, vec3 P, out vec3 L) {
  PunctualLight light = u_lights[i];
  if (light.type == DIRECTIONAL) {
    L = -light.direction;
    return light.intensity / PI;  // IL = E_perp / pi
  }
  vec3 to_light = light.position - P;
  float d = length(to_light);
  L = to_light / d;
  return light.intensity * attenuation(light, d) * spot_factor(light, -L) / PI;
}

// IL and L for emissive triangle i: a point light of intensity Le * A * cos(theta_e), 1/d^2.
vec3 area_IL(int i, vec3 P, out vec3 L) {
  AreaLight light = u_area_lights[i];
  vec3 to_light = light.position - P;
  float d = length(to_light);
  if (d < 1e-6) { L = vec3(0.0); return vec3(0.0); }  // P is the light's own centroid
  L = to_light / d;
  float cos_theta_e = max(dot(light.normal, -L), 0.0);  // dark behind the emitter
  return light.power * cos_theta_e / (d * d) / PI;
}

// ---- [the formula] -----------------------------------------------------------------------------
// The three terms kept apart: Gouraud interpolates them and applies the kd texture per fragment.
struct Terms {
  vec3 ambient;   // I_A
  vec3 diffuse;   // sum of I_D (with the material's kd, before the texture)
  vec3 specular;  // sum of I_S
};

// cos(alpha): Phong's mirror direction R of the light against the viewer V, or Blinn's N.H.
float cos_alpha(vec3 N, vec3 L, vec3 V) {
  if (u_blinn) return max(dot(N, normalize(L + V)), 0.0);
  vec3 R = reflect(-L, N);  // 2 (N.L) N - L
  return max(dot(R, V), 0.0);
}

// One light's contribution IL * [kd cos(theta) + ks cos^n(alpha)] to the terms.
void add_light(inout Terms terms, vec3 IL, vec3 N, vec3 L, vec3 V) {
  float cos_theta = dot(N, L);
  if (cos_theta <= 0.0) return;  // the light is behind the surface: no diffuse, no highlight
  if (u_diffuse_on)  terms.diffuse  += IL * u_kd * cos_theta;                              // I_D
  if (u_specular_on) terms.specular += IL * u_ks * pow(cos_alpha(N, L, V), u_shininess);  // I_S
}

// The formula at world point P with unit normal N (already facing the viewer's side).
Terms local_model(vec3 P, vec3 N) {
  vec3 V = normalize(u_eye - P);
  Terms terms = Terms(vec3(0.0), vec3(0.0), vec3(0.0));
  if (u_ambient_on) terms.ambient = u_ambient * u_ka;  // I_A = Ia * ka
  for (int i = 0; i < u_light_count; ++i) {
    vec3 L;
    vec3 IL = punctual_IL(i, P, L);
    add_light(terms, IL, N, L, V);
  }
  for (int i = 0; i < u_area_light_count; ++i) {
    vec3 L;
    vec3 IL = area_IL(i, P, L);
    add_light(terms, IL, N, L, V);
  }
  return terms;
}

// kd's texture factor at uv (1 without a texture or with textures switched off).
vec3 kd_texture_factor(vec2 uv) {
  return u_has_kd_texture ? texture(u_kd_texture, uv).rgb : vec3(1.0);
}

// I = I_A + I_D * texture + I_S (+ Le): the sum the fragment writes.
vec3 radiance(Terms terms, vec2 uv, bool emitting_side) {
  vec3 I = terms.ambient + terms.diffuse * kd_texture_factor(uv) + terms.specular;
  if (u_emission_on && emitting_side) I += u_emission;  // an emitter shows its own Le
  return I;
}

// ---- [two-sided lighting] ----------------------------------------------------------------------
#ifdef LUZ_FRAGMENT_SHADER
// True when the viewer sees the back of the face, i.e. the side opposite the shading normal N.
// The face's plane comes from the screen-space derivatives of P (exact on a flat triangle,
// whatever its winding), so a Cornell box is lit from inside however its walls were wound.
bool viewer_sees_back(vec3 P, vec3 N) {
  vec3 face = cross(dFdx(P), dFdy(P));
  return dot(face, N) * dot(face, u_eye - P) < 0.0;
}
#endif
