#pragma once
// Which element corners show one value (SCENES.md, "Units and the models"): the displayed value
// at a point averages the elements that meet there on the same surface only. Never across a
// crease, whatever the file shares (a box exported smooth shares the vertices of its edges, and
// averaging there would smear each face's light onto the next); always across coincident corners
// of one surface, whatever the file separates (a triangle soup, each triangle with its own
// vertices, would otherwise show every triangle's edge as a seam).
//
// One surface, at a point: elements of the same material (a change of material is an edge of
// the picture's colour, kept sharp) whose planes meet at no more than kCreaseDegrees, the
// smoothing angle Blender also defaults to, so a tessellated sphere or cylinder stays smooth and
// a box's edges stay sharp. Corners are coincident when they lie within a millionth of the
// scene's size of each other (a soup's copies of one vertex are the same numbers; the points
// subdivision puts on their edges differ in the last bits).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace luz {

class PatchMesh;

inline constexpr float kCreaseDegrees = 30.0f;

struct DisplaySurfaces {
  std::vector<uint32_t> corner;  // per element corner (3 e + k): the display point it shows
  uint32_t points = 0;           // how many display points

  // Groups the corners of `mesh`'s elements; `material_of_mesh[m]` is scene mesh m's material.
  static DisplaySurfaces of(const PatchMesh& mesh, const std::vector<int>& material_of_mesh);
  // Made for a mesh of this many elements (adaptive subdivision adds elements).
  bool fits(size_t elements) const { return corner.size() == 3 * elements; }
};

}  // namespace luz
