#include "radiosity/item_buffer.h"

#include <cassert>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "gl/glsl_dialect.h"

namespace luz {

PatchItems::PatchItems(const PatchMesh& mesh)
    : unindexed_(gl::current_glsl_dialect() == gl::GlslDialect::es_300) {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glGenBuffers(1, &ebo_);
  upload(mesh);
  if (!unindexed_) compile_atlas_program();
}

void PatchItems::compile_atlas_program() const {
  if (!atlas_program_) atlas_program_.emplace(std::vector<std::string>{"item_buffer_atlas.vert", "item_buffer.frag"});
}

// Indexed, over the mesh's shared vertices: software rasterisers shade each vertex once for the
// half a dozen elements around it instead of three times per element. GLSL ES names a patch by
// its vertices' gl_VertexID / 3 instead of gl_PrimitiveID, so there each element has its own three.
void PatchItems::upload(const PatchMesh& mesh) {
  std::vector<uint32_t> indices;
  indices.reserve(mesh.size() * 3);
  for (const Patch& p : mesh.patches)
    for (const uint32_t v : p.vertices) indices.push_back(v);
  std::vector<glm::vec3> corners;
  if (unindexed_) {
    corners.reserve(indices.size());
    for (const uint32_t v : indices) corners.push_back(mesh.vertices[v]);
  }
  const std::vector<glm::vec3>& vertices = unindexed_ ? corners : mesh.vertices;
  count_ = GLsizei(indices.size());

  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(glm::vec3)), vertices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);  // recorded in the vertex array
  if (!unindexed_)
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

PatchItems::~PatchItems() {
  if (vao_) glDeleteVertexArrays(1, &vao_);
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (ebo_) glDeleteBuffers(1, &ebo_);
}

void PatchItems::begin() const {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);  // back faces must occlude; the shader gives them ID 0
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  if (glPolygonMode) glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);  // GL ES has only filled polygons
  program_.use();
  glBindVertexArray(vao_);
}

void PatchItems::draw(const glm::mat4& view_projection) const {
  program_.set("u_view_projection", view_projection);
  draw_triangles(1);
}

void PatchItems::draw_triangles(GLsizei instances) const {
  if (unindexed_) glDrawArraysInstanced(GL_TRIANGLES, 0, count_, instances);
  else if (instances == 1) glDrawElements(GL_TRIANGLES, count_, GL_UNSIGNED_INT, nullptr);
  else glDrawElementsInstanced(GL_TRIANGLES, count_, GL_UNSIGNED_INT, nullptr, instances);
}

// A face's clip coordinates c land in its rectangle of the atlas: x_atlas = sx x + ox w, so that
// after the divide x_atlas / w = sx (x / w) + ox maps the face's [-1, 1] onto its pixels.
void PatchItems::draw_atlas(std::span<const AtlasFace> faces, int atlas_width, int atlas_height) const {
  assert(faces.size() <= size_t(kMaxAtlasFaces));
  compile_atlas_program();
  atlas_program_->use();
  for (size_t f = 0; f < faces.size(); ++f) {
    const AtlasFace& face = faces[f];
    const float sx = float(face.width) / float(atlas_width);
    const float sy = float(face.height) / float(atlas_height);
    const float ox = float(2 * face.x + face.width) / float(atlas_width) - 1.0f;
    const float oy = float(2 * face.y + face.height) / float(atlas_height) - 1.0f;
    glm::mat4 to_atlas(1.0f);  // column-major: column 3 holds what w adds to each row
    to_atlas[0][0] = sx;
    to_atlas[1][1] = sy;
    to_atlas[3][0] = ox;
    to_atlas[3][1] = oy;
    // Appended, not "[" + ...: GCC 12 warns falsely (-Wrestrict) on that inlined operator+.
    std::string index = "[";
    index += std::to_string(f);
    index += ']';
    atlas_program_->set("u_face_view_projection" + index, face.view_projection);
    atlas_program_->set("u_face_to_atlas" + index, to_atlas);
  }
  for (int plane = 0; plane < 4; ++plane) glEnable(GLenum(GL_CLIP_DISTANCE0 + plane));
  glViewport(0, 0, atlas_width, atlas_height);
  draw_triangles(GLsizei(faces.size()));
  for (int plane = 0; plane < 4; ++plane) glDisable(GLenum(GL_CLIP_DISTANCE0 + plane));
  program_.use();
}

void PatchItems::end() const {
  glDisable(GL_DEPTH_TEST);  // GL's default again; begin()'s other settings are GL's defaults
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
