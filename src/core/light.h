#pragma once
// Punctual lights (KHR_lights_punctual) in the program's units, SCENES.md "Lights":
// point and spot: radiant intensity I (W/sr); directional: irradiance E_perp (W/m^2).
#include <string>

#include <glm/vec3.hpp>

#include "core/color.h"

namespace luz {

enum class LightType { point, spot, directional };

// f_att(d): physical 1/d^2, or the classroom form 1/(c0 + c1 d + c2 d^2).
struct Attenuation {
  bool classroom = false;
  glm::vec3 c{1.0f, 0.0f, 0.0f};  // c0, c1, c2 of the classroom form
  float factor(float d) const {  // inline: the tracer's lanes compute it for many points at once
    if (!classroom) return 1.0f / (d * d);
    return 1.0f / (c.x + c.y * d + c.z * d * d);
  }
  bool operator==(const Attenuation&) const = default;
};

struct Light {
  std::string name;
  LightType type = LightType::point;
  Rgb intensity{1.0f};              // colour x intensity: W/sr (point, spot) or W/m^2 (directional)
  glm::vec3 position{0.0f};         // world space (point, spot)
  glm::vec3 direction{0, 0, -1};    // unit, the way the light travels (spot, directional)
  float inner_cone = 0.0f;          // radians (spot)
  float outer_cone = 0.7853981634f; // radians (spot), glTF default pi/4
  float warn_exponent = 0.0f;       // > 0: Warn's cos^p spot instead of the smooth cone
  Attenuation attenuation;
  bool enabled = true;

  // The spot's angular factor for a unit vector from the light toward the lit point:
  // glTF's smooth falloff between inner and outer cone, or Warn's cos^p inside the outer cone.
  float spot_factor(const glm::vec3& light_to_point) const;
  std::string to_string() const;
  bool operator==(const Light&) const = default;
};

const char* to_string(LightType type);

}  // namespace luz
