#pragma once
// One core::Mesh on the GPU: a vertex array with position (location 0), normal (1), uv (2) and
// COLOR_0 (3) from one interleaved buffer, and an element buffer of its triangles.
#include "core/scene.h"
#include "gl/functions.h"

namespace luz::gl {

class MeshBuffers {
public:
  static constexpr GLuint position_location = 0;
  static constexpr GLuint normal_location = 1;
  static constexpr GLuint uv_location = 2;
  static constexpr GLuint colour_location = 3;

  explicit MeshBuffers(const Mesh& mesh);
  ~MeshBuffers();
  MeshBuffers(MeshBuffers&& other) noexcept;
  MeshBuffers& operator=(MeshBuffers&& other) noexcept;
  MeshBuffers(const MeshBuffers&) = delete;
  MeshBuffers& operator=(const MeshBuffers&) = delete;

  // Draws the triangles with the program in use.
  void draw() const;
  GLsizei index_count() const { return index_count_; }

private:
  void release();
  GLuint vao_ = 0, vbo_ = 0, ebo_ = 0;
  GLsizei index_count_ = 0;
};

}  // namespace luz::gl
