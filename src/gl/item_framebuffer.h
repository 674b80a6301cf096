#pragma once
// An offscreen item buffer: one unsigned integer per pixel (GL_R32UI colour attachment) and a
// 32-bit float depth buffer. Radiosity renders patch IDs into it (the hemicube of Cohen and
// Greenberg 1985, the cube around a point light); 0 means "no patch".
#include <cstdint>
#include <vector>

#include "gl/functions.h"
#include "gl/render_target.h"

namespace luz::gl {

class ItemFramebuffer {
public:
  // Throws luz::Error (kind gl) when the driver cannot make a complete R32UI framebuffer.
  ItemFramebuffer(int width, int height);
  ItemFramebuffer(const ItemFramebuffer&) = delete;
  ItemFramebuffer& operator=(const ItemFramebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  GLuint id_texture() const { return target_.colour; }  // for an overlay (usampler2D)

  // Binds it for drawing and clears IDs to 0 and depth to the far plane.
  void bind_and_clear() const;
  // Reads every ID, in GL's row order (row 0 at the BOTTOM), into `out` (resized).
  void read(std::vector<uint32_t>& out) const;
  // Reads the window-space depth (0 near .. 1 far) in the same order.
  void read_depth(std::vector<float>& out) const;

private:
  int width_, height_;
  RenderTarget target_;
};

}  // namespace luz::gl
