#include "app/models/local/render_local.h"

#include <fmt/format.h>

#include "app/common/i18n.h"
#include "gl/offscreen_context.h"
#include "local/local_renderer.h"

namespace luz::app {

Rendered render_local(Shading shading, const Scene& scene, const Camera& camera, int width, int height,
                      const RenderSettings& settings) {
  gl::OffscreenContext context;
  LocalOptions options = settings.local;
  options.shading = shading;
  LocalRenderer renderer(scene);
  Rendered rendered;
  rendered.image = renderer.render(camera, width, height, options);
  for (const std::string& warning : renderer.warnings()) fmt::print(stderr, "{}\n", trf("warning: {}", warning));
  return rendered;
}

}  // namespace luz::app
