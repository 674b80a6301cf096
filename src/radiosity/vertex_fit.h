#pragma once
// The value shown at each display point (display_surfaces.h) from the constant values of the
// elements around it, as a fixed combination of those values: what Gouraud shading then
// interpolates across every element.
//
// Each point takes a least-squares linear fit over the centroids of the elements that meet there
// on its surface (weighted by their areas, in the surface's tangent plane), evaluated at the
// point. A plain mean of those elements is the fit's value at their centroid, not at the point:
// on a surface's edge the elements all lie to one side, and after adaptive subdivision their
// centroids lie nearer to the edge at one point than at the next, so where the light changes
// fast the means alternate along the edge (dark notches along a wall's top row). The fit gives
// a radiosity that varies linearly across the surface exactly, whatever the mesh, at the edge
// as inside; inside a surface, where the elements surround the point, it stays close to the mean.
//
// A point whose elements cannot fix a plane (one element, or centroids on a line: a corner of a
// surface, a strip one element wide) is fitted over the elements around those elements on the
// same surface; where even they cannot, it takes their area-weighted mean.
#include <cstdint>
#include <vector>

namespace luz {

class PatchMesh;

struct VertexFit {
  // Display point p's value is the sum over k in [start[p], start[p + 1]) of
  // weight[k] x the value of element element[k]. The weights sum to 1.
  std::vector<uint32_t> start;
  std::vector<uint32_t> element;
  std::vector<float> weight;

  // From the mesh's elements and display surfaces (PatchMesh::find_display_surfaces() keeps one
  // with the mesh, made again whenever its elements change).
  static VertexFit of(const PatchMesh& mesh);
};

}  // namespace luz
