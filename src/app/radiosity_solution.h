#pragma once
// A radiosity solution solved once and shown by every picture that needs it: the radiosity and
// hybrid panes of one sheet (`luz render --model radiosity,hybrid`) and a lesson step's picture.
// Radiosity is view-independent (slide 39), so the panes of a sheet share one solve.
#include <memory>
#include <optional>

#include "core/scene.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/vertex_colours.h"

namespace luz::app {

struct RenderSettings;

struct RadiositySolution {
  PatchMesh mesh;
  RadianceField radiance;                  // B/pi per patch and vertex: the picture and the hybrid's diffuse part
  std::optional<RadianceField> heat_map;   // the unshot power's colours, when the picture shows them
};

// How far the shared solve goes: the radiosity flags' stopping rule (--converge, --shots,
// --time), or exactly `shots` shots (0: the emitters alone, slide 39's step 1).
struct SolveExtent {
  std::optional<int> shots;
  bool heat_map = false;  // also the heat map of the unshot power, in units for `exposure` EV
  float exposure = 0.0f;
};

// Meshes and solves as `luz render --model radiosity` does (its progress bar and summary line
// included). Makes its own OSMesa context: none may be current. Throws luz::Error.
std::shared_ptr<const RadiositySolution> solve_radiosity(const Scene& scene, const RenderSettings& settings,
                                                         const SolveExtent& extent = {});

}  // namespace luz::app
