#pragma once
// The switches of the local models (slides 15-19). One struct, defaults here only: the panel
// edits it, `luz render` fills it from flags, tests construct it.
//
// Slide 19's "other possibilities" are the sub-structs below. Every one is off by default, so the
// plain formula of slides 15-18 is what a scene shows until a switch is thrown (and the goldens
// and the inspector's formula of the plain model stay what they were). Distance attenuation and
// non-uniform (spot, Warn) lights are not switches here: they belong to each light (core::Light,
// edited in the panel's Lights section, `F` switches every light's f_att).
#include <string>

#include "core/color.h"
#include "core/term_switches.h"

namespace luz {

enum class Shading {
  flat,     // one colour per triangle: the formula at its centroid with the face normal
  gouraud,  // the formula per vertex, colours interpolated
  phong,    // normals interpolated, the formula per fragment
};

// Atmospheric attenuation ("atenuación atmosférica", depth cueing): the radiance I reaching the
// eye from distance d is blended toward the fog colour, I' = f I + (1 - f) C_fog, with
//   linear:      f = (far - d) / (far - near), clamped to [0, 1]
//   exponential: f = exp(-density d)
// d is the Euclidean distance from the eye. Rays that hit nothing see the fog colour (f = 0).
enum class FogMode { off, linear, exponential };

struct Fog {
  FogMode mode = FogMode::off;
  Rgb colour{0.25f, 0.27f, 0.3f};  // radiance, W/(m^2 sr)
  float near = 2.0f;               // m, linear: no fog closer than this
  float far = 20.0f;               // m, linear: only fog beyond this
  float density = 0.1f;            // 1/m, exponential
  bool operator==(const Fog&) const = default;
};

// Blocking of the sources by occlusion ("bloqueo de fuentes por oclusión"): the lecture's S_i,
// from shadow maps. A point light and each emitter group get a cube of six maps (linear distance
// from the light), a spot a perspective map, a directional light an orthographic one. A point is
// lit by light i (S_i = 1) when its distance to the light, less the bias, is not beyond what the
// map stored; else S_i = 0.
//   bias = constant + slope * texel * tan(theta), and P is first moved normal_offset texels
//   along N (texel: the world size of one map texel at P).
struct Shadows {
  bool on = false;
  float constant_bias = 0.002f;  // m
  float slope_bias = 1.0f;       // texels of depth per unit of tan(theta)
  float normal_offset = 1.0f;    // texels along the normal
  int map_size = 1024;           // texels per side of every map (cube faces too)
  bool operator==(const Shadows&) const = default;
};

// Non-refractive transparency ("transparencias no refractivas"): a surface with kt > 0 lets what
// lies behind it through, unbent, as Whitted's formula weighs a transmitted ray with ior 1:
//   I = I_local + kt * I_behind
// Transparent meshes are drawn after the opaque ones, back to front.
struct Transparency {
  bool on = false;
  bool operator==(const Transparency&) const = default;
};

// Reflection maps ("mapas de reflexión"): kr * Ir with Ir looked up in a cube map rendered from the
// centre of each object with kr > 0 (the object itself left out), along the mirror direction
// R = 2 (N.V) N - V. Where the cube map saw nothing, the environment image (equirectangular) or
// the scene's background.
struct ReflectionMap {
  bool on = false;
  int resolution = 256;     // texels per cube face
  std::string environment;  // an equirectangular image file (linear after decoding), or empty
  bool operator==(const ReflectionMap&) const = default;
};

struct LocalOptions {
  Shading shading = Shading::phong;
  TermSwitches terms;   // slides 15-18, one switch per term

  // Slide 19.
  Fog fog;
  Shadows shadows;
  Transparency transparency;
  ReflectionMap reflection;
  bool operator==(const LocalOptions&) const = default;
};

const char* to_string(Shading shading);
const char* to_string(FogMode mode);

}  // namespace luz
