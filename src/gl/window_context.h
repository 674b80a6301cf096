#pragma once
// An OpenGL 3.3 core context in a resizable GLFW window, for the viewer. Creating it makes the
// context current on this thread and loads the GL function table through glfwGetProcAddress.
// GLFW stays inside window_context.cpp; the viewer's ImGui backend gets the raw GLFWwindow*.
#include <cstdint>
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
  GLFWwindow* handle() const { return window_; }

  // True when GLFW can reach a display (X11 or Wayland), i.e. a window could be opened.
  static bool display_available();

private:
  GLFWwindow* window_ = nullptr;
  // GLX's, through glfwGetProcAddress; null where the window swaps.
  using CopySubBuffer = void (*)(void* display, unsigned long drawable, int x, int y, int width, int height);
  CopySubBuffer copy_sub_buffer_ = nullptr;
  void* display_ = nullptr;      // the X display (Display*)
  unsigned long drawable_ = 0;  // the window's GLX drawable
};

}  // namespace luz::gl
