#include "gl/offscreen_context.h"

// functions.h first: glcorearb.h then owns the GL types; osmesa.h (which pulls in gl.h and its
// global prototypes) and the EGL headers are included here and nowhere else. Inside namespace
// luz, unqualified GL names still find the luz:: pointers of the table before the global
// prototypes.
#include "gl/functions.h"

#include <GL/osmesa.h>
#define EGL_NO_X11  // no Xlib types in eglplatform.h: the headless back end has no display
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>

#include <fmt/format.h>

#include "core/error.h"
#include "core/i18n.h"

namespace luz::gl {

using i18n::tr;
using i18n::trf;

namespace {

std::optional<GlBackend> g_default;

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const size_t length = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += length)
    if ((p == list || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0')) return true;
  return false;
}

// eglGetProcAddress returns core functions too (EGL 1.5, EGL_KHR_get_all_proc_addresses), so
// the whole table resolves through it.
GlProc egl_resolve(const char* name) { return reinterpret_cast<GlProc>(eglGetProcAddress(name)); }
GlProc osmesa_resolve(const char* name) { return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name)); }

// The headless display: surfaceless (Mesa), else the first device (vendor EGL), else default.
EGLDisplay headless_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_platform_display && has_extension(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  }
  auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (get_platform_display && query_devices && has_extension(client, "EGL_EXT_platform_device")) {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (query_devices(8, devices, &count))
      for (EGLint i = 0; i < count; ++i) {
        EGLDisplay display = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
      }
  }
  EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  return EGL_NO_DISPLAY;
}

}  // namespace

const char* to_string(GlBackend backend) {
  switch (backend) {
    case GlBackend::automatic: return "auto";
    case GlBackend::egl: return "egl";
    case GlBackend::osmesa: return "osmesa";
  }
  return "?";
}

std::optional<GlBackend> parse_backend(std::string_view name) {
  if (name == "egl") return GlBackend::egl;
  if (name == "osmesa") return GlBackend::osmesa;
  if (name == "auto") return GlBackend::automatic;
  return std::nullopt;
}

void set_default_backend(GlBackend backend) { g_default = backend; }

GlBackend default_backend() {
  if (g_default) return *g_default;
  const char* variable = std::getenv("LUZ_GL");
  if (!variable || !*variable) return GlBackend::automatic;
  if (std::optional<GlBackend> parsed = parse_backend(variable)) return *parsed;
  throw Error(ErrorKind::usage, trf("LUZ_GL={}: must be egl, osmesa or auto", variable));
}

OffscreenContext::OffscreenContext() : OffscreenContext(default_backend()) {}

OffscreenContext::OffscreenContext(GlBackend backend) {
  if (backend == GlBackend::egl) {
    create_egl();
    return;
  }
  if (backend == GlBackend::osmesa) {
    create_osmesa();
    return;
  }
  try {
    create_egl();
  } catch (const Error& egl_failure) {
    try {
      create_osmesa();
    } catch (const Error& osmesa_failure) {
      throw Error(ErrorKind::gl, trf("no headless OpenGL 3.3 context: {}; {}", egl_failure.what(),
                                     osmesa_failure.what()));
    }
  }
}

void OffscreenContext::check_version(const char* backend_name) {
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 33)
    throw Error(ErrorKind::gl, trf("{} gave OpenGL {}.{}; Luz needs 3.3 core ({})", backend_name, major,
                                   minor, gl_version_string()));
}

void OffscreenContext::create_egl() {
  EGLDisplay display = headless_display();
  if (display == EGL_NO_DISPLAY) throw Error(ErrorKind::gl, tr("EGL has no headless display"));
  egl_display_ = display;
  auto fail = [&](const char* what) {  // `what`: the sentence, translated, naming EGL
    const EGLint code = eglGetError();
    release();
    return Error(ErrorKind::gl, trf("{} (EGL error 0x{:04X})", what, code));
  };
  if (!eglBindAPI(EGL_OPENGL_API)) throw fail(tr("EGL has no desktop OpenGL API"));
  const bool surfaceless = has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context");
  const EGLint config_attributes[] = {
      EGL_SURFACE_TYPE, surfaceless ? 0 : EGL_PBUFFER_BIT,
      EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
      EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
      EGL_NONE,
  };
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(display, config_attributes, &config, 1, &count) || count < 1)
    throw fail(tr("EGL has no OpenGL configuration"));
  const EGLint context_attributes[] = {
      EGL_CONTEXT_MAJOR_VERSION, 3,
      EGL_CONTEXT_MINOR_VERSION, 3,
      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
      EGL_NONE,
  };
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  if (context == EGL_NO_CONTEXT) throw fail(tr("EGL could not create an OpenGL 3.3 core context"));
  egl_context_ = context;
  EGLSurface surface = EGL_NO_SURFACE;
  if (!surfaceless) {
    const EGLint pbuffer_attributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    surface = eglCreatePbufferSurface(display, config, pbuffer_attributes);
    if (surface == EGL_NO_SURFACE) throw fail(tr("EGL could not create a 1x1 pbuffer"));
    egl_surface_ = surface;
  }
  if (!eglMakeCurrent(display, surface, surface, context))
    throw fail(tr("EGL could not make its context current"));
  backend_ = GlBackend::egl;
  try {
    load_gl_functions(egl_resolve);
    check_version("EGL");
  } catch (...) {
    release();
    throw;
  }
}

void OffscreenContext::create_osmesa() {
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
    throw Error(ErrorKind::gl, tr("OSMesa could not create an OpenGL 3.3 core context "
                                  "(is libosmesa6 Mesa's gallium build with llvmpipe?)"));
  osmesa_context_ = context;
  // The context's own 1x1 buffer only makes it current: renderers draw into their own FBOs.
  if (!OSMesaMakeCurrent(context, buffer_, GL_UNSIGNED_BYTE, 1, 1)) {
    release();
    throw Error(ErrorKind::gl, tr("OSMesa could not make its OpenGL context current"));
  }
  backend_ = GlBackend::osmesa;
  try {
    load_gl_functions(osmesa_resolve);
    check_version("OSMesa");
  } catch (...) {
    release();
    throw;
  }
}

void OffscreenContext::release() {
  if (osmesa_context_) OSMesaDestroyContext(static_cast<OSMesaContext>(osmesa_context_));
  osmesa_context_ = nullptr;
  if (egl_display_) {
    EGLDisplay display = egl_display_;
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (egl_surface_) eglDestroySurface(display, egl_surface_);
    if (egl_context_) eglDestroyContext(display, egl_context_);
    eglTerminate(display);
  }
  egl_display_ = egl_context_ = egl_surface_ = nullptr;
  backend_ = GlBackend::automatic;
}

OffscreenContext::~OffscreenContext() { release(); }

}  // namespace luz::gl
