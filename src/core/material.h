#pragma once
// A material as SCENES.md maps it from glTF: the coefficients of the lecture's formula
//   I = Ia*ka + sum_i S_i * IL_i * [kd*cos(theta) + ks*cos^n(alpha)] + kr*Ir + kt*It
// plus the emitted radiance Le of area lights.
#include <string>

#include "core/color.h"

namespace luz {

struct Material {
  std::string name = "default";
  Rgb kd{0.8f};         // diffuse reflectance (albedo, rho in radiosity)
  Rgb ka{0.8f};         // ambient coefficient
  Rgb ks{0.0f};         // specular (highlight) coefficient
  float shininess = 1;  // Phong exponent n
  Rgb kr{0.0f};         // mirror reflection coefficient
  Rgb kt{0.0f};         // transmission coefficient
  float ior = 1.5f;     // index of refraction eta
  Rgb emission{0.0f};   // emitted radiance Le
  int kd_texture = -1;  // index into Scene::textures modulating kd, or -1
  int emission_texture = -1;  // index into Scene::textures modulating Le (emissiveTexture), or -1

  bool is_emissive() const { return emission.r > 0 || emission.g > 0 || emission.b > 0; }
  std::string to_string() const;
  bool operator==(const Material&) const = default;
};

// SCENES.md: the Phong exponent implied by a glTF roughness r when extras.shininess is absent,
// n = 2/r^4 - 2, clamped to [1, 10000].
float shininess_from_roughness(float roughness);

}  // namespace luz
