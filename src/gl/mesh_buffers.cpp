#include "gl/mesh_buffers.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace luz::gl {

namespace {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;  // (0, 0) when the mesh has no TEXCOORD_0
  Rgb colour;    // COLOR_0, white when the mesh has none
};

}  // namespace

MeshBuffers::MeshBuffers(const Mesh& mesh) {
  std::vector<Vertex> vertices(mesh.positions.size());
  for (size_t i = 0; i < vertices.size(); ++i) {
    vertices[i].position = mesh.positions[i];
    vertices[i].normal = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0.0f);
    vertices[i].uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f);
    vertices[i].colour = i < mesh.colors.size() ? mesh.colors[i] : Rgb(1.0f);
  }
  index_count_ = GLsizei(mesh.indices.size());

  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(),
               GL_STATIC_DRAW);
  glGenBuffers(1, &ebo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);  // recorded in the vertex array
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);

  const auto attribute = [](GLuint location, GLint size, size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offset));
  };
  attribute(position_location, 3, offsetof(Vertex, position));
  attribute(normal_location, 3, offsetof(Vertex, normal));
  attribute(uv_location, 2, offsetof(Vertex, uv));
  attribute(colour_location, 3, offsetof(Vertex, colour));

  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

MeshBuffers::~MeshBuffers() { release(); }

MeshBuffers::MeshBuffers(MeshBuffers&& other) noexcept
    : vao_(std::exchange(other.vao_, 0)), vbo_(std::exchange(other.vbo_, 0)),
      ebo_(std::exchange(other.ebo_, 0)), index_count_(std::exchange(other.index_count_, 0)) {}

MeshBuffers& MeshBuffers::operator=(MeshBuffers&& other) noexcept {
  if (this != &other) {
    release();
    vao_ = std::exchange(other.vao_, 0);
    vbo_ = std::exchange(other.vbo_, 0);
    ebo_ = std::exchange(other.ebo_, 0);
    index_count_ = std::exchange(other.index_count_, 0);
  }
  return *this;
}

void MeshBuffers::release() {
  if (vao_) glDeleteVertexArrays(1, &vao_);
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (ebo_) glDeleteBuffers(1, &ebo_);
  vao_ = vbo_ = ebo_ = 0;
}

void MeshBuffers::draw() const {
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

}  // namespace luz::gl
