#include "core/material.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace luz {

float shininess_from_roughness(float roughness) {
  const float r4 = std::pow(std::max(roughness, 0.0f), 4.0f);
  if (r4 <= 0.0f) return 10000.0f;
  return std::clamp(2.0f / r4 - 2.0f, 1.0f, 10000.0f);
}

std::string Material::to_string() const {
  auto rgb = [](const Rgb& c) { return fmt::format("({:.3g}, {:.3g}, {:.3g})", c.r, c.g, c.b); };
  return fmt::format("Material \"{}\" [kd {} ka {} ks {} n {:.4g} kr {} kt {} ior {:.3g} Le {}{}]",
                     name, rgb(kd), rgb(ka), rgb(ks), shininess, rgb(kr), rgb(kt), ior,
                     rgb(emission), kd_texture >= 0 ? fmt::format(" tex {}", kd_texture) : "");
}

}  // namespace luz
