#include "radiosity/element_form_factor.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "radiosity/polygon_form_factor.h"

namespace luz {

bool near_the_patch(const Patch& element, const ShootingPatch& shooter) {
  return glm::length(element.centre - shooter.centre) <= kNearRadii * shooter.radius;
}

double element_to_patch_form_factor(const PatchMesh& mesh, const Patch& element,
                                    const ShootingPatch& shooter) {
  if (!near_the_patch(element, shooter))  // far: the element's centroid stands for it
    return point_to_polygon_form_factor_single(element.centre, element.normal, shooter.corners);
  const glm::vec3 corners[3] = {mesh.vertices[element.vertices[0]],
                                mesh.vertices[element.vertices[1]],
                                mesh.vertices[element.vertices[2]]};
  float element_radius = 0.0f;
  for (const glm::vec3& corner : corners)
    element_radius = std::max(element_radius, glm::length(corner - element.centre));
  const float distance = glm::length(element.centre - shooter.centre);
  // near: 12 points, 48 next to the patch (a row then sums to 1 within 0.1% in a box)
  return triangle_to_polygon_form_factor(corners[0], corners[1], corners[2], element.normal,
                                         shooter.corners,
                                         distance < 2.0f * (shooter.radius + element_radius) ? 2 : 1);
}

}  // namespace luz
