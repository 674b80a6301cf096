#pragma once
// A headless OpenGL 3.3 core context: no display needed. Two back ends, chosen at run time:
// - EGL (libEGL): Mesa's surfaceless platform (EGL_MESA_platform_surfaceless), else the device
//   platform (EGL_EXT_platform_device, vendor drivers on GPU machines), else the default
//   display; no surface at all where EGL_KHR_surfaceless_context allows, else a 1x1 pbuffer.
// - OSMesa (Mesa's llvmpipe in a library), which Mesa removed in 25.1.
// Renderers draw into their own framebuffer objects; the context's own buffer is at most 1x1.
#include <optional>
#include <string>
#include <string_view>

namespace luz::gl {

enum class GlBackend { automatic, egl, osmesa };

const char* to_string(GlBackend backend);
std::optional<GlBackend> parse_backend(std::string_view name);  // "egl", "osmesa", "auto"

// The back end a default-constructed OffscreenContext uses: the one set here (luz's --gl flag),
// else the environment variable LUZ_GL (egl or osmesa; the tests read it too), else automatic:
// EGL when it gives a 3.3 core context, else OSMesa. Throws luz::Error (kind usage) for a
// LUZ_GL that names neither.
void set_default_backend(GlBackend backend);
GlBackend default_backend();

class OffscreenContext {
public:
  // Creates the context, makes it current on this thread and loads the GL function table.
  // Throws luz::Error (kind gl) when the back end cannot give a 3.3 core context (automatic:
  // when neither can, naming both reasons).
  OffscreenContext();
  explicit OffscreenContext(GlBackend backend);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  GlBackend backend() const { return backend_; }  // egl or osmesa: the one in use

private:
  void create_egl();
  void create_osmesa();
  void check_version(const char* backend_name);
  void release();

  GlBackend backend_ = GlBackend::automatic;
  void* osmesa_context_ = nullptr;  // OSMesaContext, kept opaque so osmesa.h stays in one file
  unsigned char buffer_[4] = {};
  void* egl_display_ = nullptr;     // EGLDisplay, EGLContext, EGLSurface, likewise opaque
  void* egl_context_ = nullptr;
  void* egl_surface_ = nullptr;
};

}  // namespace luz::gl
