// Lambert's contour integral for point-to-polygon form factors. See polygon_form_factor.h.
#include "radiosity/polygon_form_factor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

namespace luz {
namespace {

// The clipped polygon, on the stack up to kSmall corners: the solver evaluates the contour
// integral millions of times a second on triangles, and a heap allocation each time cost more
// than the sum. Larger polygons (a disc in a test) go to the heap.
template <typename T>
class Polygon {
public:
  using V = glm::vec<3, T>;
  void push(const V& v) {
    if (large_.empty() && size_ < kSmall) {
      small_[size_++] = v;
      return;
    }
    if (large_.empty()) large_.assign(small_.begin(), small_.begin() + long(size_));
    large_.push_back(v);
    ++size_;
  }
  size_t size() const { return size_; }
  const V& operator[](size_t k) const { return large_.empty() ? small_[k] : large_[k]; }

private:
  static constexpr size_t kSmall = 8;
  std::array<V, kSmall> small_;
  std::vector<V> large_;
  size_t size_ = 0;
};

// Sutherland-Hodgman against one plane: keeps the part with dot(n, v - x) >= 0.
template <typename T>
Polygon<T> clipped_above(const glm::vec<3, T>& x, const glm::vec<3, T>& n,
                         std::span<const glm::vec3> polygon) {
  Polygon<T> out;
  const size_t count = polygon.size();
  for (size_t k = 0; k < count; ++k) {
    const glm::vec<3, T> p(polygon[k]), q(polygon[(k + 1) % count]);
    const T hp = glm::dot(n, p - x), hq = glm::dot(n, q - x);
    if (hp >= T(0)) out.push(p);
    if ((hp >= T(0)) != (hq >= T(0))) out.push(p + (hp / (hp - hq)) * (q - p));
  }
  return out;
}

template <typename T>
double contour_integral(const glm::vec3& x, const glm::vec3& n, std::span<const glm::vec3> polygon) {
  using V = glm::vec<3, T>;
  if (polygon.size() < 3) return 0.0;
  const V xd(x), nd(n);
  // The polygon's front must face x: its vertices run counter-clockwise seen from x.
  const V face = glm::cross(V(polygon[1]) - V(polygon[0]), V(polygon[2]) - V(polygon[0]));
  if (glm::dot(face, xd - V(polygon[0])) <= T(0)) return 0.0;
  const Polygon<T> visible = clipped_above(xd, nd, polygon);
  if (visible.size() < 3) return 0.0;
  T sum = 0;
  for (size_t k = 0; k < visible.size(); ++k) {
    const V r0 = visible[k] - xd, r1 = visible[(k + 1) % visible.size()] - xd;
    const V cross = glm::cross(r0, r1);
    const T length = glm::length(cross);
    if (length <= T(0)) continue;  // an edge through x's line of sight adds nothing
    const T gamma = std::atan2(length, glm::dot(r0, r1));
    sum += gamma * glm::dot(nd, cross / length);
  }
  // Counter-clockwise seen from x makes every cross product point away from x's side: minus.
  return std::max(0.0, -double(sum) / (2.0 * std::numbers::pi));
}

}  // namespace

double point_to_polygon_form_factor(const glm::vec3& x, const glm::vec3& n,
                                    std::span<const glm::vec3> polygon) {
  return contour_integral<double>(x, n, polygon);
}

double point_to_polygon_form_factor_single(const glm::vec3& x, const glm::vec3& n,
                                        std::span<const glm::vec3> polygon) {
  return contour_integral<float>(x, n, polygon);
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
  for (const glm::vec3& p : points) sum += point_to_polygon_form_factor_single(p, n, polygon);
  return sum / 3.0;
}

}  // namespace luz
