#pragma once
// An OpenGL 3.3 core context in a resizable GLFW window, for the viewer. Creating it makes the
// context current on this thread and loads the GL function table through glfwGetProcAddress.
// GLFW stays inside window_context.cpp; the viewer's ImGui backend gets the raw GLFWwindow*.
#include <string>

#include <glm/vec2.hpp>

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
  void swap();
  bool should_close() const;
  void poll();
  GLFWwindow* handle() const { return window_; }

  // True when GLFW can reach a display (X11 or Wayland), i.e. a window could be opened.
  static bool display_available();

private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace luz::gl
