#include "core/light.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace luz {

float Light::spot_factor(const glm::vec3& light_to_point) const {
  if (type != LightType::spot) return 1.0f;
  const float cos_angle = glm::dot(direction, light_to_point);
  const float cos_outer = std::cos(outer_cone);
  if (warn_exponent > 0.0f)
    return cos_angle >= cos_outer ? std::pow(std::max(cos_angle, 0.0f), warn_exponent) : 0.0f;
  // KHR_lights_punctual's recommended smooth falloff: a squared linear ramp in cos(angle).
  const float scale = 1.0f / std::max(0.001f, std::cos(inner_cone) - cos_outer);
  const float t = std::clamp((cos_angle - cos_outer) * scale, 0.0f, 1.0f);
  return t * t;
}

const char* to_string(LightType type) {
  switch (type) {
    case LightType::point: return "point";
    case LightType::spot: return "spot";
    case LightType::directional: return "directional";
  }
  return "?";
}

std::string Light::to_string() const {
  std::string s = fmt::format("Light \"{}\" [{} I ({:.4g}, {:.4g}, {:.4g})", name,
                              luz::to_string(type), intensity.r, intensity.g, intensity.b);
  if (type != LightType::directional)
    s += fmt::format(" at ({:.4g}, {:.4g}, {:.4g})", position.x, position.y, position.z);
  if (type != LightType::point)
    s += fmt::format(" dir ({:.3g}, {:.3g}, {:.3g})", direction.x, direction.y, direction.z);
  if (type == LightType::spot)
    s += warn_exponent > 0 ? fmt::format(" warn p {:.3g}", warn_exponent)
                           : fmt::format(" cone {:.3g}..{:.3g} rad", inner_cone, outer_cone);
  if (attenuation.classroom)
    s += fmt::format(" att 1/({:.3g} + {:.3g} d + {:.3g} d^2)", attenuation.c.x,
                     attenuation.c.y, attenuation.c.z);
  return s + "]";
}

}  // namespace luz
