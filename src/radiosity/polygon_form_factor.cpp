// Lambert's contour integral for point-to-polygon form factors. See polygon_form_factor.h.
#include "radiosity/polygon_form_factor.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

namespace luz {
namespace {

// Sutherland-Hodgman against one plane: keeps the part with dot(n, v - x) >= 0.
std::vector<glm::dvec3> clipped_above(const glm::dvec3& x, const glm::dvec3& n,
                                      std::span<const glm::vec3> polygon) {
  std::vector<glm::dvec3> out;
  const size_t count = polygon.size();
  for (size_t k = 0; k < count; ++k) {
    const glm::dvec3 p(polygon[k]), q(polygon[(k + 1) % count]);
    const double hp = glm::dot(n, p - x), hq = glm::dot(n, q - x);
    if (hp >= 0.0) out.push_back(p);
    if ((hp >= 0.0) != (hq >= 0.0)) out.push_back(p + (hp / (hp - hq)) * (q - p));
  }
  return out;
}

}  // namespace

double point_to_polygon_form_factor(const glm::vec3& x, const glm::vec3& n,
                                    std::span<const glm::vec3> polygon) {
  if (polygon.size() < 3) return 0.0;
  const glm::dvec3 xd(x), nd(n);
  // The polygon's front must face x: its vertices run counter-clockwise seen from x.
  const glm::dvec3 face = glm::cross(glm::dvec3(polygon[1]) - glm::dvec3(polygon[0]),
                                     glm::dvec3(polygon[2]) - glm::dvec3(polygon[0]));
  if (glm::dot(face, xd - glm::dvec3(polygon[0])) <= 0.0) return 0.0;
  const std::vector<glm::dvec3> visible = clipped_above(xd, nd, polygon);
  if (visible.size() < 3) return 0.0;
  double sum = 0.0;
  for (size_t k = 0; k < visible.size(); ++k) {
    const glm::dvec3 r0 = visible[k] - xd, r1 = visible[(k + 1) % visible.size()] - xd;
    const glm::dvec3 cross = glm::cross(r0, r1);
    const double length = glm::length(cross);
    if (length <= 0.0) continue;  // an edge through x's line of sight adds nothing
    const double gamma = std::atan2(length, glm::dot(r0, r1));
    sum += gamma * glm::dot(nd, cross / length);
  }
  // Counter-clockwise seen from x makes every cross product point away from x's side: minus.
  return std::max(0.0, -sum / (2.0 * std::numbers::pi));
}

double triangle_to_polygon_form_factor(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                                       const glm::vec3& n, std::span<const glm::vec3> polygon,
                                       int splits) {
  if (splits > 0) {  // four similar triangles of a quarter of the area each
    const glm::vec3 ab = 0.5f * (a + b), bc = 0.5f * (b + c), ca = 0.5f * (c + a);
    return 0.25 * (triangle_to_polygon_form_factor(a, ab, ca, n, polygon, splits - 1) +
                   triangle_to_polygon_form_factor(ab, b, bc, n, polygon, splits - 1) +
                   triangle_to_polygon_form_factor(ca, bc, c, n, polygon, splits - 1) +
                   triangle_to_polygon_form_factor(ab, bc, ca, n, polygon, splits - 1));
  }
  const glm::vec3 points[3] = {(4.0f * a + b + c) / 6.0f, (a + 4.0f * b + c) / 6.0f,
                               (a + b + 4.0f * c) / 6.0f};
  double sum = 0.0;
  for (const glm::vec3& p : points) sum += point_to_polygon_form_factor(p, n, polygon);
  return sum / 3.0;
}

}  // namespace luz
