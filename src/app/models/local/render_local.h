#pragma once
// `luz render --model flat|gouraud|phong`: the local-model rasteriser, headless through OSMesa.
#include "app/common/model_registry.h"
#include "app/cli/render_command.h"
#include "local/local_options.h"

namespace luz::app {

Rendered render_local(Shading shading, const Scene& scene, const Camera& camera, int width, int height,
                      const RenderSettings& settings);

}  // namespace luz::app
