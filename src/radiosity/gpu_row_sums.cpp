#include "radiosity/gpu_row_sums.h"

#include <algorithm>

namespace luz {

GpuRowSums::GpuRowSums(const std::vector<float>& weights, int atlas_width, int atlas_height)
    : atlas_pixels_(atlas_width * atlas_height) {
  glGenTextures(1, &weights_texture_);
  glBindTexture(GL_TEXTURE_2D, weights_texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, atlas_width, atlas_height, 0, GL_RED, GL_FLOAT, weights.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenVertexArrays(1, &vao_);  // core profile draws need one, even with no attributes
}

GpuRowSums::~GpuRowSums() {
  glDeleteTextures(1, &weights_texture_);
  glDeleteVertexArrays(1, &vao_);
}

// The target grows with the mesh (adaptive subdivision adds elements between rows).
void GpuRowSums::make_target(size_t count) {
  const int rows = int((count + kSumsWidth - 1) / kSumsWidth);
  if (sums_ && rows <= rows_) return;
  rows_ = std::max(rows, 1);
  sums_ = std::make_unique<gl::RenderTarget>(kSumsWidth, rows_,
                                             gl::ColourFormat{GL_R32F, GL_RED, GL_FLOAT, "R32F sums"});
}

const std::vector<float>& GpuRowSums::sum(GLuint item_texture, size_t count) {
  make_target(count);
  glBindFramebuffer(GL_FRAMEBUFFER, sums_->fbo);
  glViewport(0, 0, kSumsWidth, rows_);
  const float zero[4] = {0, 0, 0, 0};
  glClearBufferfv(GL_COLOR, 0, zero);

  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  program_.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, item_texture);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, weights_texture_);
  program_.set("u_items", 0);
  program_.set("u_weights", 1);
  program_.set("u_sums_width", kSumsWidth);
  program_.set("u_sums_size", glm::vec2(kSumsWidth, rows_));
  glBindVertexArray(vao_);
  glDrawArrays(GL_POINTS, 0, atlas_pixels_);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glDisable(GL_BLEND);
  glUseProgram(0);

  values_.resize(size_t(kSumsWidth) * size_t(rows_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, sums_->fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, kSumsWidth, rows_, GL_RED, GL_FLOAT, values_.data());
  values_.resize(count);
  return values_;
}

}  // namespace luz
