#pragma once
// `luz render --model radiosity`: mesh, solve by progressive shooting, draw. Separate from
// render_command.cpp so each model's command code stays in its own file.
#include "app/cli/render_command.h"
#include "core/camera.h"
#include "core/image.h"
#include <memory>
#include <optional>

#include "core/scene.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/vertex_colours.h"
#include "radiosity/shooting.h"

namespace luz::app {

// A radiosity solution solved once and shown by every picture that needs it: the radiosity and
// hybrid panes of one sheet (`luz render --model radiosity,hybrid`) and a lesson step's picture.
// Radiosity is view-independent (slide 39), so the panes of a sheet share one solve.

// The solver's options: the radiosity flags', with the kd textures as `--no-textures` leaves them.
RadiosityOptions radiosity_options(const RenderSettings& settings);

// Needs a current GL context. Shows a progress bar on stderr when it is a terminal (unless
// settings.quiet), writes settings.csv when given. Throws luz::Error.
// Steps `solver` to its stopping rule with that progress bar, then writes settings.csv and the
// summary line (the hybrid solves its radiosity the same way).
void run_radiosity_solver(ProgressiveSolver& solver, const RenderSettings& settings);

Image render_radiosity(const Scene& scene, const Camera& camera, int width, int height,
                       const RenderSettings& settings);

struct RadiositySolution {
  PatchMesh mesh;
  RadianceField radiance;                  // B/pi per patch and vertex: the picture and the hybrid's diffuse part
  std::optional<RadianceField> heat_map;   // the unshot power's colours, when the picture shows them
};

// How far the shared solve goes: the radiosity flags' stopping rule (--converge, --shots,
// --time), or exactly `shots` shots (0: the emitters alone, slide 39's step 1).
struct SolveExtent {
  std::optional<int> shots;
  // Also a false-colour picture made from the solver (the viewer's heat map of the unshot
  // power), divided by 2^exposure so that the PNG shows its colours as they are; nullptr: none.
  RadianceField (*heat_map)(const ProgressiveSolver& solver) = nullptr;
  float exposure = 0.0f;
};

// Meshes and solves as `luz render --model radiosity` does (its progress bar and summary line
// included). Makes its own OSMesa context: none may be current. Throws luz::Error.
std::shared_ptr<const RadiositySolution> solve_radiosity(const Scene& scene, const RenderSettings& settings,
                                                         const SolveExtent& extent = {});

}  // namespace luz::app
