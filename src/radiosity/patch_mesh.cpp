// Meshing for radiosity: uniform n x n subdivision of every triangle, n per source mesh, into
// shooting patches and their elements (substructuring).
//
// Sections: [reflectance and emission] [subdivision counts] [one triangle's grid] [build]
//           [locate]
// Patches (which shoot) and the elements they hold (which receive) are built together.
#include "radiosity/patch_mesh.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/i18n.h"
#include "radiosity/texture_detail.h"

namespace luz {
namespace {

// ---- [reflectance and emission] ----------------------------------------------------------------
const Material& material_of(const Scene& scene, const Mesh& mesh) {
  static const Material fallback;
  return mesh.material >= 0 && size_t(mesh.material) < scene.materials.size()
             ? scene.materials[size_t(mesh.material)]
             : fallback;
}

// ---- [subdivision counts] ----------------------------------------------------------------------
// Throws for an edge that is not a finite length (a vertex near the float limit, a NaN): no
// subdivision count can be made from it.
float longest_edge(const Mesh& mesh) {
  float longest = 0.0f;
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int e = 0; e < 3; ++e) {
      const glm::vec3& a = mesh.positions[mesh.indices[3 * t + size_t(e)]];
      const glm::vec3& b = mesh.positions[mesh.indices[3 * t + size_t((e + 1) % 3)]];
      const float length = glm::length(b - a);
      if (!std::isfinite(length))
        throw Error(ErrorKind::not_finite,
                    i18n::trf("radiosity: mesh \"{}\", triangle {}: an edge from ({:g}, {:g}, "
                              "{:g}) to ({:g}, {:g}, {:g}) has no finite length", mesh.name, t,
                              a.x, a.y, a.z, b.x, b.y, b.z));
      longest = std::max(longest, length);
    }
  // Areas are squares of lengths: a triangle 1e20 m across has no float area.
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const glm::vec3& a = mesh.positions[mesh.indices[3 * t]];
    const glm::vec3 cross = glm::cross(mesh.positions[mesh.indices[3 * t + 1]] - a,
                                       mesh.positions[mesh.indices[3 * t + 2]] - a);
    if (!std::isfinite(glm::length(cross)))
      throw Error(ErrorKind::not_finite,
                  i18n::trf("radiosity: mesh \"{}\", triangle {}: its area overflows a float "
                            "(edges up to {:g} m); radiosity needs finite areas", mesh.name, t,
                            longest));
  }
  return longest;
}

// One n for the whole mesh, so shared edges get the same points (no T-junctions). In double,
// unclamped, so that a count can be checked against the budget before anything is built.
double subdivisions_for(float longest, float max_edge) {
  if (!(max_edge > 0.0f) || !std::isfinite(max_edge)) return 1.0;
  return std::max(1.0, std::ceil(double(longest) / double(max_edge) - 1e-4));
}

// Elements per patch edge for a mesh cut into n patches per edge: up to k, but no more than
// make the elements shorter than max_edge / k. A mesh whose triangles are already that small
// (a finely tessellated sphere) is not cut further: its elements are its patches.
int elements_per_patch_edge(float longest, float max_edge, int k, double patches_per_edge) {
  if (!(max_edge > 0.0f) || !std::isfinite(max_edge)) return k;
  const double needed = std::ceil(double(longest) * double(k) / (patches_per_edge * double(max_edge)) - 1e-4);
  return int(std::clamp(needed, 1.0, double(k)));
}

// The cell of the n x n grid of a triangle holding the point at barycentrics (b1, b2) of its
// second and third corner. Cells are in row order j = 0 .. n-1: "up" (i, j), (i+1, j), (i, j+1),
// then, except at the row's end, "down" (i+1, j), (i+1, j+1), (i, j+1).
struct GridCell {
  int i = 0, j = 0;
  bool down = false;
  glm::vec3 weights{1.0f, 0.0f, 0.0f};  // of the point in the cell's three corners
  // Index among the triangle's cells: row j starts after rows 0 .. j-1, which hold
  // 2 (n - k) - 1 cells each, 2 n j - j^2 in all.
  size_t index(int n) const { return size_t(2 * n * j - j * j) + size_t(2 * i + (down ? 1 : 0)); }
  // The cell's corners in the grid's (i, j) units, counter-clockwise as the source triangle.
  void corners(glm::ivec2 out[3]) const {
    if (!down) {
      out[0] = {i, j}, out[1] = {i + 1, j}, out[2] = {i, j + 1};
    } else {
      out[0] = {i + 1, j}, out[1] = {i + 1, j + 1}, out[2] = {i, j + 1};
    }
  }
};

GridCell grid_cell(int n, float b1, float b2) {
  const float u = std::clamp(b1, 0.0f, 1.0f) * float(n), v = std::clamp(b2, 0.0f, 1.0f) * float(n);
  GridCell cell;
  cell.j = std::clamp(int(v), 0, n - 1);
  cell.i = std::clamp(int(u), 0, n - 1 - cell.j);
  const float fu = u - float(cell.i), fv = v - float(cell.j);
  cell.down = fu + fv > 1.0f && cell.i + cell.j <= n - 2;
  cell.weights = !cell.down ? glm::vec3(1.0f - fu - fv, fu, fv)             // (i, j), (i+1, j), (i, j+1)
                            : glm::vec3(1.0f - fv, fu + fv - 1.0f, 1.0f - fu);  // down corners
  cell.weights = glm::max(cell.weights, glm::vec3(0.0f));
  return cell;
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

}  // namespace

Patch make_element(const std::vector<glm::vec3>& vertices, uint32_t v0, uint32_t v1, uint32_t v2) {
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

// ---- [build] -----------------------------------------------------------------------------------
// Elements of one triangle in grid_cell()'s order: they keep the source triangle's winding, and
// locate() relies on the order.
double PatchMesh::element_count(const Scene& scene, float max_edge, int elements_per_edge) {
  double total = 0.0;
  for (const Mesh& mesh : scene.meshes) {
    const float longest = longest_edge(mesh);
    const double patches = subdivisions_for(longest, max_edge);
    const double n = patches * elements_per_patch_edge(longest, max_edge, elements_per_edge, patches);
    total += double(mesh.triangle_count()) * n * n;
  }
  return total;
}

PatchMesh PatchMesh::build(const Scene& scene, float max_edge, int elements_per_edge, bool textures) {
  const int k = elements_per_edge;
  if (k < 1 || k > kMaxElementsPerEdge)
    throw Error(ErrorKind::bad_value, i18n::trf("radiosity: {} elements per patch edge, expected "
                                                "1 .. {}", k, kMaxElementsPerEdge));
  const double elements = element_count(scene, max_edge, k);
  if (elements > kMaxElements)
    throw Error(ErrorKind::bad_value,
                i18n::trf("radiosity: patch size {:g} m with {} x {} elements per patch would "
                          "make {:.3g} elements, more than the budget of {:.3g} (about 300 bytes "
                          "each); use a larger patch size or fewer elements per patch",
                          max_edge, k, k, elements, kMaxElements));
  PatchMesh result;
  result.max_edge = max_edge;
  result.elements_per_edge = k;
  result.detail = TextureDetail(scene, textures);
  result.patches.reserve(size_t(elements));
  // rho = kd; a kd texture the mesh shows multiplies it by its mean texel (a patch has one
  // reflectance; the picture puts the texture's detail back, texture_detail.h).
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    const Material& material = material_of(scene, mesh);
    result.mesh_material.push_back(mesh.material);
    const Rgb rho = material.kd * result.detail.mean(int(m));
    const Rgb exitance = std::numbers::pi_v<float> * material.emission;  // E = pi * Le
    // An emissive texture: each element shoots pi times the mean of Le over it (SCENES.md).
    const bool emission_textured = material.is_emissive() && scene.shown_emission_texture(mesh, material) >= 0;
    const float longest = longest_edge(mesh);
    const int patches_per_edge = int(subdivisions_for(longest, max_edge));
    const int k_mesh = elements_per_patch_edge(longest, max_edge, k, double(patches_per_edge));
    const int n = patches_per_edge * k_mesh;  // elements per source edge
    result.sources_.push_back({n, result.patches.size()});
    const size_t first_shooter = result.shooters.size();
    const size_t shooters_per_triangle = size_t(patches_per_edge) * size_t(patches_per_edge);
    result.shooters.resize(first_shooter + mesh.triangle_count() * shooters_per_triangle);

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
            Patch p = half == 0 ? make_element(result.vertices, at(i, j), at(i + 1, j), at(i, j + 1))
                                : make_element(result.vertices, at(i + 1, j), at(i + 1, j + 1),
                                             at(i, j + 1));
            p.mesh = int(m);
            p.triangle = int(t);
            // COLOR_0 at the patch's centroid: (i + 1/3, j + 1/3) / n up, + 2/3 down.
            const float third = half == 0 ? 1.0f / 3.0f : 2.0f / 3.0f;
            p.rho = rho * mesh.colour_at(t, glm::vec2(float(i) + third, float(j) + third) / float(n));
            p.emission = exitance;
            if (emission_textured) {
              const float fn = float(n), fi = float(i), fj = float(j);
              const std::array<glm::vec2, 3> corners =
                  half == 0 ? std::array<glm::vec2, 3>{glm::vec2(fi, fj) / fn, glm::vec2(fi + 1, fj) / fn,
                                                       glm::vec2(fi, fj + 1) / fn}
                            : std::array<glm::vec2, 3>{glm::vec2(fi + 1, fj) / fn, glm::vec2(fi + 1, fj + 1) / fn,
                                                       glm::vec2(fi, fj + 1) / fn};
              p.emission = std::numbers::pi_v<float> * scene.mean_emission(int(m), t, corners);
            }
            // The patch holding this element: the coarse cell of the element's centroid.
            const float cu = (float(i) + (half == 0 ? 1.0f : 2.0f) / 3.0f) / float(n);
            const float cv = (float(j) + (half == 0 ? 1.0f : 2.0f) / 3.0f) / float(n);
            const GridCell cell = grid_cell(patches_per_edge, cu, cv);
            const size_t s = first_shooter + t * shooters_per_triangle + cell.index(patches_per_edge);
            ShootingPatch& shooter = result.shooters[s];
            if (shooter.area == 0.0f) {  // first element seen: the patch's corners
              glm::ivec2 corner[3];
              cell.corners(corner);
              const glm::vec3 &A = mesh.positions[a], &B = mesh.positions[b], &C = mesh.positions[c];
              const float np = float(patches_per_edge);
              for (int q = 0; q < 3; ++q)
                shooter.corners[q] = A + (float(corner[q].x) / np) * (B - A) + (float(corner[q].y) / np) * (C - A);
            }
            shooter.area += p.area;
            shooter.centre += p.area * p.centre;
            shooter.normal = p.normal;
            // Patches and elements are similar triangles, k times larger.
            shooter.clearance = float(k_mesh) * p.clearance;
            result.shooter_of.push_back(uint32_t(s));
            result.patches.push_back(p);
          }
        }
    }
  }
  // Centroids, and the members grouped by shooter (a counting sort keeps each group in order).
  for (ShootingPatch& shooter : result.shooters) {
    if (shooter.area > 0.0f) shooter.centre /= shooter.area;
    for (const glm::vec3& corner : shooter.corners)
      shooter.radius = std::max(shooter.radius, glm::length(corner - shooter.centre));
  }
  result.group_by_shooter();
  result.find_display_surfaces();
  return result;
}

// A counting sort: keeps each group in index order.
void PatchMesh::group_by_shooter() {
  for (ShootingPatch& shooter : shooters) shooter.count = 0;
  for (const uint32_t s : shooter_of) ++shooters[s].count;
  uint32_t first = 0;
  for (ShootingPatch& shooter : shooters) {
    shooter.first = first;
    first += shooter.count;
    shooter.count = 0;
  }
  members.resize(patches.size());
  for (size_t e = 0; e < patches.size(); ++e) {
    ShootingPatch& shooter = shooters[shooter_of[e]];
    members[shooter.first + shooter.count++] = uint32_t(e);
  }
}

PatchMesh PatchMesh::build(const Scene& scene, const RadiosityOptions& options) {
  options.validate();
  return build(scene, options.patch_size > 0.0f
                          ? options.patch_size
                          : patch_size_for(scene, size_t(std::max(1, options.target_patches))),
               options.elements_per_edge, options.textures);
}

float PatchMesh::patch_size_for(const Scene& scene, size_t target) {
  std::vector<std::pair<float, size_t>> meshes;  // longest edge, triangles
  float longest = 0.0f;
  size_t triangles = 0;
  for (const Mesh& mesh : scene.meshes) {
    meshes.emplace_back(longest_edge(mesh), mesh.triangle_count());
    longest = std::max(longest, meshes.back().first);
    triangles += mesh.triangle_count();
  }
  const auto count = [&meshes](float size) {
    double total = 0.0;
    for (const auto& [edge, mesh_triangles] : meshes) {
      const double n = subdivisions_for(edge, size);
      total += double(mesh_triangles) * n * n;
    }
    return total;
  };
  // The scene's own triangles are patches whatever the size; subdivision adds to them.
  const double wanted = double(triangles) + double(target);
  // count() falls as the size grows: bisect on a log scale for the size closest to the target.
  float lo = longest * 1e-4f, hi = longest * 1.0001f;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const float mid = std::sqrt(lo) * std::sqrt(hi);  // lo * hi may overflow
    (count(mid) > wanted ? lo : hi) = mid;
  }
  const auto miss = [&](float size) { return std::abs(count(size) - wanted); };
  return miss(lo) < miss(hi) ? lo : hi;
}

float PatchMesh::total_area() const {
  float total = 0.0f;
  for (const Patch& p : patches) total += p.area;
  return total;
}

// ---- [locate] ----------------------------------------------------------------------------------
namespace {

// The weights of the element's vertices that give `point` (projected into its plane), clamped
// to the element.
glm::vec3 barycentric_weights(const std::vector<glm::vec3>& vertices, const Patch& p,
                              const glm::vec3& point) {
  const glm::vec3 &a = vertices[p.vertices[0]], &b = vertices[p.vertices[1]], &c = vertices[p.vertices[2]];
  const glm::vec3 ab = b - a, ac = c - a, ap = point - a;
  const float d00 = glm::dot(ab, ab), d01 = glm::dot(ab, ac), d11 = glm::dot(ac, ac);
  const float d20 = glm::dot(ap, ab), d21 = glm::dot(ap, ac);
  const float denominator = d00 * d11 - d01 * d01;
  if (!(denominator > 0.0f)) return {1.0f, 0.0f, 0.0f};
  const float v = (d11 * d20 - d01 * d21) / denominator, w = (d00 * d21 - d01 * d20) / denominator;
  glm::vec3 weights = glm::max(glm::vec3(1.0f - v - w, v, w), glm::vec3(0.0f));
  return weights / (weights.x + weights.y + weights.z);
}

}  // namespace

PatchMesh::Location PatchMesh::locate(int mesh, int triangle, glm::vec2 b) const {
  const Source& source = sources_[size_t(mesh)];
  const size_t n = size_t(source.n);
  const GridCell cell = grid_cell(source.n, b.x, b.y);
  Location location;
  location.patch = source.first_patch + size_t(triangle) * n * n + cell.index(source.n);
  location.weights = cell.weights;
  if (location.patch >= refinements.size() || refinements[location.patch].steps.empty())
    return location;
  // Cut since: the point in space, then down the cuts to the element now holding it.
  const Refinement& cut = refinements[location.patch];
  const glm::vec3 point = cell.weights.x * vertices[cut.corners[0]] +
                          cell.weights.y * vertices[cut.corners[1]] +
                          cell.weights.z * vertices[cut.corners[2]];
  size_t e = location.patch, step = 0;
  while (step < refinements[e].steps.size()) {
    const Bisection& cut_here = refinements[e].steps[step];
    // The cut runs from `middle` to `apex`; the second half is on the side of `end`.
    const glm::vec3 &m = vertices[cut_here.middle], &c = vertices[cut_here.apex];
    const glm::vec3 across = glm::cross(c - m, patches[e].normal);
    if (glm::dot(point - m, across) * glm::dot(vertices[cut_here.end] - m, across) > 0.0f) {
      e = cut_here.second;
      step = 0;
    } else {
      ++step;
    }
  }
  location.patch = e;
  location.weights = barycentric_weights(vertices, patches[e], point);
  return location;
}

}  // namespace luz
