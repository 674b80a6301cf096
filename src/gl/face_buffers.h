#pragma once
// One core::Mesh on the GPU for flat shading: its triangles unindexed, each vertex carrying its
// own position (location 0) and uv (2) and the whole triangle's three corners (4, 5, 6) and three
// COLOR_0 values (7, 8, 9). A vertex shader sees one vertex; with the triangle beside it, it
// evaluates the formula once for the face (shaders/flat.vert) as a geometry shader would, and
// GLSL ES 3.00 (the page's WebGL 2), which has no geometry stage, draws it the same way.
#include "core/scene.h"
#include "gl/functions.h"

namespace luz::gl {

class FaceBuffers {
public:
  static constexpr GLuint position_location = 0;
  static constexpr GLuint uv_location = 2;
  static constexpr GLuint first_corner_location = 4;  // 4, 5, 6
  static constexpr GLuint first_colour_location = 7;  // 7, 8, 9

  explicit FaceBuffers(const Mesh& mesh);
  ~FaceBuffers();
  FaceBuffers(FaceBuffers&& other) noexcept;
  FaceBuffers& operator=(FaceBuffers&& other) noexcept;
  FaceBuffers(const FaceBuffers&) = delete;
  FaceBuffers& operator=(const FaceBuffers&) = delete;

  // Draws the triangles with the program in use.
  void draw() const;

private:
  void release();
  GLuint vao_ = 0, vbo_ = 0;
  GLsizei vertex_count_ = 0;
};

}  // namespace luz::gl
