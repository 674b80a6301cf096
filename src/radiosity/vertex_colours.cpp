#include "radiosity/vertex_colours.h"

#include <algorithm>
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

  // Nodal averaging, area-weighted.
  std::vector<Rgb> sum(mesh.vertices.size(), Rgb(0.0f));
  std::vector<float> weight(mesh.vertices.size(), 0.0f);
  for (size_t i = 0; i < mesh.size(); ++i)
    for (const uint32_t v : mesh.patches[i].vertices) {
      sum[v] += mesh.patches[i].area * field.patch[i];
      weight[v] += mesh.patches[i].area;
    }
  field.vertex.resize(mesh.vertices.size());
  for (size_t v = 0; v < sum.size(); ++v)
    field.vertex[v] = weight[v] > 0.0f ? sum[v] / weight[v] : Rgb(0.0f);
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
  const Patch& p = mesh.patches[where.patch];
  return where.weights.x * vertex[p.vertices[0]] + where.weights.y * vertex[p.vertices[1]] +
         where.weights.z * vertex[p.vertices[2]];
}

}  // namespace luz
