#include "gl/item_framebuffer.h"

namespace luz::gl {

ItemFramebuffer::ItemFramebuffer(int width, int height)
    : width_(width), height_(height),
      target_(width, height, {GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, "R32UI item"}) {}

void ItemFramebuffer::bind_and_clear() const {
  glBindFramebuffer(GL_FRAMEBUFFER, target_.fbo);
  glViewport(0, 0, width_, height_);
  // An integer attachment must be cleared with glClearBufferuiv (glClear's colour is float).
  const GLuint none[4] = {0, 0, 0, 0};
  const float far_depth = 1.0f;
  glClearBufferuiv(GL_COLOR, 0, none);
  glClearBufferfv(GL_DEPTH, 0, &far_depth);
}

void ItemFramebuffer::read(std::vector<uint32_t>& out) const {
  out.resize(size_t(width_) * size_t(height_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target_.fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width_, height_, GL_RED_INTEGER, GL_UNSIGNED_INT, out.data());
}

void ItemFramebuffer::read_depth(std::vector<float>& out) const {
  out.resize(size_t(width_) * size_t(height_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target_.fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
}

}  // namespace luz::gl
