#include "radiosity/vertex_fit.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

#include "radiosity/patch_mesh.h"

namespace luz {
namespace {

// Centroids spread along a line within this ratio of the spread across it (the smaller
// eigenvalue of their scatter over the larger, roughly) fix no plane worth extrapolating along.
constexpr double kFlatness = 1e-3;

// The elements at each display point, each once (a sliver's coincident corners are one point).
struct ElementsAt {
  std::vector<uint32_t> start, element;
  std::vector<glm::vec3> position;  // of each display point

  explicit ElementsAt(const PatchMesh& mesh) {
    const DisplaySurfaces& display = mesh.display;
    start.assign(size_t(display.points) + 1, 0);
    position.assign(display.points, glm::vec3(0.0f));
    for (size_t c = 0; c < display.corner.size(); ++c) {
      ++start[display.corner[c] + 1];
      position[display.corner[c]] = mesh.vertices[mesh.patches[c / 3].vertices[c % 3]];
    }
    for (size_t p = 1; p < start.size(); ++p) start[p] += start[p - 1];
    element.assign(start.back(), UINT32_MAX);
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t c = 0; c < display.corner.size(); ++c) {
      const uint32_t point = display.corner[c], e = uint32_t(c / 3);
      if (fill[point] > start[point] && element[fill[point] - 1] == e) continue;
      element[fill[point]++] = e;
    }
    // Close the gaps the repeated corners left.
    size_t out = 0;
    for (size_t p = 0; p + 1 < start.size(); ++p) {
      const size_t begin = start[p];
      start[p] = uint32_t(out);
      for (size_t k = begin; k < fill[p]; ++k) element[out++] = element[k];
    }
    start.back() = uint32_t(out);
    element.resize(out);
  }
};

// Weighted least squares of value = m + g . u over the elements' centroids u (relative to their
// area-weighted mean, in the tangent plane of their mean normal), evaluated at `point`: the value
// there is sum_k a_k (1/W + u_k . S^-1 r) B_k, with W the total area, S the area-weighted scatter
// of the u_k and r the point relative to the mean. False when the centroids fix no plane.
bool fit_weights(const PatchMesh& mesh, const glm::vec3& point, const std::vector<uint32_t>& elements,
                 std::vector<float>& weights) {
  double total = 0.0;
  glm::dvec3 normal(0.0), mean(0.0);
  for (const uint32_t e : elements) {
    const Patch& p = mesh.patches[e];
    total += double(p.area);
    normal += double(p.area) * glm::dvec3(p.normal);
    mean += double(p.area) * glm::dvec3(p.centre);
  }
  if (!(total > 0.0) || !(glm::length(normal) > 0.0)) return false;
  normal = glm::normalize(normal);
  mean /= total;
  // Any two unit vectors across the normal.
  const glm::dvec3 helper = std::abs(normal.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 t = glm::normalize(glm::cross(normal, helper)), b = glm::cross(normal, t);
  const auto in_plane = [&](const glm::vec3& q) {
    const glm::dvec3 d = glm::dvec3(q) - mean;
    return glm::dvec2(glm::dot(d, t), glm::dot(d, b));
  };
  double suu = 0.0, suv = 0.0, svv = 0.0;
  for (const uint32_t e : elements) {
    const Patch& p = mesh.patches[e];
    const glm::dvec2 u = in_plane(p.centre);
    suu += double(p.area) * u.x * u.x;
    suv += double(p.area) * u.x * u.y;
    svv += double(p.area) * u.y * u.y;
  }
  const double det = suu * svv - suv * suv, trace = suu + svv;
  if (!(trace > 0.0) || !(det > kFlatness * trace * trace)) return false;
  // S^-1 r, with S = [[suu, suv], [suv, svv]].
  const glm::dvec2 r = in_plane(point);
  const glm::dvec2 s(( svv * r.x - suv * r.y) / det, (-suv * r.x + suu * r.y) / det);
  weights.clear();
  for (const uint32_t e : elements) {
    const Patch& p = mesh.patches[e];
    weights.push_back(float(double(p.area) * (1.0 / total + glm::dot(in_plane(p.centre), s))));
  }
  return true;
}

// The area-weighted mean (equal weights if every element is a sliver of no area).
void mean_weights(const PatchMesh& mesh, const std::vector<uint32_t>& elements, std::vector<float>& weights) {
  double total = 0.0;
  for (const uint32_t e : elements) total += double(mesh.patches[e].area);
  weights.clear();
  for (const uint32_t e : elements)
    weights.push_back(total > 0.0 ? float(double(mesh.patches[e].area) / total) : 1.0f / float(elements.size()));
}

}  // namespace

VertexFit VertexFit::of(const PatchMesh& mesh) {
  assert(mesh.display.fits(mesh.size()));
  const ElementsAt at(mesh);
  const size_t points = at.position.size();
  VertexFit fit;
  fit.start.reserve(points + 1);
  fit.start.push_back(0);
  fit.element.reserve(at.element.size());
  fit.weight.reserve(at.element.size());
  std::vector<uint32_t> ring, wider;
  std::vector<float> weights;
  for (size_t point = 0; point < points; ++point) {
    ring.assign(at.element.begin() + at.start[point], at.element.begin() + at.start[point + 1]);
    const std::vector<uint32_t>* used = &ring;
    if (!fit_weights(mesh, at.position[point], ring, weights)) {
      // The elements around those elements, on the same surface: those at their corners' points.
      wider.clear();
      for (const uint32_t e : ring)
        for (size_t k = 0; k < 3; ++k) {
          const uint32_t q = mesh.display.corner[3 * size_t(e) + k];
          wider.insert(wider.end(), at.element.begin() + at.start[q], at.element.begin() + at.start[q + 1]);
        }
      std::sort(wider.begin(), wider.end());
      wider.erase(std::unique(wider.begin(), wider.end()), wider.end());
      if (fit_weights(mesh, at.position[point], wider, weights)) used = &wider;
      else mean_weights(mesh, ring, weights);
    }
    fit.element.insert(fit.element.end(), used->begin(), used->end());
    fit.weight.insert(fit.weight.end(), weights.begin(), weights.end());
    fit.start.push_back(uint32_t(fit.element.size()));
  }
  return fit;
}

}  // namespace luz
