#include "radiosity/element_form_factor.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "radiosity/polygon_form_factor.h"

namespace luz {

double element_to_patch_form_factor(const PatchMesh& mesh, const Patch& element,
                                    const ShootingPatch& shooter) {
  const glm::vec3 corners[3] = {mesh.vertices[element.vertices[0]],
                                mesh.vertices[element.vertices[1]],
                                mesh.vertices[element.vertices[2]]};
  float radius = 0.0f, element_radius = 0.0f;
  for (int k = 0; k < 3; ++k) {
    radius = std::max(radius, glm::length(shooter.corners[k] - shooter.centre));
    element_radius = std::max(element_radius, glm::length(corners[k] - element.centre));
  }
  const float distance = glm::length(element.centre - shooter.centre);
  if (distance > kNearRadii * radius)  // far: the element's centroid stands for it
    return point_to_polygon_form_factor_single(element.centre, element.normal, shooter.corners);
  // near: 12 points, 48 next to the patch (a row then sums to 1 within 0.1% in a box)
  return triangle_to_polygon_form_factor(corners[0], corners[1], corners[2], element.normal,
                                         shooter.corners,
                                         distance < 2.0f * (radius + element_radius) ? 2 : 1);
}

}  // namespace luz
