#include "gl/framebuffer.h"

#include <vector>

#include <fmt/format.h>

#include "core/error.h"

namespace luz::gl {

Framebuffer::Framebuffer(int width, int height) : width_(width), height_(height) {
  if (width <= 0 || height <= 0)
    throw Error(ErrorKind::bad_value, fmt::format("image size {}x{} is empty", width, height));

  glGenTextures(1, &colour_);
  glBindTexture(GL_TEXTURE_2D, colour_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);

  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);

  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(1, &depth_);
    glDeleteTextures(1, &colour_);
    throw Error(ErrorKind::gl, fmt::format("a {}x{} RGBA32F framebuffer is incomplete (status "
                                           "0x{:x}) on {}", width, height, status,
                                           gl_version_string()));
  }
}

Framebuffer::~Framebuffer() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &depth_);
  glDeleteTextures(1, &colour_);
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

Image Framebuffer::read() const {
  std::vector<float> rgba(size_t(width_) * height_ * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
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
