#include "gl/window_context.h"

#include "gl/functions.h"  // before GLFW: GLFW_INCLUDE_NONE keeps GLFW from including GL

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <bit>
#include <string>
#include <string_view>

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <fmt/format.h>

#include "core/error.h"
#include "core/i18n.h"

namespace luz::gl {

using i18n::tr;
using i18n::trf;

namespace {

std::string last_glfw_error;  // GLFW reports through a callback; kept for our messages
int open_windows = 0;         // glfwTerminate only when no window needs GLFW any more

void on_glfw_error(int code, const char* description) {
  last_glfw_error = trf("{} (GLFW error 0x{:x})", description, code);
}

bool init_glfw() {
  glfwSetErrorCallback(on_glfw_error);
  return glfwInit() == GLFW_TRUE;  // a no-op returning true when already initialised
}

// Mesa's software rasterisers: their swap copies the window's pixels on the CPU.
bool software_renderer() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string_view r = renderer ? renderer : "";
  return r.find("llvmpipe") != r.npos || r.find("softpipe") != r.npos || r.find("Software Rasterizer") != r.npos;
}

}  // namespace

bool WindowContext::display_available() {
  const bool ok = init_glfw();
  if (ok && open_windows == 0) glfwTerminate();
  return ok;
}

WindowContext::WindowContext(int width, int height, const std::string& title) {
  if (!init_glfw())
    throw Error(ErrorKind::gl, trf("no display to open a window on: {} (use `luz render` for pictures "
                                   "without one)", last_glfw_error));
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);  // macOS needs it; harmless elsewhere
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    if (open_windows == 0) glfwTerminate();
    throw Error(ErrorKind::gl, trf("cannot open a window with an OpenGL 3.3 core context: {}",
                                   last_glfw_error));
  }
  ++open_windows;
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  try {
    load_gl_functions(glfwGetProcAddress);
  } catch (...) {
    glfwDestroyWindow(window_);
    if (--open_windows == 0) glfwTerminate();
    throw;
  }
  // GLX's own functions through its glXGetProcAddress, not GLFW's X11 handles: Debian also
  // ships a GLFW built for Wayland only, which has none.
  if (software_renderer() && glfwExtensionSupported("GLX_MESA_copy_sub_buffer")) {
    using CurrentDisplay = Display* (*)();
    using CurrentDrawable = unsigned long (*)();
    const auto display = reinterpret_cast<CurrentDisplay>(glfwGetProcAddress("glXGetCurrentDisplay"));
    const auto drawable = reinterpret_cast<CurrentDrawable>(glfwGetProcAddress("glXGetCurrentDrawable"));
    const auto copy = reinterpret_cast<CopySubBuffer>(glfwGetProcAddress("glXCopySubBufferMESA"));
    if (display && drawable && copy && display() && drawable()) {
      display_ = display();
      drawable_ = drawable();
      copy_sub_buffer_ = copy;
    }
  }
}

WindowContext::~WindowContext() {
  glfwDestroyWindow(window_);
  if (--open_windows == 0) glfwTerminate();
}

glm::ivec2 WindowContext::framebuffer_size() const {
  glm::ivec2 size(0);
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

const char* WindowContext::glsl_version() { return "#version 330 core"; }

glm::vec2 WindowContext::content_scale() const {
  glm::vec2 scale(1.0f);
  glfwGetWindowContentScale(window_, &scale.x, &scale.y);
  return scale;
}

void WindowContext::present(std::span<const PixelRect> changed) {
  if (!copy_sub_buffer_) {
    glfwSwapBuffers(window_);
    return;
  }
  if (changed.empty()) {
    const glm::ivec2 size = framebuffer_size();
    copy_sub_buffer_(display_, drawable_, 0, 0, size.x, size.y);
    return;
  }
  for (const PixelRect& r : changed)
    if (!r.empty()) copy_sub_buffer_(display_, drawable_, r.x, r.y, r.width, r.height);
}

std::vector<std::uint8_t> WindowContext::shown_pixels() const {
  using CurrentDisplay = Display* (*)();
  const auto current = reinterpret_cast<CurrentDisplay>(glfwGetProcAddress("glXGetCurrentDisplay"));
  Display* display = current ? current() : nullptr;
  if (!display) throw Error(ErrorKind::gl, tr("reading what the window shows needs an X11 display"));
  int x = 0, y = 0;
  glfwGetWindowPos(window_, &x, &y);
  const glm::ivec2 size = framebuffer_size();
  const int screen_w = DisplayWidth(display, DefaultScreen(display));
  const int screen_h = DisplayHeight(display, DefaultScreen(display));
  if (x < 0 || y < 0 || x + size.x > screen_w || y + size.y > screen_h || size.x <= 0 || size.y <= 0)
    throw Error(ErrorKind::gl, tr("the window is not wholly on the screen: what it shows cannot be read"));
  // The same connection as GL's presents: the server has drawn them before it answers this.
  XSync(display, False);
  XImage* image = XGetImage(display, DefaultRootWindow(display), x, y, unsigned(size.x), unsigned(size.y),
                            AllPlanes, ZPixmap);
  if (!image) throw Error(ErrorKind::gl, tr("the X server did not return the window's pixels"));
  const auto channel = [](unsigned long pixel, unsigned long mask) {
    if (mask == 0) return std::uint8_t(0);
    const unsigned long value = (pixel & mask) >> std::countr_zero(mask);
    return std::uint8_t(value * 255 / (mask >> std::countr_zero(mask)));
  };
  std::vector<std::uint8_t> rgba(size_t(size.x) * size.y * 4);
  for (int row = 0; row < size.y; ++row)
    for (int column = 0; column < size.x; ++column) {
      const unsigned long pixel = XGetPixel(image, column, row);
      std::uint8_t* out = &rgba[(size_t(row) * size.x + column) * 4];
      out[0] = channel(pixel, image->red_mask);
      out[1] = channel(pixel, image->green_mask);
      out[2] = channel(pixel, image->blue_mask);
      out[3] = 255;
    }
  XDestroyImage(image);
  return rgba;
}

bool WindowContext::should_close() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void WindowContext::poll() { glfwPollEvents(); }

int WindowContext::drive_frames(FramePass pass) {
  for (;;)
    if (const std::optional<int> exit_code = pass()) return *exit_code;
}

bool WindowContext::wait(std::optional<std::chrono::steady_clock::time_point> until) {
  if (!until) {
    glfwWaitEvents();
    return true;
  }
  const double left = std::chrono::duration<double>(*until - std::chrono::steady_clock::now()).count();
  if (left > 0.0) glfwWaitEventsTimeout(left);
  return true;
}

}  // namespace luz::gl
