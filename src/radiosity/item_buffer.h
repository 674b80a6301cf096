#pragma once
// The patches on the GPU for item buffers: one triangle list (patch i = triangle i)
// and the program that writes patch ID + 1 per pixel (shaders/item_buffer.*). The hemicube and
// the point sources draw the scene through it from their own viewpoints.
#include <optional>
#include <span>

#include <glm/mat4x4.hpp>

#include "gl/functions.h"
#include "gl/shader.h"
#include "radiosity/patch_mesh.h"

namespace luz {

// One face of a cube of item buffers: its camera and its rectangle of the atlas, in pixels.
struct AtlasFace {
  glm::mat4 view_projection;
  int x = 0, y = 0, width = 0, height = 0;
};

class PatchItems {
public:
  explicit PatchItems(const PatchMesh& mesh);  // needs a current GL context
  ~PatchItems();
  PatchItems(const PatchItems&) = delete;
  PatchItems& operator=(const PatchItems&) = delete;
  // The mesh's elements again, after adaptive subdivision changed them.
  void upload(const PatchMesh& mesh);

  // Sets the GL state an item buffer needs (depth test, no blending, both faces rasterised) and
  // makes the program current; then draw() once per face.
  void begin() const;
  void draw(const glm::mat4& view_projection) const;
  // Every face at once (at most kMaxAtlasFaces), one instance per face, into the bound atlas
  // of atlas_width x atlas_height pixels: the same pixels as one draw() per face in its viewport.
  void draw_atlas(std::span<const AtlasFace> faces, int atlas_width, int atlas_height) const;
  // Puts back GL's defaults for what begin() set (the depth test off), so that whoever draws
  // next finds the state it found before begin().
  void end() const;

  static constexpr int kMaxAtlasFaces = 5;  // the hemicube's

private:
  mutable gl::Program program_{{"item_buffer.vert", "item_buffer.frag"}};
  // Compiled with the other on the desktop; in GLSL ES 3.00, which has no clip distances, only
  // when draw_atlas() is called (and refused then): five passes of draw() need only program_.
  void compile_atlas_program() const;
  void draw_triangles(GLsizei instances) const;
  mutable std::optional<gl::Program> atlas_program_;
  // Indexed on the desktop; unindexed where the shaders name patches by gl_VertexID / 3 (GLSL
  // ES, which lacks gl_PrimitiveID): see shaders/item_buffer.vert.
  bool unindexed_ = false;
  GLuint vao_ = 0, vbo_ = 0, ebo_ = 0;
  GLsizei count_ = 0;  // indices, or vertices when unindexed
};

// A unit vector perpendicular to n, so that (t, cross(n, t), n) is a right-handed frame.
glm::vec3 any_tangent(const glm::vec3& n);

}  // namespace luz
