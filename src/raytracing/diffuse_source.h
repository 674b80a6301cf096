#pragma once
// Where the hybrid model (slides 41-43) takes the diffuse light of a hit from: "Cálculo de brillos
// por trazado de rayos (dependiente del observador) y de la iluminación difusa por radiosidad
// (independiente del observador)". The tracer only knows this interface; src/hybrid/ implements
// it with a radiosity solution, so src/raytracing stays free of GL and of src/radiosity.
#include <glm/vec2.hpp>

#include "core/color.h"

namespace luz::rt {

class DiffuseSource {
public:
  virtual ~DiffuseSource() = default;
  // The view-independent radiance leaving the front side of triangle `triangle` of scene mesh
  // `mesh` at barycentrics (b1, b2) of its second and third vertex (point = A + b1 (B - A) +
  // b2 (C - A), Embree's u, v): everything diffuse, emission included (radiosity's B / pi,
  // B = E + rho H, E = pi Le). Called from the tracer's worker threads at once: must be const
  // and thread-safe.
  virtual Rgb diffuse_radiance(int mesh, int triangle, glm::vec2 barycentrics) const = 0;
};

}  // namespace luz::rt
