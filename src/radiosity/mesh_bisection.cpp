// Conforming longest-edge bisection of the radiosity mesh. See mesh_bisection.h.
#include "radiosity/mesh_bisection.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "core/std_compat.h"

namespace luz {
namespace {

// Elements on one flat surface: normals within about 2.5 degrees. The facets of a curved mesh
// differ more, and their irradiance changes with their orientation, which Gouraud shading
// follows already: they are not compared.
constexpr float kSameSurface = 0.999f;

uint32_t bits(float x) { return bit_cast<uint32_t>(x + 0.0f); }  // -0 and +0 alike

bool less(const glm::vec3& p, const glm::vec3& q) {
  return p.x != q.x ? p.x < q.x : p.y != q.y ? p.y < q.y : p.z < q.z;
}

}  // namespace

size_t MeshBisection::PositionHash::operator()(const Position& p) const {
  uint64_t h = (uint64_t(p.x) * 0x9e3779b97f4a7c15ULL) ^ (uint64_t(p.y) * 0xc2b2ae3d27d4eb4fULL) ^
               (uint64_t(p.z) * 0x165667b19e3779f9ULL);
  return size_t(h ^ (h >> 29));
}

MeshBisection::MeshBisection(PatchMesh& mesh) : mesh_(mesh) {
  welded_.reserve(mesh.vertices.size());
  for (const glm::vec3& p : mesh.vertices) welded_.push_back(weld(p));
  for (uint32_t e = 0; e < mesh.size(); ++e) link(e);
  if (mesh.refinements.size() < mesh.size()) mesh.refinements.resize(mesh.size());
}

uint32_t MeshBisection::weld(const glm::vec3& p) {
  const auto [at, added] = positions_.try_emplace(Position{bits(p.x), bits(p.y), bits(p.z)},
                                                  uint32_t(positions_.size()));
  return at->second;
}

MeshBisection::Edge MeshBisection::edge(uint32_t a, uint32_t b) const {
  const uint64_t p = welded_[a], q = welded_[b];
  return p < q ? (p << 32) | q : (q << 32) | p;
}

void MeshBisection::link(uint32_t e) {
  const uint32_t* v = mesh_.patches[e].vertices;
  for (int k = 0; k < 3; ++k) edges_[edge(v[k], v[(k + 1) % 3])].push_back(e);
}

void MeshBisection::unlink(uint32_t e) {
  const uint32_t* v = mesh_.patches[e].vertices;
  for (int k = 0; k < 3; ++k) {
    std::vector<uint32_t>& on = edges_[edge(v[k], v[(k + 1) % 3])];
    on.erase(std::find(on.begin(), on.end(), e));
  }
}

MeshBisection::Edge MeshBisection::longest_edge(uint32_t e) const {
  const uint32_t* v = mesh_.patches[e].vertices;
  Edge best = 0;
  float best_length = -1.0f;
  for (int k = 0; k < 3; ++k) {
    const uint32_t a = v[k], b = v[(k + 1) % 3];
    const glm::vec3 d = mesh_.vertices[b] - mesh_.vertices[a];
    const float length = glm::dot(d, d);
    const Edge key = edge(a, b);
    if (length > best_length || (length == best_length && key > best)) best = key, best_length = length;
  }
  return best;
}

// The midpoint of vertices a and b, made once per pair and computed from the lesser position,
// so that the vertex on the other side of a seam gets the same bits.
uint32_t MeshBisection::midpoint(uint32_t a, uint32_t b) {
  const uint64_t key = a < b ? (uint64_t(a) << 32) | b : (uint64_t(b) << 32) | a;
  const auto found = midpoints_.find(key);
  if (found != midpoints_.end()) return found->second;
  glm::vec3 p = mesh_.vertices[a], q = mesh_.vertices[b];
  if (less(q, p)) std::swap(p, q);
  mesh_.vertices.push_back(p + 0.5f * (q - p));
  const uint32_t m = uint32_t(mesh_.vertices.size() - 1);
  welded_.push_back(weld(mesh_.vertices.back()));
  midpoints_.emplace(key, m);
  return m;
}

void MeshBisection::split(uint32_t e, std::vector<uint32_t>& changed) {
  const Edge cut = longest_edge(e);
  // Every element on the edge must have it as its longest before one midpoint can serve them
  // all: cut the others by their own longest edge first (one of the halves keeps this edge).
  for (;;) {
    const std::vector<uint32_t>& on = edges_[cut];
    const auto other = std::find_if(on.begin(), on.end(),
                                    [&](uint32_t f) { return longest_edge(f) != cut; });
    if (other == on.end()) break;
    split(*other, changed);
  }
  bisect(cut, changed);
}

// Element (a, b, c) with the cut edge from a to b becomes (a, m, c), in its own place, and
// (m, b, c), at the end; both keep the winding, the surface's data and the shooting patch.
void MeshBisection::bisect(Edge cut, std::vector<uint32_t>& changed) {
  const std::vector<uint32_t> on = edges_[cut];
  for (const uint32_t e : on) {
    const Patch parent = mesh_.patches[e];
    int k = 0;
    while (edge(parent.vertices[k], parent.vertices[(k + 1) % 3]) != cut) ++k;
    const uint32_t a = parent.vertices[k], b = parent.vertices[(k + 1) % 3],
                   c = parent.vertices[(k + 2) % 3];
    const uint32_t m = midpoint(a, b);
    unlink(e);
    const auto half = [&](uint32_t v0, uint32_t v1, uint32_t v2) {
      Patch p = make_element(mesh_.vertices, v0, v1, v2);
      p.mesh = parent.mesh;
      p.triangle = parent.triangle;
      p.rho = parent.rho;
      p.emission = parent.emission;
      p.level = parent.level + 1;
      return p;
    };
    const uint32_t second = uint32_t(mesh_.patches.size());
    mesh_.patches[e] = half(a, m, c);
    mesh_.patches.push_back(half(m, b, c));
    mesh_.shooter_of.push_back(mesh_.shooter_of[e]);
    mesh_.refinements.resize(mesh_.patches.size());
    PatchMesh::Refinement& history = mesh_.refinements[e];
    if (history.steps.empty()) std::copy(parent.vertices, parent.vertices + 3, history.corners);
    history.steps.push_back({second, m, c, b});
    link(e);
    link(second);
    changed.push_back(e);
    changed.push_back(second);
  }
}

void MeshBisection::neighbours(uint32_t e, std::vector<uint32_t>& out) const {
  const Patch& p = mesh_.patches[e];
  for (int k = 0; k < 3; ++k) {
    const auto found = edges_.find(edge(p.vertices[k], p.vertices[(k + 1) % 3]));
    if (found == edges_.end()) continue;
    for (const uint32_t f : found->second)
      if (f != e && glm::dot(mesh_.patches[f].normal, p.normal) > kSameSurface) out.push_back(f);
  }
}

}  // namespace luz
