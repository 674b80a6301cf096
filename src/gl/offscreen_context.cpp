#include "gl/offscreen_context.h"

// functions.h first: glcorearb.h then owns the GL types; osmesa.h (which pulls in gl.h and its
// global prototypes) is included here and nowhere else. Inside namespace luz, unqualified GL
// names still find the luz:: pointers of the table before the global prototypes.
#include "gl/functions.h"

#include <GL/osmesa.h>

#include <fmt/format.h>

#include "core/error.h"

namespace luz::gl {

OffscreenContext::OffscreenContext() {
  const int attributes[] = {
      OSMESA_FORMAT, OSMESA_RGBA,
      OSMESA_DEPTH_BITS, 24,
      OSMESA_PROFILE, OSMESA_CORE_PROFILE,
      OSMESA_CONTEXT_MAJOR_VERSION, 3,
      OSMESA_CONTEXT_MINOR_VERSION, 3,
      0,
  };
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context)
    throw Error(ErrorKind::gl, "OSMesa could not create an OpenGL 3.3 core context "
                               "(is libosmesa6 Mesa's gallium build with llvmpipe?)");
  context_ = context;
  // The context's own 1x1 buffer only makes it current: renderers draw into their own FBOs.
  if (!OSMesaMakeCurrent(context, buffer_, GL_UNSIGNED_BYTE, 1, 1)) {
    OSMesaDestroyContext(context);
    context_ = nullptr;
    throw Error(ErrorKind::gl, "OSMesa could not make its OpenGL context current");
  }
  try {
    load_gl_functions(OSMesaGetProcAddress);
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor < 33)
      throw Error(ErrorKind::gl, fmt::format("OSMesa gave OpenGL {}.{}; Luz needs 3.3 core ({})",
                                             major, minor, gl_version_string()));
  } catch (...) {
    OSMesaDestroyContext(context);
    context_ = nullptr;
    throw;
  }
}

OffscreenContext::~OffscreenContext() {
  if (context_) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

}  // namespace luz::gl
