// The page has one GL context, its canvas's WebGL 2 (window_context_web.cpp), current on the
// browser's main thread for as long as the page lives: a headless render there (luz render's
// code, which the page links with the viewer) draws into its own framebuffers through that
// context, so an "offscreen context" in the page is the canvas's, kept current, nothing more.
#include "gl/offscreen_context.h"

#include <emscripten/html5.h>

#include "core/error.h"

namespace luz::gl {

OffscreenContext::OffscreenContext() : OffscreenContext(GlBackend::automatic) {}

OffscreenContext::OffscreenContext(GlBackend) {
  if (emscripten_webgl_get_current_context() == 0)
    throw Error(ErrorKind::gl, "the page draws only through its canvas's WebGL 2 context, and none is current");
}

OffscreenContext::~OffscreenContext() = default;

}  // namespace luz::gl
