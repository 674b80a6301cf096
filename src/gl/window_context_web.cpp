// The viewer's window in the page: the canvas, through Emscripten's GLFW (3.2), with a WebGL 2
// context (the link's -sMIN_WEBGL_VERSION=2). What the desktop's window_context.cpp does with
// X11 (copying parts of the back buffer, reading the screen) has no counterpart in a browser.
#include "gl/window_context.h"

#include "gl/functions.h"  // before GLFW: GLFW_INCLUDE_NONE keeps GLFW from including GL

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <utility>

#include <emscripten.h>
#include <emscripten/html5.h>

#include "core/error.h"
#include "core/i18n.h"

namespace luz::gl {

namespace {

GlProc resolve(const char* name) { return reinterpret_cast<GlProc>(emscripten_webgl_get_proc_address(name)); }

WindowContext::FramePass page_pass;  // the viewer's, for as long as the page shows it

// The page's line under the canvas.
EM_JS(void, show_page_status, (const char* text), {
  const status = document.getElementById('status');
  if (status) status.textContent = UTF8ToString(text);
});

void browser_frame() {
  if (page_pass && page_pass()) {  // the viewer quit (Esc): the page keeps its last picture
    emscripten_cancel_main_loop();
    page_pass = nullptr;
    show_page_status(i18n::tr("Luz has ended: reload the page to start it again."));
  }
}

}  // namespace

bool WindowContext::display_available() { return true; }

WindowContext::WindowContext(int width, int height, const std::string& title) {
  if (glfwInit() != GLFW_TRUE) throw Error(ErrorKind::gl, i18n::tr("This browser gives no WebGL 2 context."));
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) throw Error(ErrorKind::gl, i18n::tr("This browser gives no WebGL 2 context."));
  glfwMakeContextCurrent(window_);
  // Float colour buffers: the local models draw radiance in RGBA32F, as on the desktop.
  if (!emscripten_webgl_enable_extension(emscripten_webgl_get_current_context(), "EXT_color_buffer_float")) {
    glfwDestroyWindow(window_);
    throw Error(ErrorKind::gl,
                i18n::tr("This browser's WebGL 2 cannot draw into float buffers (EXT_color_buffer_float)."));
  }
  // Transparency blends into them (lighting.glsl's two draws), which WebGL 2 allows with this one.
  emscripten_webgl_enable_extension(emscripten_webgl_get_current_context(), "EXT_float_blend");
  load_gl_functions(resolve);
}

WindowContext::~WindowContext() { glfwDestroyWindow(window_); }

glm::ivec2 WindowContext::framebuffer_size() const {
  glm::ivec2 size(0);
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

glm::vec2 WindowContext::content_scale() const { return glm::vec2(1.0f); }

const char* WindowContext::glsl_version() { return "#version 300 es"; }

// The browser shows the canvas once the frame's callback returns.
void WindowContext::present(std::span<const PixelRect>) {}

std::vector<std::uint8_t> WindowContext::shown_pixels() const {
  throw Error(ErrorKind::gl, i18n::tr("reading what the window shows needs an X11 display"));
}

bool WindowContext::should_close() const { return false; }
void WindowContext::poll() {}

int WindowContext::drive_frames(FramePass pass) {
  page_pass = std::move(pass);
  emscripten_set_main_loop(browser_frame, 0, false);  // 0: at the browser's repaint rate
  return 0;
}

bool WindowContext::wait(std::optional<std::chrono::steady_clock::time_point> until) {
  return until && std::chrono::steady_clock::now() >= *until;
}

}  // namespace luz::gl
