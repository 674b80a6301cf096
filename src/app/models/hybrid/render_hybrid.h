#pragma once
// `luz render --model hybrid` (slides 41-43): radiosity solved first (headless GL), then the
// Whitted tracer with the radiosity solution as the diffuse part of every hit.
#include "app/cli/render_command.h"
#include "app/models/whitted/render_whitted.h"
#include "core/camera.h"
#include "core/scene.h"

namespace luz::app {

// Makes its own OSMesa context for the radiosity solve (none may be current); the tracing needs
// none. The radiosity flags (stopping rule, patch size, hemicube, --ambient-estimate, --csv) and
// the Whitted flags (depth, spp, fresnel, light samples, ray tree, ...) both apply.
Rendered render_hybrid(const Scene& scene, const Camera& camera, int width, int height,
                            const RenderSettings& settings);

}  // namespace luz::app
