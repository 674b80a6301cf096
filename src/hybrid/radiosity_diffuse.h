#pragma once
// The hybrid model (slides 41-43): "cálculo de brillos por trazado de rayos (dependiente del
// observador) y de la iluminación difusa por radiosidad (independiente del observador)".
//
// RadiosityDiffuse hands the Whitted tracer the radiosity solution as its diffuse part: at a hit
// on triangle t of scene mesh m at barycentrics b, the radiance B/pi interpolated across the
// patch mesh exactly as the radiosity picture's Gouraud shading interpolates it
// (RadianceField::at), times the kd texture's detail there as that picture shows it
// (PatchMesh::detail). Everything else of a hit comes from rays (see rt::Whitted::color).
//
//   PatchMesh mesh = PatchMesh::build(scene, radiosity_options);     // needs GL from here ...
//   ProgressiveSolver solver(scene, mesh, radiosity_options);
//   while (solver.step()) {}                      // or the viewer's solution, converged or not
//   RadiosityDiffuse diffuse(mesh, RadianceField::of(solver));      // ... to here; no GL below
//   WhittedRenderer tracer(scene);
//   tracer.set_diffuse_source(&diffuse);
//   Image image = tracer.render(camera, w, h, whitted_options, ...);
//
// With the source set, the ambient and emission switches no longer apply (radiosity holds both);
// the diffuse switch turns radiosity's part off and leaves the rays' part. The renderer is
// Whitted's, so the viewer's tiles, progress, cancel and ray-tree inspection work for the hybrid
// unchanged.
#include "radiosity/patch_mesh.h"
#include "radiosity/vertex_colours.h"
#include "raytracing/diffuse_source.h"

namespace luz::hybrid {

class RadiosityDiffuse final : public rt::DiffuseSource {
public:
  // `mesh` (and the scene it was built from) must outlive this object and be the mesh `field`
  // was computed on.
  RadiosityDiffuse(const PatchMesh& mesh, RadianceField field);

  // A newer solution (the viewer after more shots). Not while a render reads this object.
  void update(RadianceField field);
  const RadianceField& field() const { return field_; }

  Rgb diffuse_radiance(int mesh, int triangle, glm::vec2 barycentrics) const override;

private:
  const PatchMesh& mesh_;
  RadianceField field_;
};

}  // namespace luz::hybrid
