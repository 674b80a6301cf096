#include "radiosity/vertex_colours.h"

#include <numbers>

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

Rgb RadianceField::at(const PatchMesh& mesh, int scene_mesh, int triangle, glm::vec2 b) const {
  const PatchMesh::Location where = mesh.locate(scene_mesh, triangle, b);
  const Patch& p = mesh.patches[where.patch];
  return where.weights.x * vertex[p.vertices[0]] + where.weights.y * vertex[p.vertices[1]] +
         where.weights.z * vertex[p.vertices[2]];
}

}  // namespace luz
