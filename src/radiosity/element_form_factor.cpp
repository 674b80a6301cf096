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
  // How far the element is from the patch, at least: the integrand changes on that scale (as
  // log(distance) at an edge the two share), the element's size sets how much of it one point
  // misses. Three points (exact for a quadratic) where the gap is over three element radii,
  // 12 within that, 48 within one (next to the patch: a row then sums to 1 within 0.1% in a box).
  const float gap = glm::length(element.centre - shooter.centre) - shooter.radius;
  const int splits = gap < element_radius ? 2 : gap < 3.0f * element_radius ? 1 : 0;
  return triangle_to_polygon_form_factor(corners[0], corners[1], corners[2], element.normal,
                                         shooter.corners, splits);
}

}  // namespace luz
