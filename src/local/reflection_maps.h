#pragma once
// Reflection maps (slide 19, "mapas de reflexión"): the kr * Ir of Whitted's formula with Ir read
// from a picture of the surroundings instead of a traced ray. LocalRenderer renders a cube map
// from the centre of every object with kr > 0 (the object left out, see local_renderer.cpp);
// where that cube saw nothing (alpha 0), the environment image or the background shows.
//
// This file is the lookup's CPU twin (shaders/lighting.glsl reflected()), for the inspector and
// the tests: the cube maps read back, sampled as GL samples them (bilinear within a face, clamped
// at its edges: GL 3.3 cube maps are not seamless unless asked), and the equirectangular
// environment sampled as lighting.glsl environment() does.
#include <functional>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/color.h"
#include "core/image.h"

namespace luz {

// A cube map: its texels (faces in GL's order +X -X +Y -Y +Z -Z, y = 0 at t = 0), read from the
// GPU on demand.
struct CubeMapData {
  int size = 0;
  std::function<glm::vec4(int face, int x, int y)> texel;
};

struct ReflectionLookup {
  CubeMapData cube;                       // the object's map (size 0: only the surroundings)
  const Image* environment = nullptr;     // equirectangular, linear; nullptr: the background
  Rgb background{0.0f};
};

// texture(samplerCube, D) with linear filtering.
glm::vec4 sample_cube(const CubeMapData& cube, const glm::vec3& D);

// lighting.glsl environment(): u = 1/2 + atan2(D.x, -D.z) / 2pi (the image's centre looks down
// -Z), v = acos(D.y) / pi (the top row looks up); bilinear, repeating in u, clamped in v.
Rgb sample_environment(const Image& environment, const glm::vec3& D);

// lighting.glsl reflected(): Ir along R, the cube's picture over the surroundings.
Rgb reflected_radiance(const ReflectionLookup& lookup, const glm::vec3& R);


}  // namespace luz
