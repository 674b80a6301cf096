#pragma once
// An OpenGL 3.3 core context in a resizable GLFW window, for the viewer (in the page, the
// canvas's WebGL 2 through Emscripten's GLFW: window_context_web.cpp). Creating it makes the
// context current on this thread and loads the GL function table through glfwGetProcAddress.
// GLFW stays inside window_context.cpp; the viewer's ImGui backend gets the raw GLFWwindow*.
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "gl/pixel_rect.h"

struct GLFWwindow;

namespace luz::gl {

class WindowContext {
public:
  // Throws luz::Error (kind gl) when there is no display or no 3.3 core context.
  WindowContext(int width, int height, const std::string& title);
  ~WindowContext();
  WindowContext(const WindowContext&) = delete;
  WindowContext& operator=(const WindowContext&) = delete;

  glm::ivec2 framebuffer_size() const;  // in pixels (differs from the window size on HiDPI)
  glm::vec2 content_scale() const;      // the screen's scale for text (HiDPI: 2); 1 in the page
  // The #version line of the context's shading language, for Dear ImGui's renderer.
  static const char* glsl_version();

  // Shows the frame drawn into the back buffer. `changed` says where it differs from the frame
  // shown before (empty: anywhere). On Mesa's software rasteriser presenting is a copy of the
  // back buffer's pixels to the display, which costs per pixel; there, when the context can
  // copy a part (GLX_MESA_copy_sub_buffer), only the changed rectangles are copied and the back
  // buffer is never swapped, so it still holds every pixel of this frame when the next is
  // drawn (keeps_back_buffer()). Elsewhere the buffers are swapped (a GPU does it for free) and
  // the back buffer's pixels are undefined afterwards.
  void present(std::span<const PixelRect> changed = {});
  bool keeps_back_buffer() const { return copy_sub_buffer_ != nullptr; }

  // What the display shows of the window, read back from the X server (not from GL): RGBA8,
  // rows from the top. Throws luz::Error (kind gl) without an X11 display or when the window is
  // not wholly on the screen.
  std::vector<std::uint8_t> shown_pixels() const;
  bool should_close() const;
  void poll();
  // Between frames with nothing to draw: on the desktop, sleeps until an event comes or `until`
  // passes, and returns true. In the page the browser's repaints call the viewer and events
  // come between them: returns whether `until` has passed (false without one), never waiting.
  bool wait(std::optional<std::chrono::steady_clock::time_point> until);
  GLFWwindow* handle() const { return window_; }

  // True when GLFW can reach a display (X11 or Wayland), i.e. a window could be opened.
  static bool display_available();

  // Who calls the frames: on the desktop a loop calls `pass` until it gives an exit code, and
  // returns that. In the page the browser calls it before each repaint
  // (emscripten_set_main_loop): its main thread must never block, so this returns 0 at once
  // and `pass`, holding what it draws, lives on until it gives an exit code.
  using FramePass = std::function<std::optional<int>()>;
  static int drive_frames(FramePass pass);

private:
  GLFWwindow* window_ = nullptr;
  // GLX's, through glfwGetProcAddress; null where the window swaps.
  using CopySubBuffer = void (*)(void* display, unsigned long drawable, int x, int y, int width, int height);
  CopySubBuffer copy_sub_buffer_ = nullptr;
  [[maybe_unused]] void* display_ = nullptr;      // the X display (Display*); none in the page
  [[maybe_unused]] unsigned long drawable_ = 0;  // the window's GLX drawable
};

}  // namespace luz::gl
