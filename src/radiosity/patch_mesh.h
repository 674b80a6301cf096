#pragma once
// The scene's triangles cut into radiosity patches (slide 32: "las superficies se dividen en
// retazos de radiosidad constante").
//
// Every source triangle is split uniformly into n x n smaller triangles (n per glTF primitive,
// from its longest edge and the patch size). Using one n for a whole primitive makes the
// subdivision conforming: two triangles that share an edge put the same points on it, so there
// are no T-junctions (no cracks or sparkles when the mesh is drawn, no gaps in the item buffer).
// Points on a shared edge are computed from the edge's ends in a canonical order, so both
// triangles get bit-identical coordinates.
//
// Vertices are shared exactly where the source mesh shares them (what the display averages is
// decided apart, by the surfaces that meet at a point: display_surfaces.h).
//
// Substructuring (Cohen, Greenberg, Immel & Brock, "An Efficient Radiosity Approach for
// Realistic Image Synthesis", IEEE CG&A 1986): the triangles of `patches` are the *elements*,
// which receive light, hold the item buffer's IDs and are drawn. They are grouped into coarser
// *shooting patches* (`shooters`): a source triangle is first cut n x n into patches and every
// patch k x k into elements, so the elements are the uniform subdivision at n k and every
// element lies inside exactly one patch (the patch grid's lines are lines of the element grid).
// With k = 1 each element is its own patch, and shooter s is element s. A mesh whose triangles
// are already shorter than the element size (max_edge / k) gets fewer elements per patch, down
// to one: a finely tessellated sphere is not cut further.
//
// Adaptive subdivision (mesh_bisection.h) cuts elements in two after the mesh is built; the
// halves keep their source triangle and shooting patch, and `refinements` records the cuts so
// that locate() still finds the element holding a point.
//
// Front side: a patch emits and receives only on the side its normal points to, the side from
// which its triangle is wound counter-clockwise (glTF's front face, which the loader keeps).
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/color.h"
#include "core/scene.h"
#include "radiosity/display_surfaces.h"
#include "radiosity/radiosity_options.h"
#include "radiosity/texture_detail.h"
#include "radiosity/vertex_fit.h"

namespace luz {

struct Patch {
  int mesh = 0;                 // source: Scene::meshes index ...
  int triangle = 0;             // ... and triangle in it
  uint32_t vertices[3] = {};    // into PatchMesh::vertices, counter-clockwise seen from the front
  glm::vec3 centre{0.0f};       // centroid
  glm::vec3 normal{0, 1, 0};    // unit, the front side
  float area = 0.0f;            // m^2
  float clearance = 0.0f;       // distance from the centroid to the nearest edge of the patch
  Rgb rho{0.0f};                // diffuse reflectance kd
  Rgb emission{0.0f};           // exitance E = pi * Le (W/m^2)
  int level = 0;                // times adaptive subdivision has halved it
};

// An element's geometry (area, normal, centroid, clearance) from its three vertices.
Patch make_element(const std::vector<glm::vec3>& vertices, uint32_t v0, uint32_t v1, uint32_t v2);

// A shooting patch: a group of elements that shoots as one, from its centroid.
struct ShootingPatch {
  glm::vec3 centre{0.0f};     // area-weighted centroid of its elements
  glm::vec3 normal{0, 1, 0};  // unit, the front side (that of its elements)
  float area = 0.0f;          // sum of its elements' areas, m^2
  float clearance = 0.0f;     // centroid to the nearest edge of the patch
  float radius = 0.0f;        // centroid to the farthest corner
  glm::vec3 corners[3] = {};  // counter-clockwise seen from the front
  uint32_t first = 0;         // its elements: PatchMesh::members[first .. first + count)
  uint32_t count = 0;
};

class PatchMesh {
public:
  PatchMesh() = default;
  // Splits every triangle so that no patch edge is longer than `max_edge` metres, and every
  // patch into elements_per_edge^2 elements; `textures`: see `detail`. Throws luz::Error
  // (bad_value) before allocating anything if the mesh would have more than kMaxElements
  // elements, and (not_finite) if a triangle's edge is not a finite length.
  static PatchMesh build(const Scene& scene, float max_edge, int elements_per_edge = 1, bool textures = true);
  // The patch size at which subdivision adds about `target` patches to the scene's triangles.
  static float patch_size_for(const Scene& scene, size_t target);
  // With options.patch_size, or else the size for options.target_patches.
  static PatchMesh build(const Scene& scene, const RadiosityOptions& options);
  // How many elements build() would make (a double: it may be far beyond any memory).
  static double element_count(const Scene& scene, float max_edge, int elements_per_edge);

  std::vector<Patch> patches;        // the elements (see above)
  std::vector<glm::vec3> vertices;   // shared corners of the elements
  std::vector<ShootingPatch> shooters;
  std::vector<uint32_t> members;     // element indices, grouped by shooter
  std::vector<uint32_t> shooter_of;  // per element, its shooting patch
  float max_edge = 0.0f;             // of a shooting patch
  int elements_per_edge = 1;
  // The kd textures the reflectances were made with (none with RadiosityOptions::textures
  // false): the picture and the hybrid show the same detail.
  TextureDetail detail;
  std::vector<int> mesh_material;    // per scene mesh, its material
  DisplaySurfaces display;           // which element corners show one value
  VertexFit vertex_fit;              // ... and how it is made from the elements' values
  int revision = 0;                  // changes whenever the elements change after build()

  size_t size() const { return patches.size(); }
  float total_area() const;
  // Subdivisions per edge of the triangles of source mesh `mesh`.
  int subdivisions(int mesh) const { return sources_[size_t(mesh)].n; }

  // The patch holding the point of source triangle (mesh, triangle) at barycentrics
  // (b1, b2) of its second and third vertex (point = A + b1 (B - A) + b2 (C - A)), and that
  // point's barycentrics in the patch (weights of the patch's three vertices).
  struct Location {
    size_t patch = 0;
    glm::vec3 weights{1.0f, 0.0f, 0.0f};
  };
  Location locate(int mesh, int triangle, glm::vec2 b) const;

  // The cuts made in element slot e since the mesh was built, in order (mesh_bisection.h): each
  // split the element then in that slot, with vertices (a, middle, apex) kept there and
  // (middle, end, apex) put in slot `second`. Empty when adaptive subdivision has not run.
  struct Bisection {
    uint32_t second, middle, apex, end;
  };
  struct Refinement {
    uint32_t corners[3] = {};          // of the slot's element before its first cut
    std::vector<Bisection> steps;
  };
  std::vector<Refinement> refinements;

  // Fills `members` and every shooter's (first, count) from `shooter_of`, keeping the elements of
  // a patch in index order.
  void group_by_shooter();
  // `display` and `vertex_fit` again, after elements were cut.
  void find_display_surfaces() {
    display = DisplaySurfaces::of(*this, mesh_material);
    vertex_fit = VertexFit::of(*this);
  }

private:
  struct Source {
    int n = 1;                 // subdivisions per edge
    size_t first_patch = 0;    // patches of triangle t start at first_patch + t * n * n
  };
  std::vector<Source> sources_;  // one per Scene::meshes entry
};

}  // namespace luz
