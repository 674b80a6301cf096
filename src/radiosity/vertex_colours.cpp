#include "radiosity/vertex_colours.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include <glm/common.hpp>

#include "radiosity/shooting.h"

namespace luz {

RadianceField RadianceField::from(const PatchMesh& mesh, const std::vector<Rgb>& exitance,
                                  const Rgb& ambient) {
  RadianceField field;
  field.patch.resize(mesh.size());
  const float inv_pi = 1.0f / std::numbers::pi_v<float>;
  for (size_t i = 0; i < mesh.size(); ++i)
    field.patch[i] = (exitance[i] + mesh.patches[i].rho * ambient) * inv_pi;  // L = B / pi

  // Each display point's value from the elements around it (vertex_fit.h); a fit may overshoot
  // below zero at a sharp shadow's edge, and no radiance is negative.
  assert(mesh.display.fits(mesh.size()) && "the display surfaces are found again after elements are cut");
  const VertexFit& fit = mesh.vertex_fit;
  assert(fit.start.size() == size_t(mesh.display.points) + 1 && "and the fit with them");
  std::vector<Rgb> value(mesh.display.points, Rgb(0.0f));
  for (size_t point = 0; point < value.size(); ++point) {
    for (uint32_t k = fit.start[point]; k < fit.start[point + 1]; ++k)
      value[point] += fit.weight[k] * field.patch[fit.element[k]];
    value[point] = glm::max(value[point], Rgb(0.0f));
  }
  field.corner.resize(mesh.display.corner.size());
  for (size_t c = 0; c < field.corner.size(); ++c) field.corner[c] = value[mesh.display.corner[c]];
  return field;
}

RadianceField RadianceField::of(const ProgressiveSolver& solver) {
  return from(solver.mesh(), solver.displayed(),
              solver.options().ambient_estimate ? solver.ambient() : Rgb(0.0f));
}

RadianceField RadianceField::unshot_heat_map(const ProgressiveSolver& solver) {
  const PatchMesh& mesh = solver.mesh();
  std::vector<float> power(mesh.size());
  float largest = 0.0f;
  for (size_t i = 0; i < mesh.size(); ++i) {
    const Rgb& u = solver.unshot()[i];
    power[i] = (u.r + u.g + u.b) / 3.0f * mesh.patches[i].area;
    largest = std::max(largest, power[i]);
  }
  std::vector<Rgb> colours(mesh.size(), Rgb(0.0f));
  for (size_t i = 0; i < mesh.size(); ++i) {
    if (!(largest > 0.0f) || !(power[i] > 0.0f)) continue;
    const float t = std::clamp(1.0f + std::log10(power[i] / largest) / 3.0f, 0.0f, 1.0f);
    colours[i] = t < 0.5f ? glm::mix(Rgb(0.0f, 0.0f, 0.3f), Rgb(0.9f, 0.0f, 0.0f), 2.0f * t)
                          : glm::mix(Rgb(0.9f, 0.0f, 0.0f), Rgb(1.0f, 1.0f, 0.0f), 2.0f * t - 1.0f);
    colours[i] *= std::numbers::pi_v<float>;  // from() divides by pi: show the ramp as is
  }
  return from(mesh, colours);
}

Rgb RadianceField::at(const PatchMesh& mesh, int scene_mesh, int triangle, glm::vec2 b) const {
  const PatchMesh::Location where = mesh.locate(scene_mesh, triangle, b);
  const size_t c = 3 * where.patch;
  return where.weights.x * corner[c] + where.weights.y * corner[c + 1] + where.weights.z * corner[c + 2];
}

}  // namespace luz
