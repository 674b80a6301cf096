#pragma once
// An offscreen render target: RGBA32F colour (linear radiance, unclamped) and a depth buffer;
// for the viewer's pictures also an RGBA8 second colour buffer, the displayed values.
#include "core/image.h"
#include "gl/functions.h"
#include "gl/render_target.h"

namespace luz::gl {

class Framebuffer {
public:
  // Throws luz::Error (kind gl) when the driver cannot make a complete float framebuffer.
  explicit Framebuffer(int width, int height, bool with_display = false);
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  GLuint id() const { return target_.fbo; }
  GLuint colour_texture() const { return target_.colour; }

  // Binds it for drawing and reading, with the viewport covering it: the radiance alone, or
  // (with_display) the radiance and the displayed values, draw buffers 0 and 1.
  void bind() const;
  void bind_with_display() const;
  GLuint display_texture() const { return display_; }  // 0 without
  // The colour buffer as an Image with row 0 at the TOP (GL's rows go bottom-up).
  Image read() const;

private:
  int width_, height_;
  RenderTarget target_;
  GLuint display_ = 0;
};

// The framebuffer and viewport bound when it is made, bound again when it goes: a pass drawing
// into a target of its own leaves its caller's as they were.
class KeptBinding {
public:
  KeptBinding();
  ~KeptBinding();
  KeptBinding(const KeptBinding&) = delete;
  KeptBinding& operator=(const KeptBinding&) = delete;

private:
  GLint framebuffer_ = 0;
  GLint viewport_[4] = {};
};

// The window's framebuffer (0) bound so that a program's output 1, the displayed values, goes to
// its back buffer and output 0, the radiance, nowhere: what LocalRenderer::draw_display draws
// into. False, binding nothing, where the window takes output 0 alone (GL ES). bind_window()
// binds it as usual again (output 0 to the back buffer).
bool bind_window_for_display();
void bind_window();

// Whether the window's framebuffer (0) is multisampled (a driver's forced antialiasing): a blit
// into it then fails, so what is copied elsewhere is drawn instead.
bool window_is_multisampled();

}  // namespace luz::gl
