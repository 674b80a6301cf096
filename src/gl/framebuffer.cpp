#include "gl/framebuffer.h"

#include <vector>

namespace luz::gl {

Framebuffer::Framebuffer(int width, int height)
    : width_(width), height_(height),
      target_(width, height, {GL_RGBA32F, GL_RGBA, GL_FLOAT, "RGBA32F"}) {}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, target_.fbo);
  glViewport(0, 0, width_, height_);
}

Image Framebuffer::read() const {
  std::vector<float> rgba(size_t(width_) * height_ * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target_.fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rgba.data());
  Image image(width_, height_);
  for (int y = 0; y < height_; ++y) {
    const float* row = &rgba[size_t(height_ - 1 - y) * width_ * 4];  // GL row 0 is the bottom
    for (int x = 0; x < width_; ++x)
      image.at(x, y) = Rgb(row[4 * x], row[4 * x + 1], row[4 * x + 2]);
  }
  return image;
}

}  // namespace luz::gl
