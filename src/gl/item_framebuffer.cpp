#include "gl/item_framebuffer.h"

#include <fmt/format.h>

#include "core/error.h"

namespace luz::gl {

ItemFramebuffer::ItemFramebuffer(int width, int height) : width_(width), height_(height) {
  if (width <= 0 || height <= 0)
    throw Error(ErrorKind::bad_value, fmt::format("item buffer size {}x{} is empty", width, height));

  glGenTextures(1, &ids_);
  glBindTexture(GL_TEXTURE_2D, ids_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, width, height, 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
               nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // integers: no filtering
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);

  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);

  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, ids_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(1, &depth_);
    glDeleteTextures(1, &ids_);
    throw Error(ErrorKind::gl, fmt::format("a {}x{} R32UI item buffer is incomplete (status "
                                           "0x{:x}) on {}", width, height, status,
                                           gl_version_string()));
  }
}

ItemFramebuffer::~ItemFramebuffer() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &depth_);
  glDeleteTextures(1, &ids_);
}

void ItemFramebuffer::bind_and_clear() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
  // An integer attachment must be cleared with glClearBufferuiv (glClear's colour is float).
  const GLuint none[4] = {0, 0, 0, 0};
  const float far_depth = 1.0f;
  glClearBufferuiv(GL_COLOR, 0, none);
  glClearBufferfv(GL_DEPTH, 0, &far_depth);
}

void ItemFramebuffer::read(std::vector<uint32_t>& out) const {
  out.resize(size_t(width_) * size_t(height_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width_, height_, GL_RED_INTEGER, GL_UNSIGNED_INT, out.data());
}

void ItemFramebuffer::read_depth(std::vector<float>& out) const {
  out.resize(size_t(width_) * size_t(height_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
}

}  // namespace luz::gl
