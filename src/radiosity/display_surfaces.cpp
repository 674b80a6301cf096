#include "radiosity/display_surfaces.h"

#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "radiosity/patch_mesh.h"

namespace luz {
namespace {

// A mesh vertex's cell on a grid of `step` metres, packed into one key (21 bits per axis, which
// holds a million cells across the scene).
uint64_t cell_of(const glm::vec3& p, const glm::vec3& origin, float step) {
  const auto axis = [&](int k) { return uint64_t(std::llround(double(p[k] - origin[k]) / double(step))) & 0x1fffffu; };
  return axis(0) | axis(1) << 21 | axis(2) << 42;
}

}  // namespace

DisplaySurfaces DisplaySurfaces::of(const PatchMesh& mesh, const std::vector<int>& material_of_mesh) {
  // Coincident vertices: one id per grid cell of a millionth of the scene's size.
  Bounds bounds;
  for (const glm::vec3& v : mesh.vertices) bounds.grow(v);
  const float step = bounds.empty() ? 1.0f : std::max(glm::length(bounds.extent()), 1e-20f) * 1e-6f;
  std::unordered_map<uint64_t, uint32_t> cells;
  cells.reserve(mesh.vertices.size());
  std::vector<uint32_t> point_of(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    point_of[v] = cells.emplace(cell_of(mesh.vertices[v], bounds.min, step), uint32_t(cells.size())).first->second;

  // The corners at each point, in element order (a counting sort).
  const size_t corners = 3 * mesh.size();
  std::vector<uint32_t> start(cells.size() + 1, 0), order(corners);
  for (const Patch& p : mesh.patches)
    for (const uint32_t v : p.vertices) ++start[point_of[v] + 1];
  for (size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (size_t c = 0; c < corners; ++c) order[fill[point_of[mesh.patches[c / 3].vertices[c % 3]]]++] = uint32_t(c);

  // At each point, one display point per surface: a corner joins the first surface there of its
  // material whose first element's plane is within the crease angle of its own.
  const float smooth = std::cos(kCreaseDegrees * 3.14159265f / 180.0f) - 1e-4f;
  DisplaySurfaces result;
  result.corner.resize(corners);
  struct Surface {
    int material;
    glm::vec3 normal;
    uint32_t id;
  };
  std::vector<Surface> here;
  for (size_t point = 0; point + 1 < start.size(); ++point) {
    here.clear();
    for (uint32_t k = start[point]; k < start[point + 1]; ++k) {
      const uint32_t c = order[k];
      const Patch& p = mesh.patches[c / 3];
      const int material = material_of_mesh.at(size_t(p.mesh));
      uint32_t id = 0;
      bool found = false;
      for (const Surface& s : here)
        if (s.material == material && glm::dot(s.normal, p.normal) >= smooth) {
          id = s.id;
          found = true;
          break;
        }
      if (!found) {
        id = result.points++;
        here.push_back({material, p.normal, id});
      }
      result.corner[c] = id;
    }
  }
  return result;
}

}  // namespace luz
