// lighting.glsl: the lecture's local illumination model (slides 15-19), shared by the flat,
// Gouraud and Phong programs (spliced in after each stage's #version line).
//
//   I = I_A + sum_i S_i (I_D,i + I_S,i)  (+ Le)  + kr Ir  + kt It
//   I_A = Ia * ka                       ambient            (slide 15)
//   I_D = IL * kd * cos(theta)          Lambert            (slide 16)
//   I_S = IL * ks * cos^n(alpha)        Phong's highlight  (slide 17)
//   IL  = I * f_att(d) * spot / pi      point and spot lights, attenuated (slide 18)
//   IL  = E_perp / pi                   directional lights
// The 1/pi makes the diffuse term Lambert's law in radiance, kd/pi * E (SCENES.md), so this
// picture agrees with the ray tracer and radiosity.
//
// Slide 19's other possibilities, each behind its switch (local/local_options.h):
//   f_att(d), spot and Warn's cos^p    per light, in punctual_IL()           (distance, non-uniform)
//   S_i                                shadow maps, shadow_factor()          (blocking by occlusion)
//   kr Ir                              reflection map, reflected()           (reflection maps)
//   kt It                              blending with what lies behind        (non-refractive transparency)
//   I' = f I + (1 - f) C_fog           depth cueing, fog_factor()            (atmospheric attenuation)
// Whitted's formula (slide 25) is the same sum with S_i, Ir and It found by rays.
//
// Sections: [limits and uniforms] [lights] [shadows: S_i] [the formula] [reflection map: kr Ir]
//           [atmospheric attenuation] [two-sided lighting] [the fragment]

// ---- [limits and uniforms] --------------------------------------------------------------------
// Must match LocalRenderer's constants (local_renderer.cpp), which merge or drop extra lights.
#define MAX_LIGHTS 16
#define MAX_AREA_LIGHTS 64

const float PI = 3.14159265358979;
const int POINT = 0;
const int SPOT = 1;
const int DIRECTIONAL = 2;
const int SHADOW_NONE = 0;
const int SHADOW_CUBE = 1;
const int SHADOW_PERSPECTIVE = 2;
const int SHADOW_ORTHOGRAPHIC = 3;
const int FOG_OFF = 0;
const int FOG_LINEAR = 1;
const int FOG_EXPONENTIAL = 2;

// Where a light's shadow map is (local/shadow_maps.h ShadowView).
struct ShadowView {
  int kind;        // SHADOW_NONE, SHADOW_CUBE, SHADOW_PERSPECTIVE or SHADOW_ORTHOGRAPHIC
  int layer;       // the first layer (a cube: six) in u_shadow_maps
  vec3 origin;     // the light's position (cube, perspective)
  vec3 direction;  // the way a directional light travels (orthographic)
  mat4 matrix;     // world -> the map's clip space (perspective, orthographic)
  float texel;     // a texel's world size, per metre of distance (cube, perspective) or absolute
};

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
  ShadowView shadow;
};

// An emissive triangle as a point light at its centroid (SCENES.md): I = Le * A * cos(theta_e).
struct AreaLight {
  vec3 position;  // the triangle's centroid ("centroid" is a GLSL keyword)
  vec3 normal;  // unit, the side it emits from
  vec3 power;   // Le * A
  ShadowView shadow;  // its group's cube (kind SHADOW_NONE while shadows are off)
};

uniform PunctualLight u_lights[MAX_LIGHTS];
// How many of each the shader adds up: constants of the program as well (LocalRenderer counts the
// lights that are on, see below).
const int light_count = LUZ_LIGHT_COUNT;
const int area_light_count = LUZ_AREA_LIGHT_COUNT;
// And what each one is, so that only its own branches are compiled in: light i's type and the
// kind of its shadow map (-1 past light_count), and the kind of every emitter's map (all cubes, or
// none).
const int light_type[MAX_LIGHTS] = int[](LUZ_LIGHT_TYPES);
const int light_shadow_kind[MAX_LIGHTS] = int[](LUZ_LIGHT_SHADOW_KINDS);
const int area_shadow_kind = LUZ_AREA_SHADOW_KIND;
uniform AreaLight u_area_lights[MAX_AREA_LIGHTS];

uniform vec3 u_eye;      // camera position, world space
uniform vec3 u_ambient;  // Ia

// The material (core/material.h).
uniform vec3 u_ka;
uniform vec3 u_kd;
uniform vec3 u_ks;
uniform float u_shininess;  // n
uniform vec3 u_emission;    // Le
uniform sampler2D u_kd_texture;  // baseColorTexture, linear texels
uniform sampler2D u_emission_texture;  // emissiveTexture, linear texels: multiplies Le
uniform vec3 u_kr;
uniform vec3 u_kt;

// The switches, one per term: constants of the program, not uniforms. LocalRenderer compiles one
// program per combination it draws with (LUZ_* defined before this file, local_renderer.cpp
// program_for), so a term that is off is not in the program at all: a software rasteriser such
// as llvmpipe runs both sides of every branch, and would pay for the shadow lookups, the cube map
// and the textures of every switch on every fragment.
const bool ambient_on = LUZ_AMBIENT_ON;        // I_A
const bool diffuse_on = LUZ_DIFFUSE_ON;        // I_D
const bool specular_on = LUZ_SPECULAR_ON;      // I_S
const bool emission_on = LUZ_EMISSION_ON;      // Le
const bool blinn = LUZ_BLINN;                  // cos(alpha) = N.H instead of R.V
const bool has_kd_texture = LUZ_KD_TEXTURE;    // this mesh's kd is textured (and textures are on)
const bool has_emission_texture = LUZ_EMISSION_TEXTURE;  // this mesh's Le is textured
// Slide 19's (LocalOptions' sub-structs, and the mesh's part in them).
const bool shadows_on = LUZ_SHADOWS_ON;        // S_i from the shadow maps
const bool reflection_on = LUZ_REFLECTION_ON;  // this mesh has kr > 0 and a reflection map
const bool has_environment = LUZ_ENVIRONMENT;  // an environment image behind the cube maps
const int fog_mode = LUZ_FOG_MODE;             // FOG_OFF, FOG_LINEAR, FOG_EXPONENTIAL
const bool transparent = LUZ_TRANSPARENT;      // this mesh is drawn blended over what lies behind

// Their parameters.
uniform sampler2DArray u_shadow_maps;  // R32F, one layer per map (local/shadow_maps.h)
uniform float u_shadow_constant_bias;  // m
uniform float u_shadow_slope_bias;     // texels per unit of tan(theta)
uniform float u_shadow_normal_offset;  // texels
uniform samplerCube u_reflection_map;  // the surroundings seen from the object's centre
uniform sampler2D u_environment;       // equirectangular, linear
uniform vec3 u_background;
uniform vec3 u_fog_colour;
uniform float u_fog_near;
uniform float u_fog_far;
uniform float u_fog_density;

// ---- [lights] ----------------------------------------------------------------------------------
// The lights' fields are read one by one, never a light's struct whole: ANGLE (the page's WebGL)
// copies a uniform array indexed by a variable whole, every light with its shadow matrix, for
// each such copy, and SwiftShader spent most of a Phong frame on it.

// f_att(d) of light i, as core/light.cpp Attenuation::factor.
float attenuation(int i, float d) {
  if (!u_lights[i].classroom) return 1.0 / (d * d);
  vec3 c = u_lights[i].attenuation;
  return 1.0 / (c.x + c.y * d + c.z * d * d);
}

// Light i's angular factor, as core/light.cpp Light::spot_factor.
float spot_factor(int i, vec3 light_to_point) {
  if (light_type[i] != SPOT) return 1.0;
  float cos_angle = dot(u_lights[i].direction, light_to_point);
  float cos_outer = u_lights[i].cos_outer;
  if (u_lights[i].warn_exponent > 0.0)
    return cos_angle >= cos_outer ? pow(max(cos_angle, 0.0), u_lights[i].warn_exponent) : 0.0;
  // KHR_lights_punctual's smooth falloff: a squared linear ramp in cos(angle).
  float scale = 1.0 / max(0.001, u_lights[i].cos_inner - cos_outer);
  float t = clamp((cos_angle - cos_outer) * scale, 0.0, 1.0);
  return t * t;
}

// IL and the unit direction L from P toward light i (its type: light_type[i], known to the
// compiler).
vec3 punctual_IL(int i, vec3 P, out vec3 L) {
  if (light_type[i] == DIRECTIONAL) {
    L = -u_lights[i].direction;
    return u_lights[i].intensity / PI;  // IL = E_perp / pi
  }
  vec3 to_light = u_lights[i].position - P;
  float d = length(to_light);
  L = to_light / d;
  return u_lights[i].intensity * attenuation(i, d) * spot_factor(i, -L) / PI;
}

// IL and L for emissive triangle i: a point light of intensity Le * A * cos(theta_e), 1/d^2.
vec3 area_IL(int i, vec3 P, out vec3 L) {
  vec3 to_light = u_area_lights[i].position - P;
  float d = length(to_light);
  if (d < 1e-6) { L = vec3(0.0); return vec3(0.0); }  // P is the light's own centroid
  L = to_light / d;
  float cos_theta_e = max(dot(u_area_lights[i].normal, -L), 0.0);  // dark behind the emitter
  return u_area_lights[i].power * cos_theta_e / (d * d) / PI;
}

// ---- [shadows: S_i] ---------------------------------------------------------------------------
// The texel of direction D on a cube around the light: the OpenGL specification's cube-map rule
// (the major axis picks the face, sc and tc are the coordinates on it); the faces were rendered so
// that their image axes are sc and tc (local/shadow_maps.cpp). Returns (x, y, face).
ivec3 cube_texel(vec3 D, int size) {
  vec3 a = abs(D);
  int face;
  float sc, tc, ma;
  if (a.x >= a.y && a.x >= a.z) {
    face = D.x >= 0.0 ? 0 : 1;
    sc = D.x >= 0.0 ? -D.z : D.z;
    tc = -D.y;
    ma = a.x;
  } else if (a.y >= a.z) {
    face = D.y >= 0.0 ? 2 : 3;
    sc = D.x;
    tc = D.y >= 0.0 ? D.z : -D.z;
    ma = a.y;
  } else {
    face = D.z >= 0.0 ? 4 : 5;
    sc = D.z >= 0.0 ? D.x : -D.x;
    tc = -D.y;
    ma = a.z;
  }
  float s = 0.5 * (sc / ma + 1.0), t = 0.5 * (tc / ma + 1.0);
  return ivec3(clamp(int(floor(s * float(size))), 0, size - 1),
               clamp(int(floor(t * float(size))), 0, size - 1), face);
}

// S_i: 1 when the light reaches P (unit normal N facing the viewer, cos(theta) = N.L > 0), 0 when
// its shadow map holds a surface nearer the light. Bias against self-shadowing ("acne"): look up
// from P moved normal_offset texels along N, and forgive constant + slope * texel * tan(theta).
// Called only with shadows on and a map (view.kind not SHADOW_NONE).
float shadow_factor(ShadowView view, vec3 P, vec3 N, float cos_theta) {
  int size = textureSize(u_shadow_maps, 0).x;
  float texel = view.kind == SHADOW_ORTHOGRAPHIC ? view.texel : view.texel * length(P - view.origin);
  vec3 Q = P + N * (u_shadow_normal_offset * texel);
  float sin_theta = sqrt(max(1.0 - cos_theta * cos_theta, 0.0));
  float tan_theta = min(sin_theta / max(cos_theta, 1e-4), 10.0);
  float bias = u_shadow_constant_bias + u_shadow_slope_bias * texel * tan_theta;

  ivec3 at;
  float measured;
  if (view.kind == SHADOW_CUBE) {
    vec3 D = Q - view.origin;
    measured = length(D);
    at = cube_texel(D, size);
    at.z += view.layer;
  } else {
    vec4 clip = view.matrix * vec4(Q, 1.0);
    if (clip.w <= 0.0) return 1.0;  // behind a spot: outside its cone anyway
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (uv.x < 0.0 || uv.y < 0.0 || uv.x >= 1.0 || uv.y >= 1.0) return 1.0;  // off the map
    at = ivec3(int(floor(uv.x * float(size))), int(floor(uv.y * float(size))), view.layer);
    measured = view.kind == SHADOW_ORTHOGRAPHIC ? dot(Q, view.direction) : length(Q - view.origin);
  }
  float stored = texelFetch(u_shadow_maps, at, 0).r;
  return measured - bias > stored ? 0.0 : 1.0;
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
  if (blinn) return max(dot(N, normalize(L + V)), 0.0);
  vec3 R = reflect(-L, N);  // 2 (N.L) N - L
  return max(dot(R, V), 0.0);
}

// One light's contribution S_i * IL * [kd cos(theta) + ks cos^n(alpha)] to the terms, where
// cos(theta) = N.L > 0.
void add_light(inout Terms terms, vec3 IL, float S, float cos_theta, vec3 N, vec3 L, vec3 V) {
  if (diffuse_on)  terms.diffuse  += S * IL * u_kd * cos_theta;                              // I_D
  if (specular_on) terms.specular += S * IL * u_ks * pow(cos_alpha(N, L, V), u_shininess);  // I_S
}

// Punctual light i's contribution. Its type and shadow kind are constants of the program where i
// is a constant, which is what local_model() calls this with. Its shadow view is copied only when
// there is a map to look up (see [lights] on copies of uniform structs).
void add_punctual_light(inout Terms terms, int i, vec3 P, vec3 N, vec3 V) {
  vec3 L;
  vec3 IL = punctual_IL(i, P, L);
  float cos_theta = dot(N, L);
  if (cos_theta <= 0.0) return;  // the light is behind the surface: no diffuse, no highlight
  float S = 1.0;                                                                             // S_i
  if (shadows_on && light_shadow_kind[i] != SHADOW_NONE) {
    ShadowView shadow = u_lights[i].shadow;
    shadow.kind = light_shadow_kind[i];
    S = shadow_factor(shadow, P, N, cos_theta);
  }
  add_light(terms, IL, S, cos_theta, N, L, V);
}

// Emissive triangle i's, the same way (all of their maps are of one kind).
void add_area_light(inout Terms terms, int i, vec3 P, vec3 N, vec3 V) {
  vec3 L;
  vec3 IL = area_IL(i, P, L);
  float cos_theta = dot(N, L);
  if (cos_theta <= 0.0) return;
  float S = 1.0;
  if (shadows_on && area_shadow_kind != SHADOW_NONE) {
    ShadowView shadow = u_area_lights[i].shadow;
    shadow.kind = area_shadow_kind;
    S = shadow_factor(shadow, P, N, cos_theta);
  }
  add_light(terms, IL, S, cos_theta, N, L, V);
}

// The formula at world point P with unit normal N (already facing the viewer's side).
Terms local_model(vec3 P, vec3 N) {
  vec3 V = normalize(u_eye - P);
  Terms terms = Terms(vec3(0.0), vec3(0.0), vec3(0.0));
  if (ambient_on) terms.ambient = u_ambient * u_ka;  // I_A = Ia * ka
  // The punctual lights one call each, not a loop: Mesa unrolls a loop only while its body is
  // small, and a loop left rolled runs every type's and every shadow kind's code for every light
  // (the effects plate's six shadowed lights took 1.6-1.8x as long on llvmpipe; the written-out
  // calls compile for longer, once per machine with Mesa's shader cache). The calls past
  // light_count fold away.
#if MAX_LIGHTS != 16
#error "local_model() calls add_punctual_light() once per light: MAX_LIGHTS times"
#endif
#define PUNCTUAL(i) if (i < light_count) add_punctual_light(terms, i, P, N, V);
  PUNCTUAL(0)  PUNCTUAL(1)  PUNCTUAL(2)  PUNCTUAL(3)  PUNCTUAL(4)  PUNCTUAL(5)  PUNCTUAL(6)  PUNCTUAL(7)
  PUNCTUAL(8)  PUNCTUAL(9)  PUNCTUAL(10) PUNCTUAL(11) PUNCTUAL(12) PUNCTUAL(13) PUNCTUAL(14) PUNCTUAL(15)
#undef PUNCTUAL
  // The emitters one call each as well: indexed by a loop's variable, SwiftShader (the page's
  // WebGL) took a quarter to a third longer over the Cornell box's whole Phong frame, two
  // emitters, than with the calls written out (docs/web.md).
#if MAX_AREA_LIGHTS != 64
#error "local_model() calls add_area_light() once per emitter: MAX_AREA_LIGHTS times"
#endif
#define AREA(i) if (i < area_light_count) add_area_light(terms, i, P, N, V);
  AREA(0)  AREA(1)  AREA(2)  AREA(3)  AREA(4)  AREA(5)  AREA(6)  AREA(7)
  AREA(8)  AREA(9)  AREA(10) AREA(11) AREA(12) AREA(13) AREA(14) AREA(15)
  AREA(16) AREA(17) AREA(18) AREA(19) AREA(20) AREA(21) AREA(22) AREA(23)
  AREA(24) AREA(25) AREA(26) AREA(27) AREA(28) AREA(29) AREA(30) AREA(31)
  AREA(32) AREA(33) AREA(34) AREA(35) AREA(36) AREA(37) AREA(38) AREA(39)
  AREA(40) AREA(41) AREA(42) AREA(43) AREA(44) AREA(45) AREA(46) AREA(47)
  AREA(48) AREA(49) AREA(50) AREA(51) AREA(52) AREA(53) AREA(54) AREA(55)
  AREA(56) AREA(57) AREA(58) AREA(59) AREA(60) AREA(61) AREA(62) AREA(63)
#undef AREA
  return terms;
}

// COLOR_0 at the fragment, which multiplies kd (SCENES.md); the fragment shader sets it before
// write_fragment (white: no vertex colours).
vec3 kd_colour = vec3(1.0);

// kd's factor at uv: the texture (1 without a texture or with textures switched off) times the
// vertex colour.
vec3 kd_texture_factor(vec2 uv) {
  return (has_kd_texture ? texture(u_kd_texture, uv).rgb : vec3(1.0)) * kd_colour;
}

// I = I_A + I_D * texture + I_S (+ Le): the sum the fragment writes.
vec3 radiance(Terms terms, vec2 uv, bool emitting_side) {
  vec3 I = terms.ambient + terms.diffuse * kd_texture_factor(uv) + terms.specular;
  if (emission_on && emitting_side)  // an emitter shows its own Le, the texel at uv with a texture
    I += u_emission * (has_emission_texture ? texture(u_emission_texture, uv).rgb : vec3(1.0));
  return I;
}

// ---- [reflection map: kr Ir] -------------------------------------------------------------------
// The mirror direction of the viewer, R = 2 (N.V) N - V: where a mirror at P shows the world.
vec3 mirror_direction(vec3 P, vec3 N) { return reflect(normalize(P - u_eye), N); }

// What surrounds the scene along D: the environment image (equirectangular: its centre looks
// down -Z, its top row up) or the background radiance.
vec3 environment(vec3 D) {
  if (!has_environment) return u_background;
  D = normalize(D);
  vec2 uv = vec2(0.5 + atan(D.x, -D.z) / (2.0 * PI), acos(clamp(D.y, -1.0, 1.0)) / PI);
  return textureLod(u_environment, uv, 0.0).rgb;
}

// Ir along R: the cube map's picture (alpha: how much of the texel saw a surface) over the
// surroundings.
vec3 reflected(vec3 R) {
  vec4 seen = textureLod(u_reflection_map, R, 0.0);
  return seen.rgb + (1.0 - seen.a) * environment(R);
}

// ---- [atmospheric attenuation] -----------------------------------------------------------------
// Depth cueing: the share f of a surface's radiance that reaches the eye from distance d; the
// rest, 1 - f, is the fog colour.
float fog_factor(float d) {
  if (fog_mode == FOG_LINEAR) return clamp((u_fog_far - d) / max(u_fog_far - u_fog_near, 1e-6), 0.0, 1.0);
  if (fog_mode == FOG_EXPONENTIAL) return exp(-u_fog_density * d);
  return 1.0;
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

// What the surface at P sends to the eye before the fog: the local formula, + kr Ir.
vec3 surface_radiance(Terms terms, vec2 uv, bool emitting_side, vec3 R) {
  vec3 I = radiance(terms, uv, emitting_side);
  if (reflection_on) I += u_kr * reflected(R);  // + kr Ir
  return I;
}

#if LUZ_DISPLAY_OUTPUT
uniform float u_display_scale;  // 2^exposure
// What the window shows of radiance I: I x 2^exposure through the sRGB curve.
vec3 displayed(vec3 I) { return srgb_encode(I * u_display_scale); }
#endif

// ---- [the fragment] ----------------------------------------------------------------------------
#ifdef LUZ_FRAGMENT_SHADER
#if LUZ_DISPLAY_OUTPUT
// The viewer's opaque meshes: the radiance, and beside it in a second colour buffer what the
// window shows of it (displayed()), so that the window copies the picture instead of running
// its display pass over it.
layout(location = 0) out vec4 frag_radiance;
layout(location = 1) out vec4 frag_display;
#elif defined(LUZ_GLSL_ES)
// GLSL ES (the page) has no dual-source blending: a transparent mesh is drawn twice with one
// output, first its share of the pixel behind (blended dst x src: what comes through), then its
// radiance (blended dst + src), which sums to dual-source's I + kt x pixel behind.
layout(location = 0) out vec4 frag_radiance;
vec4 frag_transmittance;
uniform bool u_transmittance_pass;  // the first of the two draws writes frag_transmittance
#else
// Two outputs for dual-source blending (GL 3.3 core): the radiance, and what share of the pixel
// behind it comes through (kt, for a transparent mesh drawn with glBlendFunc(ONE, SRC1_COLOR)).
layout(location = 0, index = 0) out vec4 frag_radiance;
layout(location = 0, index = 1) out vec4 frag_transmittance;
#endif

// What the pixel shows of the surface at P: the local formula, + kr Ir, then the fog.
// A transparent surface adds kt times the pixel behind it (non-refractive transparency):
//   pixel = f (I + kt It) + (1 - f) C_fog,  with It taken as the pixel already drawn behind.
void write_fragment(Terms terms, vec2 uv, bool emitting_side, vec3 R, vec3 P) {
  vec3 I = surface_radiance(terms, uv, emitting_side, R);
  float f = fog_factor(length(P - u_eye));
  vec3 transmitted = transparent ? f * u_kt : vec3(0.0);
  // Alpha: how much of the pixel is covered, for the reflection cube maps (cleared to 0, where the
  // surroundings show through by 1 - alpha): a transparent surface covers 1 - kt of what is behind
  // it (kt's mean: one alpha for three channels).
  float through = (transmitted.r + transmitted.g + transmitted.b) / 3.0;
  frag_radiance = vec4(f * I + (1.0 - f) * u_fog_colour, 1.0 - through);
#if LUZ_DISPLAY_OUTPUT
  frag_display = vec4(displayed(frag_radiance.rgb), 1.0);
#else
  frag_transmittance = vec4(transmitted, through);
#endif
#if defined(LUZ_GLSL_ES) && !LUZ_DISPLAY_OUTPUT
  if (transparent && u_transmittance_pass) frag_radiance = frag_transmittance;
#endif
}
#endif
