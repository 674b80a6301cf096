#pragma once
// Linear RGB (Rec. 709 primaries). Radiance, reflectances and intensities are all RGB triples.
#include <glm/vec3.hpp>

namespace luz {

using Rgb = glm::vec3;

inline bool is_finite(const Rgb& c) {
  return c.r == c.r && c.g == c.g && c.b == c.b &&  // not NaN
         c.r - c.r == 0.0f && c.g - c.g == 0.0f && c.b - c.b == 0.0f;  // not Inf
}

}  // namespace luz
