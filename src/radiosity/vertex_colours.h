#pragma once
// From patch exitances B (W/m^2) to what is drawn: the radiance of a diffuse surface, B / pi
// (SCENES.md), per patch and at the element corners (each corner takes a linear fit over the
// elements that meet there on its surface, vertex_fit.h, so Gouraud interpolation shows a smooth
// surface and a crease stays sharp: display_surfaces.h).
//
// The same field answers "what radiance does radiosity give at this point of this triangle?"
// on the CPU, for a ray tracer that takes its diffuse light from radiosity (the hybrid model).
#include <vector>

#include <glm/vec2.hpp>

#include "core/color.h"
#include "radiosity/patch_mesh.h"

namespace luz {

class ProgressiveSolver;

struct RadianceField {
  std::vector<Rgb> patch;   // B_i / pi (+ rho_i * ambient / pi), one per patch
  std::vector<Rgb> corner;  // `patch` fitted at the element corners, one per corner (3 e + k)

  // `exitance`: B per patch. `ambient`: Cohen's ambient exitance (0 for none); patch i shows
  // rho_i * ambient more.
  static RadianceField from(const PatchMesh& mesh, const std::vector<Rgb>& exitance,
                            const Rgb& ambient = Rgb(0.0f));
  // What the solver shows now (slide 39 step 3), with the ambient term when its options ask.
  static RadianceField of(const ProgressiveSolver& solver);

  // The interpolated radiance at barycentrics (b1, b2) of source triangle `triangle` of scene
  // mesh `mesh` (point = A + b1 (B - A) + b2 (C - A)), as the Gouraud picture shows it.
  Rgb at(const PatchMesh& mesh, int scene_mesh, int triangle, glm::vec2 b) const;

  // A false-colour map of the unshot power per patch (unshot x area, from dark blue through red
  // to yellow, log scale over three decades below the largest), for the viewer's heat map.
  static RadianceField unshot_heat_map(const ProgressiveSolver& solver);
};

}  // namespace luz
