#include "radiosity/item_buffer.h"

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "core/error.h"

namespace luz {

PatchItems::PatchItems(const PatchMesh& mesh) {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  upload(mesh);
}

void PatchItems::upload(const PatchMesh& mesh) {
  std::vector<glm::vec3> corners;
  corners.reserve(mesh.size() * 3);
  for (const Patch& p : mesh.patches)
    for (const uint32_t v : p.vertices) corners.push_back(mesh.vertices[v]);
  vertex_count_ = GLsizei(corners.size());

  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(corners.size() * sizeof(glm::vec3)), corners.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

PatchItems::~PatchItems() {
  if (vao_) glDeleteVertexArrays(1, &vao_);
  if (vbo_) glDeleteBuffers(1, &vbo_);
}

void PatchItems::begin() const {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);  // back faces must occlude; the shader gives them ID 0
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  program_.use();
  glBindVertexArray(vao_);
}

void PatchItems::draw(const glm::mat4& view_projection) const {
  program_.set("u_view_projection", view_projection);
  glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
}

void PatchItems::end() const {
  glBindVertexArray(0);
  glUseProgram(0);
}

glm::vec3 any_tangent(const glm::vec3& n) {
  // Cross with the world axis least aligned with n: never degenerate.
  const glm::vec3 a = std::abs(n.x) < std::abs(n.y)
                          ? (std::abs(n.x) < std::abs(n.z) ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1))
                          : (std::abs(n.y) < std::abs(n.z) ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1));
  return glm::normalize(glm::cross(a, n));
}

}  // namespace luz
