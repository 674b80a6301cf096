#pragma once
// The viewer's picture of a hemicube (slide 37): the item buffer of the last shot, its five faces
// unfolded into a cross, each patch ID in its own false colour (shaders/item_buffer_view.*), in
// a small texture the panel shows with ImGui::Image.
#include <memory>

#include "gl/framebuffer.h"
#include "gl/shader.h"
#include "radiosity/hemicube.h"

namespace luz::app {

class ItemBufferTexture {
public:
  ItemBufferTexture();  // needs a current GL context
  ~ItemBufferTexture();
  ItemBufferTexture(const ItemBufferTexture&) = delete;
  ItemBufferTexture& operator=(const ItemBufferTexture&) = delete;

  // Redraws the cross from the hemicube's item texture (what its last row() drew). Leaves the
  // default framebuffer bound and no program in use.
  void update(const Hemicube& hemicube);
  unsigned texture() const { return target_ ? target_->colour_texture() : 0; }
  int size() const { return target_ ? target_->width() : 0; }

private:
  gl::Program program_{{"item_buffer_view.vert", "item_buffer_view.frag"}};
  std::unique_ptr<gl::Framebuffer> target_;
  GLuint empty_vertex_array_ = 0;  // core profile draws need one bound, even with no attributes
};

}  // namespace luz::app
