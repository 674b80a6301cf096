#include "gl/face_buffers.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace luz::gl {

namespace {

struct FaceVertex {
  glm::vec3 position;
  glm::vec2 uv;           // (0, 0) when the mesh has no TEXCOORD_0
  glm::vec3 corners[3];   // the triangle's positions, in its index order
  Rgb colours[3];         // its COLOR_0 values, white when the mesh has none
};

}  // namespace

FaceBuffers::FaceBuffers(const Mesh& mesh) {
  const auto position = [&](uint32_t i) { return i < mesh.positions.size() ? mesh.positions[i] : glm::vec3(0.0f); };
  const auto uv = [&](uint32_t i) { return i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f); };
  const auto colour = [&](uint32_t i) { return i < mesh.colors.size() ? mesh.colors[i] : Rgb(1.0f); };
  std::vector<FaceVertex> vertices;
  vertices.reserve(mesh.indices.size() / 3 * 3);
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t* corner = &mesh.indices[t];
    for (int k = 0; k < 3; ++k) {
      FaceVertex v;
      v.position = position(corner[k]);
      v.uv = uv(corner[k]);
      for (int j = 0; j < 3; ++j) {
        v.corners[j] = position(corner[j]);
        v.colours[j] = colour(corner[j]);
      }
      vertices.push_back(v);
    }
  }
  vertex_count_ = GLsizei(vertices.size());

  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(FaceVertex)), vertices.data(),
               GL_STATIC_DRAW);
  const auto attribute = [](GLuint location, GLint size, size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, sizeof(FaceVertex),
                          reinterpret_cast<const void*>(offset));
  };
  attribute(position_location, 3, offsetof(FaceVertex, position));
  attribute(uv_location, 2, offsetof(FaceVertex, uv));
  for (GLuint j = 0; j < 3; ++j) {
    attribute(first_corner_location + j, 3, offsetof(FaceVertex, corners) + j * sizeof(glm::vec3));
    attribute(first_colour_location + j, 3, offsetof(FaceVertex, colours) + j * sizeof(Rgb));
  }
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

FaceBuffers::~FaceBuffers() { release(); }

FaceBuffers::FaceBuffers(FaceBuffers&& other) noexcept
    : vao_(std::exchange(other.vao_, 0)), vbo_(std::exchange(other.vbo_, 0)),
      vertex_count_(std::exchange(other.vertex_count_, 0)) {}

FaceBuffers& FaceBuffers::operator=(FaceBuffers&& other) noexcept {
  if (this != &other) {
    release();
    vao_ = std::exchange(other.vao_, 0);
    vbo_ = std::exchange(other.vbo_, 0);
    vertex_count_ = std::exchange(other.vertex_count_, 0);
  }
  return *this;
}

void FaceBuffers::release() {
  if (vao_) glDeleteVertexArrays(1, &vao_);
  if (vbo_) glDeleteBuffers(1, &vbo_);
  vao_ = vbo_ = 0;
}

void FaceBuffers::draw() const {
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
  glBindVertexArray(0);
}

}  // namespace luz::gl
