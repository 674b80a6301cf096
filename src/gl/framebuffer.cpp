#include "gl/framebuffer.h"

#include <vector>

#include "core/error.h"
#include "core/i18n.h"

namespace luz::gl {

Framebuffer::Framebuffer(int width, int height, bool with_display)
    : width_(width), height_(height),
      target_(width, height, {GL_RGBA32F, GL_RGBA, GL_FLOAT, "RGBA32F"}) {
  if (!with_display) return;
  glGenTextures(1, &display_);
  glBindTexture(GL_TEXTURE_2D, display_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, target_.fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, display_, 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteTextures(1, &display_);
    throw Error(ErrorKind::gl, i18n::trf("a {}x{} {} framebuffer is incomplete (status 0x{:x}) on {}", width,
                                         height, "RGBA32F + RGBA8", status, gl_version_string()));
  }
}

Framebuffer::~Framebuffer() {
  if (display_) glDeleteTextures(1, &display_);
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, target_.fbo);
  glViewport(0, 0, width_, height_);
  const GLenum radiance = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &radiance);
}

void Framebuffer::bind_with_display() const {
  glBindFramebuffer(GL_FRAMEBUFFER, target_.fbo);
  glViewport(0, 0, width_, height_);
  const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(display_ ? 2 : 1, both);
}

// GL ES (the page's WebGL 2) gives the window one draw buffer, taking output 0 alone, and has no
// glDrawBuffer: there the displayed values go through the float picture and display.frag.
bool bind_window_for_display() {
  if (!glDrawBuffer) return false;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const GLenum outputs[2] = {GL_NONE, GL_BACK_LEFT};
  glDrawBuffers(2, outputs);
  return true;
}

void bind_window() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (glDrawBuffer) {
    glDrawBuffer(GL_BACK);
  } else {
    const GLenum back = GL_BACK;  // GL ES's one name for the window's buffer
    glDrawBuffers(1, &back);
  }
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

bool window_is_multisampled() {
  GLint previous = 0, sample_buffers = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glGetIntegerv(GL_SAMPLE_BUFFERS, &sample_buffers);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previous));
  return sample_buffers != 0;
}

KeptBinding::KeptBinding() {
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &framebuffer_);
  glGetIntegerv(GL_VIEWPORT, viewport_);
}

KeptBinding::~KeptBinding() {
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
}

}  // namespace luz::gl
