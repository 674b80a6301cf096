#include "app/models/whitted/ray_tree_drawing.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

namespace luz::app {

namespace {

// One vertex of a segment's quad: both ends, which end and side this is, the colour and whether
// it is dashed (see shaders/ray_tree.vert).
struct Vertex {
  glm::vec3 from;
  glm::vec3 to;
  float end, side;
  float r, g, b, dashed;
};

}  // namespace

glm::vec3 ray_colour(rt::RayKind kind, bool blocked_shadow) {
  switch (kind) {
    case rt::RayKind::primary: return {1.0f, 1.0f, 1.0f};          // white: from the eye
    case rt::RayKind::shadow:                                       // yellow: toward a light
      return blocked_shadow ? glm::vec3(0.6f, 0.45f, 0.1f) : glm::vec3(1.0f, 0.85f, 0.15f);
    case rt::RayKind::reflected: return {0.25f, 0.9f, 1.0f};       // cyan: kr
    case rt::RayKind::transmitted: return {1.0f, 0.35f, 0.85f};    // magenta: kt
  }
  return {1.0f, 0.0f, 0.0f};
}

RayTreeDrawing::RayTreeDrawing() {
  glGenVertexArrays(1, &vertex_array_);
  glGenBuffers(1, &buffer_);
  glBindVertexArray(vertex_array_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  const GLsizei stride = sizeof(Vertex);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, from)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, to)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, end)));
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, r)));
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

RayTreeDrawing::~RayTreeDrawing() {
  if (buffer_) glDeleteBuffers(1, &buffer_);
  if (vertex_array_) glDeleteVertexArrays(1, &vertex_array_);
}

void RayTreeDrawing::set(const rt::RayTree& tree, const Scene& scene) {
  const float size = std::max(glm::length(scene.bounds().extent()), 1e-3f);
  dash_ = size / 80.0f;
  std::vector<Vertex> vertices;
  for (const rt::RayTreeNode& node : tree.nodes) {
    // Where the segment ends: the hit, the light (shadow rays: t is the distance to it, infinite
    // for a directional light), or out of the scene for a ray that hits nothing.
    const bool shadow = node.kind == rt::RayKind::shadow;
    float length = size;
    if (shadow ? std::isfinite(node.t) : node.hit) length = node.t;
    const glm::vec3 from = node.origin, to = node.origin + length * node.direction;
    const glm::vec3 c = ray_colour(node.kind, shadow && node.hit);
    const float dashed = shadow && node.hit ? 1.0f : 0.0f;
    // Two triangles: (from, -1) (to, -1) (to, +1) and (from, -1) (to, +1) (from, +1).
    for (const auto& [end, side] : {std::pair{0.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f},
                                    {0.0f, -1.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}})
      vertices.push_back({from, to, end, side, c.r, c.g, c.b, dashed});
  }
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  vertex_count_ = int(vertices.size());
}

void RayTreeDrawing::clear() { vertex_count_ = 0; }

void RayTreeDrawing::draw(const Camera& camera, const Scene& scene, int width, int height, float scale,
                          float pixels_per_unit) {
  if (vertex_count_ == 0 || width <= 0 || height <= 0) return;
  program_.use();
  program_.set("u_view_projection", camera.projection(float(width) / float(height), scene.bounds()) * camera.view());
  program_.set("u_viewport", glm::vec2(float(width), float(height)));
  program_.set("u_half_width", 1.5f * pixels_per_unit);
  program_.set("u_scale", scale);
  program_.set("u_dash", dash_);
  glBindVertexArray(vertex_array_);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);  // the scene's depth stays as it was drawn
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  // First what a surface hides, dimmed, then what is in view over it: the rays inside the glass
  // sphere show, and still read as inside.
  glDepthFunc(GL_GREATER);
  program_.set("u_dim", 0.45f);
  glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
  glDepthFunc(GL_LEQUAL);
  program_.set("u_dim", 1.0f);
  glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace luz::app
