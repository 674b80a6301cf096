#pragma once
// The hemicube's reduction on the GPU (slide 37's F_ij = sum of the delta form factors of the
// pixels that show j): every pixel of the item buffer is drawn as a point onto texel j of a float
// target, where additive blending sums it, and only that target, one float per element, is read
// back instead of the whole item buffer. OpenGL 3.3: no compute shaders are needed.
#include <cstdint>
#include <memory>
#include <vector>

#include "gl/functions.h"
#include "gl/render_target.h"
#include "gl/shader.h"

namespace luz {

class GpuRowSums {
public:
  // `weights`: the delta form factor of every pixel of the atlas (width x height, GL row order).
  GpuRowSums(const std::vector<float>& weights, int atlas_width, int atlas_height);
  ~GpuRowSums();
  GpuRowSums(const GpuRowSums&) = delete;
  GpuRowSums& operator=(const GpuRowSums&) = delete;

  // The sums of the item texture (an R32UI atlas of the same size) for elements 0 .. count-1.
  // Leaves the sums framebuffer bound. Valid until the next call.
  const std::vector<float>& sum(GLuint item_texture, size_t count);

private:
  static constexpr int kSumsWidth = 1024;
  void make_target(size_t count);

  gl::Program program_{{"form_factor_sums.vert", "form_factor_sums.frag"}};
  int atlas_pixels_;
  GLuint weights_texture_ = 0, vao_ = 0;
  std::unique_ptr<gl::RenderTarget> sums_;
  int rows_ = 0;
  std::vector<float> values_;
};

}  // namespace luz
