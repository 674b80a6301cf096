#include "local/reflection_maps.h"

#include "local/cube_face.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>


namespace luz {
namespace {

constexpr float pi = 3.14159265358979f;

// Bilinear weights as GL computes them: texel centres at (i + 1/2) / size.
struct Taps {
  int i0, i1;
  float w;  // the weight of i1
};

Taps taps(float coordinate, int size, bool repeat) {
  const float u = coordinate * float(size) - 0.5f;
  const float floor_u = std::floor(u);
  int i0 = int(floor_u), i1 = i0 + 1;
  if (repeat) {
    i0 = ((i0 % size) + size) % size;
    i1 = ((i1 % size) + size) % size;
  } else {
    i0 = std::clamp(i0, 0, size - 1);
    i1 = std::clamp(i1, 0, size - 1);
  }
  return {i0, i1, u - floor_u};
}

}  // namespace

glm::vec4 sample_cube(const CubeMapData& cube, const glm::vec3& D) {
  if (cube.size == 0 || !cube.texel) return glm::vec4(0.0f);
  const CubeFacePoint p = cube_face_point(D);
  const int face = p.face;
  const Taps s = taps(p.s, cube.size, false);
  const Taps t = taps(p.t, cube.size, false);
  auto at = [&](int x, int y) { return cube.texel(face, x, y); };
  return (1 - s.w) * (1 - t.w) * at(s.i0, t.i0) + s.w * (1 - t.w) * at(s.i1, t.i0) +
         (1 - s.w) * t.w * at(s.i0, t.i1) + s.w * t.w * at(s.i1, t.i1);
}

Rgb sample_environment(const Image& environment, const glm::vec3& D) {
  const glm::vec3 d = glm::normalize(D);
  const float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * pi);
  const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / pi;
  const Taps s = taps(u, environment.width, true);
  const Taps t = taps(v, environment.height, false);
  return (1 - s.w) * (1 - t.w) * environment.at(s.i0, t.i0) + s.w * (1 - t.w) * environment.at(s.i1, t.i0) +
         (1 - s.w) * t.w * environment.at(s.i0, t.i1) + s.w * t.w * environment.at(s.i1, t.i1);
}

Rgb reflected_radiance(const ReflectionLookup& lookup, const glm::vec3& R) {
  const Rgb surroundings = lookup.environment ? sample_environment(*lookup.environment, R) : lookup.background;
  if (lookup.cube.size == 0 || !lookup.cube.texel) return surroundings;
  const glm::vec4 seen = sample_cube(lookup.cube, R);
  // The cube was cleared to alpha 0 and every surface drawn with alpha 1; filtered, alpha is the
  // share of the texel footprint that saw a surface.
  return Rgb(seen) + (1.0f - seen.a) * surroundings;
}

}  // namespace luz
