#pragma once
// `luz render --model radiosity`: mesh, solve by progressive shooting, draw. Separate from
// render_command.cpp so each model's command code stays in its own file.
#include "app/cli/render_command.h"
#include "core/camera.h"
#include "core/image.h"
#include "core/scene.h"
#include "radiosity/shooting.h"

namespace luz::app {

// The solver's options: the radiosity flags', with the kd textures as `--no-textures` leaves them.
RadiosityOptions radiosity_options(const RenderSettings& settings);

// Needs a current GL context. Shows a progress bar on stderr when it is a terminal (unless
// settings.quiet), writes settings.csv when given. Throws luz::Error.
// Steps `solver` to its stopping rule with that progress bar, then writes settings.csv and the
// summary line (the hybrid solves its radiosity the same way).
void run_radiosity_solver(ProgressiveSolver& solver, const RenderSettings& settings);

Image render_radiosity(const Scene& scene, const Camera& camera, int width, int height,
                       const RenderSettings& settings);

}  // namespace luz::app
