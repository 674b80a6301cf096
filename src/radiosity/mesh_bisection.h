#pragma once
// Adaptive subdivision's meshing (slide 40, "Mallado"): elements cut in two where the radiosity
// changes fast, the mesh kept free of T-junctions.
//
// An element is cut by its longest edge's midpoint into two (longest-edge bisection, Rivara,
// "Algorithms for Refining Triangular Grids Suitable for Adaptive and Multigrid Techniques",
// IJNME 1984). A T-junction would appear if the element across that edge kept the edge whole: so
// every element on the edge is cut at the same midpoint, and one whose own longest edge is
// another is first cut by that one (which may cut its neighbour first, and so on: the edges grow
// along the chain, so it ends). What is drawn then has no vertex inside another element's edge,
// no cracks, and the Gouraud colours are continuous. Bisecting the longest edge keeps the angles
// bounded away from 0 however often it is repeated: the uniform mesh's right triangles stay right.
//
// "Every element on the edge" is found by position, not by vertex index: two surfaces that touch
// along a seam with vertices of their own (a glTF mesh split for its texture coordinates) are
// cut together too, each side getting its own midpoint vertex with the same coordinates, so a
// crease keeps its separate radiosity on either side and still has no crack.
//
// Elements keep their shooting patch: a patch's area and corners do not change, only how many
// elements it holds.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "radiosity/patch_mesh.h"

namespace luz {

class MeshBisection {
public:
  explicit MeshBisection(PatchMesh& mesh);

  // Cuts element e in two, and whatever else conformity needs. The elements made or changed are
  // appended to `changed` (the first half of a cut element keeps its index, the second is new).
  // PatchMesh::members is stale until PatchMesh::group_by_shooter() is called after the splits.
  void split(uint32_t e, std::vector<uint32_t>& changed);
  // The elements sharing an edge with e on the same flat surface (normals within 2.5 degrees):
  // those its irradiance is compared with.
  void neighbours(uint32_t e, std::vector<uint32_t>& out) const;

private:
  using Edge = uint64_t;  // the welded ids of its two ends, the smaller in the high half
  Edge edge(uint32_t a, uint32_t b) const;
  // The element's longest edge: by length, ties broken by the edge's key, so that every element
  // on an edge agrees which of its edges is longest.
  Edge longest_edge(uint32_t e) const;
  // Cuts every element on edge `cut` (each has it as its longest edge) at its midpoint.
  void bisect(Edge cut, std::vector<uint32_t>& changed);
  uint32_t weld(const glm::vec3& p);
  uint32_t midpoint(uint32_t a, uint32_t b);
  void link(uint32_t e);
  void unlink(uint32_t e);

  struct Position {  // a vertex position's bits
    uint32_t x, y, z;
    bool operator==(const Position&) const = default;
  };
  struct PositionHash {
    size_t operator()(const Position& p) const;
  };

  PatchMesh& mesh_;
  std::vector<uint32_t> welded_;                                 // per vertex, its position's id
  std::unordered_map<Position, uint32_t, PositionHash> positions_;  // -> welded id
  std::unordered_map<Edge, std::vector<uint32_t>> edges_;  // welded edge -> elements on it
  std::unordered_map<uint64_t, uint32_t> midpoints_;       // vertex pair -> midpoint vertex
};

}  // namespace luz
