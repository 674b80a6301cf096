#include "app/models/radiosity/item_buffer_texture.h"

#include <algorithm>
#include <string>

#include <fmt/format.h>
#include <glm/vec4.hpp>

namespace luz::app {

ItemBufferTexture::ItemBufferTexture() { glGenVertexArrays(1, &empty_vertex_array_); }

ItemBufferTexture::~ItemBufferTexture() {
  if (empty_vertex_array_) glDeleteVertexArrays(1, &empty_vertex_array_);
}

void ItemBufferTexture::update(const Hemicube& hemicube) {
  // Two top faces across (the cross is 4 half-widths wide), but never more than a panel shows.
  const int size = std::min(2 * hemicube.resolution(), 512);
  if (!target_ || target_->width() != size) target_ = std::make_unique<gl::Framebuffer>(size, size);
  target_->bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  program_.use();
  program_.set("u_items", 0);
  program_.set("u_size", glm::vec2(float(size)));
  for (int face = 0; face < Hemicube::kFaces; ++face) {
    const Hemicube::Rect r = hemicube.face_rect(face);
    program_.set(fmt::format("u_faces[{}]", face), glm::vec4(float(r.x), float(r.y), float(r.width), float(r.height)));
  }
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, hemicube.item_texture());
  glBindVertexArray(empty_vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace luz::app
