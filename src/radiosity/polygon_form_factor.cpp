// Lambert's contour integral for point-to-polygon form factors. See polygon_form_factor.h.
#include "radiosity/polygon_form_factor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include <glm/geometric.hpp>

namespace luz {
namespace {

// Sutherland-Hodgman against one plane: the part with dot(n, v - x) >= 0, into `out` (room for
// two corners per edge: each edge gives its start, the crossing, both or neither). Returns the
// corners written.
template <typename T>
std::span<const glm::vec<3, T>> clip_above(const glm::vec<3, T>& x, const glm::vec<3, T>& n,
                                           std::span<const glm::vec3> polygon, std::span<glm::vec<3, T>> out) {
  size_t written = 0;
  const size_t count = polygon.size();
  for (size_t k = 0; k < count; ++k) {
    const glm::vec<3, T> p(polygon[k]), q(polygon[(k + 1) % count]);
    const T hp = glm::dot(n, p - x), hq = glm::dot(n, q - x);
    if (hp >= T(0)) out[written++] = p;
    if ((hp >= T(0)) != (hq >= T(0))) out[written++] = p + (hp / (hp - hq)) * (q - p);
  }
  return out.first(written);
}

// The angle atan2(y, x) for y >= 0, in [0, pi]. In double, the library's; in float, which the
// solver calls millions of times a second, an odd polynomial for atan on [0, 1] (degree 15, its
// coefficients fitted for the least maximum error: 4e-8 rad, 1.3e-7 evaluated in float, a float
// angle's rounding) after folding the argument into [0, 1]. It takes 12% off a solve's time.
inline double angle(double y, double x) { return std::atan2(y, x); }
inline float angle(float y, float x) {
  const float ax = std::abs(x);
  const bool steep = y > ax;
  const float t = steep ? ax / y : (ax > 0.0f ? y / ax : 0.0f);
  const float t2 = t * t;
  float a = -0.00405455987f;
  for (const float c : {0.0218629347f, -0.0559122998f, 0.0964219601f, -0.139086294f, 0.199465657f,
                        -0.333298608f, 0.999999336f})
    a = a * t2 + c;
  a *= t;
  constexpr float half_pi = std::numbers::pi_v<float> / 2.0f;
  if (steep) a = half_pi - a;
  return x < 0.0f ? std::numbers::pi_v<float> - a : a;
}

template <typename T>
double contour_integral(const glm::vec3& x, const glm::vec3& n, std::span<const glm::vec3> polygon) {
  using V = glm::vec<3, T>;
  if (polygon.size() < 3) return 0.0;
  const V xd(x), nd(n);
  // The polygon's front must face x: its vertices run counter-clockwise seen from x.
  const V face = glm::cross(V(polygon[1]) - V(polygon[0]), V(polygon[2]) - V(polygon[0]));
  if (glm::dot(face, xd - V(polygon[0])) <= T(0)) return 0.0;
  // The clipped polygon on the stack for the solver's triangles: the solver evaluates the
  // integral millions of times a second, on the page's main thread too, where the first use of a
  // thread-local buffer on a thread could wait for another (core/parallel_for.h, MainThread).
  constexpr size_t kCornersOnStack = 8;
  std::array<V, 2 * kCornersOnStack> on_stack;
  std::vector<V> on_heap(polygon.size() > kCornersOnStack ? 2 * polygon.size() : 0);
  const std::span<const V> visible =
      clip_above(xd, nd, polygon, on_heap.empty() ? std::span<V>(on_stack) : std::span<V>(on_heap));
  if (visible.size() < 3) return 0.0;
  T sum = 0;
  for (size_t k = 0; k < visible.size(); ++k) {
    const V r0 = visible[k] - xd, r1 = visible[(k + 1) % visible.size()] - xd;
    const V cross = glm::cross(r0, r1);
    const T length = glm::length(cross);
    if (length <= T(0)) continue;  // an edge through x's line of sight adds nothing
    const T gamma = angle(length, glm::dot(r0, r1));
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
