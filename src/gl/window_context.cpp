#include "gl/window_context.h"

#include "gl/functions.h"  // before GLFW: GLFW_INCLUDE_NONE keeps GLFW from including GL

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <string>

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

void WindowContext::swap() { glfwSwapBuffers(window_); }
bool WindowContext::should_close() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void WindowContext::poll() { glfwPollEvents(); }

}  // namespace luz::gl
