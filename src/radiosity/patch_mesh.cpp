// Meshing for radiosity: uniform n x n subdivision of every triangle, n per source mesh.
//
// Sections: [reflectance and emission] [subdivision counts] [one triangle's grid] [build]
//           [locate]
#include "radiosity/patch_mesh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace luz {
namespace {

// ---- [reflectance and emission] ----------------------------------------------------------------
// rho = kd; a kd texture modulates it by its mean texel (a patch has one reflectance).
Rgb reflectance_of(const Scene& scene, const Material& material) {
  Rgb rho = material.kd;
  if (material.kd_texture >= 0 && size_t(material.kd_texture) < scene.textures.size()) {
    const Texture& texture = scene.textures[size_t(material.kd_texture)];
    Rgb mean(0.0f);
    for (const Rgb& texel : texture.texels) mean += texel;
    rho *= mean / float(std::max<size_t>(1, texture.texels.size()));
  }
  return rho;
}

const Material& material_of(const Scene& scene, const Mesh& mesh) {
  static const Material fallback;
  return mesh.material >= 0 && size_t(mesh.material) < scene.materials.size()
             ? scene.materials[size_t(mesh.material)]
             : fallback;
}

// ---- [subdivision counts] ----------------------------------------------------------------------
float longest_edge(const Mesh& mesh) {
  float longest = 0.0f;
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int e = 0; e < 3; ++e) {
      const glm::vec3& a = mesh.positions[mesh.indices[3 * t + size_t(e)]];
      const glm::vec3& b = mesh.positions[mesh.indices[3 * t + size_t((e + 1) % 3)]];
      longest = std::max(longest, glm::length(b - a));
    }
  return longest;
}

// One n for the whole mesh, so shared edges get the same points (no T-junctions).
int subdivisions_for(float longest, float max_edge) {
  if (!(max_edge > 0.0f)) return 1;
  const float n = std::ceil(longest / max_edge - 1e-4f);
  return int(std::clamp(n, 1.0f, 4096.0f));
}

// ---- [one triangle's grid] ---------------------------------------------------------------------
// Grid point (i, j) of triangle (A, B, C) is A + (i/n)(B - A) + (j/n)(C - A), i + j <= n.
// Points on the triangle's edges and corners are keyed by the source vertices of that edge, so
// the neighbouring triangle finds the same vertex; interior points belong to one triangle only.
class VertexTable {
public:
  VertexTable(const Mesh& mesh, std::vector<glm::vec3>& vertices, int n)
      : mesh_(mesh), vertices_(vertices), n_(n) {}

  uint32_t grid_point(uint32_t a, uint32_t b, uint32_t c, int i, int j) {
    if (j == 0) return on_edge(a, b, i);          // edge AB (corners A and B included)
    if (i == 0) return on_edge(a, c, j);          // edge AC (corner C included)
    if (i + j == n_) return on_edge(b, c, j);     // edge BC
    const glm::vec3 &A = mesh_.positions[a], &B = mesh_.positions[b], &C = mesh_.positions[c];
    const float n = float(n_);
    vertices_.push_back(A + (float(i) / n) * (B - A) + (float(j) / n) * (C - A));
    return uint32_t(vertices_.size() - 1);
  }

private:
  // The point k/n of the way from source vertex `from` to `to`, computed from the lower index
  // so both triangles sharing the edge get the same bits.
  uint32_t on_edge(uint32_t from, uint32_t to, int k) {
    if (k == 0) to = from;            // a corner: the source vertex itself
    if (k == n_) from = to, k = 0;
    if (from > to) {
      std::swap(from, to);
      k = n_ - k;
    }
    assert(from < (1u << 24) && to < (1u << 24) && k < (1 << 16));
    const uint64_t key = (uint64_t(from) << 40) | (uint64_t(to) << 16) | uint64_t(k);
    const auto found = keys_.find(key);
    if (found != keys_.end()) return found->second;
    const glm::vec3 &P = mesh_.positions[from], &Q = mesh_.positions[to];
    vertices_.push_back(from == to ? P : P + (float(k) / float(n_)) * (Q - P));
    const uint32_t index = uint32_t(vertices_.size() - 1);
    keys_.emplace(key, index);
    return index;
  }

  const Mesh& mesh_;
  std::vector<glm::vec3>& vertices_;
  int n_;
  std::unordered_map<uint64_t, uint32_t> keys_;
};

Patch make_patch(const std::vector<glm::vec3>& vertices, uint32_t v0, uint32_t v1, uint32_t v2) {
  Patch p;
  p.vertices[0] = v0;
  p.vertices[1] = v1;
  p.vertices[2] = v2;
  const glm::vec3 &a = vertices[v0], &b = vertices[v1], &c = vertices[v2];
  const glm::vec3 cross = glm::cross(b - a, c - a);
  const float twice_area = glm::length(cross);
  p.area = 0.5f * twice_area;
  p.normal = twice_area > 0.0f ? cross / twice_area : glm::vec3(0, 1, 0);
  p.centre = (a + b + c) / 3.0f;
  // The centroid is a third of each height from the opposite edge: height = 2 A / edge.
  float clearance = 1e30f;
  for (const float edge : {glm::length(b - a), glm::length(c - b), glm::length(a - c)})
    clearance = std::min(clearance, twice_area / std::max(edge, 1e-30f) / 3.0f);
  p.clearance = clearance;
  return p;
}

}  // namespace

// ---- [build] -----------------------------------------------------------------------------------
// Patches of one triangle in row order j = 0 .. n-1: "up" triangle (i, j), (i+1, j), (i, j+1)
// then, except at the row's end, "down" triangle (i+1, j), (i+1, j+1), (i, j+1). Both keep the
// source triangle's winding. locate() relies on this order.
PatchMesh PatchMesh::build(const Scene& scene, float max_edge) {
  PatchMesh result;
  result.max_edge = max_edge;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    const Material& material = material_of(scene, mesh);
    const Rgb rho = reflectance_of(scene, material);
    const Rgb exitance = std::numbers::pi_v<float> * material.emission;  // E = pi * Le
    const int n = subdivisions_for(longest_edge(mesh), max_edge);
    result.sources_.push_back({n, result.patches.size()});

    VertexTable table(mesh, result.vertices, n);
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      const uint32_t a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1],
                     c = mesh.indices[3 * t + 2];
      // Grid points of this triangle, row by row (row j has n + 1 - j points).
      std::vector<std::vector<uint32_t>> grid(size_t(n) + 1);
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i + j <= n; ++i) grid[size_t(j)].push_back(table.grid_point(a, b, c, i, j));
      const auto at = [&grid](int i, int j) { return grid[size_t(j)][size_t(i)]; };
      for (int j = 0; j < n; ++j)
        for (int i = 0; i + j < n; ++i) {
          for (int half = 0; half < 2; ++half) {
            if (half == 1 && i + j > n - 2) break;
            Patch p = half == 0 ? make_patch(result.vertices, at(i, j), at(i + 1, j), at(i, j + 1))
                                : make_patch(result.vertices, at(i + 1, j), at(i + 1, j + 1),
                                             at(i, j + 1));
            p.mesh = int(m);
            p.triangle = int(t);
            // COLOR_0 at the patch's centroid: (i + 1/3, j + 1/3) / n up, + 2/3 down.
            const float third = half == 0 ? 1.0f / 3.0f : 2.0f / 3.0f;
            p.rho = rho * mesh.colour_at(t, glm::vec2(float(i) + third, float(j) + third) / float(n));
            p.emission = exitance;
            result.patches.push_back(p);
          }
        }
    }
  }
  return result;
}

PatchMesh PatchMesh::build(const Scene& scene, const RadiosityOptions& options) {
  return build(scene, options.patch_size > 0.0f
                          ? options.patch_size
                          : patch_size_for(scene, size_t(std::max(1, options.target_patches))));
}

float PatchMesh::patch_size_for(const Scene& scene, size_t target) {
  std::vector<std::pair<float, size_t>> meshes;  // longest edge, triangles
  float longest = 0.0f;
  for (const Mesh& mesh : scene.meshes) {
    meshes.emplace_back(longest_edge(mesh), mesh.triangle_count());
    longest = std::max(longest, meshes.back().first);
  }
  const auto count = [&meshes](float size) {
    size_t total = 0;
    for (const auto& [edge, triangles] : meshes) {
      const size_t n = size_t(subdivisions_for(edge, size));
      total += triangles * n * n;
    }
    return total;
  };
  // count() falls as the size grows: bisect on a log scale for the size closest to the target.
  float lo = longest * 1e-4f, hi = longest * 1.0001f;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const float mid = std::sqrt(lo * hi);
    (count(mid) > target ? lo : hi) = mid;
  }
  const auto miss = [&](float size) {
    return std::abs(double(count(size)) - double(target));
  };
  return miss(lo) < miss(hi) ? lo : hi;
}

float PatchMesh::total_area() const {
  float total = 0.0f;
  for (const Patch& p : patches) total += p.area;
  return total;
}

// ---- [locate] ----------------------------------------------------------------------------------
PatchMesh::Location PatchMesh::locate(int mesh, int triangle, glm::vec2 b) const {
  const Source& source = sources_[size_t(mesh)];
  const int n = source.n;
  const float u = std::clamp(b.x, 0.0f, 1.0f) * float(n), v = std::clamp(b.y, 0.0f, 1.0f) * float(n);
  int j = std::clamp(int(v), 0, n - 1);
  int i = std::clamp(int(u), 0, n - 1 - j);
  const float fu = u - float(i), fv = v - float(j);
  // Row j starts after rows 0 .. j-1, which hold 2 (n - k) - 1 patches each: 2 n j - j^2.
  const size_t row_start = size_t(2 * n * j - j * j);
  const bool down = fu + fv > 1.0f && i + j <= n - 2;
  Location location;
  location.patch = source.first_patch + size_t(triangle) * size_t(n) * size_t(n) + row_start +
                   size_t(2 * i + (down ? 1 : 0));
  if (!down)  // corners (i, j), (i+1, j), (i, j+1)
    location.weights = glm::vec3(1.0f - fu - fv, fu, fv);
  else        // corners (i+1, j), (i+1, j+1), (i, j+1)
    location.weights = glm::vec3(1.0f - fv, fu + fv - 1.0f, 1.0f - fu);
  location.weights = glm::max(location.weights, glm::vec3(0.0f));
  return location;
}

}  // namespace luz
