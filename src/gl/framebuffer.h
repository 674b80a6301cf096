#pragma once
// An offscreen render target: RGBA32F colour (linear radiance, unclamped) and a depth buffer.
#include "core/image.h"
#include "gl/functions.h"
#include "gl/render_target.h"

namespace luz::gl {

class Framebuffer {
public:
  // Throws luz::Error (kind gl) when the driver cannot make a complete float framebuffer.
  Framebuffer(int width, int height);
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  GLuint id() const { return target_.fbo; }
  GLuint colour_texture() const { return target_.colour; }

  // Binds it for drawing and reading, with the viewport covering it.
  void bind() const;
  // The colour buffer as an Image with row 0 at the TOP (GL's rows go bottom-up).
  Image read() const;

private:
  int width_, height_;
  RenderTarget target_;
};

}  // namespace luz::gl
