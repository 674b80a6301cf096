#pragma once
// `luz render --model whitted`: the tracer of src/raytracing with a progress bar on a terminal,
// the counters at the end, and the ray tree of one pixel as JSON.
#include <filesystem>
#include <optional>
#include <string>

#include "app/common/model_registry.h"
#include "app/cli/render_command.h"
#include "core/camera.h"
#include "core/image.h"
#include "core/scene.h"
#include "raytracing/diffuse_source.h"

namespace luz::app {


// The tracer's options as `luz render` and the viewer make them: the Whitted switches, with the
// local terms' switches (--no-TERM, --blinn; the panel's term checkboxes) applied to its local part.
rt::WhittedOptions tracer_options(const rt::WhittedOptions& whitted, const LocalOptions& local);

// Throws luz::Error (usage) when the --ray-tree pixel lies outside the image. With `diffuse`
// (the hybrid, render_hybrid.h) the tracer takes the diffuse part of every hit from it.
// A usage error (luz::Error) unless --spp is a square: the tracer's sqrt(N) x sqrt(N) grid.
void check_square_spp(const RenderSettings& settings);

Rendered render_whitted(const Scene& scene, const Camera& camera, int width, int height,
                             const RenderSettings& settings,
                             const rt::DiffuseSource* diffuse = nullptr);

}  // namespace luz::app
