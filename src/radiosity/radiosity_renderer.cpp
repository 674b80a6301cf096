#include "radiosity/radiosity_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "gl/framebuffer.h"
#include "gl/functions.h"
#include "gl/scene_texture.h"
#include "gl/shader.h"

namespace luz {

// The corners drawn with one kd texture, or none: consecutive elements of meshes that show the
// same one (for a scene without textures, all of them).
struct Run {
  GLint first = 0;             // corners
  GLsizei count = 0;
  const Texture* texture = nullptr;
  int mesh = 0;                // one of its meshes (they share the texture)
};

struct RadiosityRenderer::Impl {
  const Scene& scene;
  const PatchMesh& mesh;
  gl::Program program{{"radiosity.vert", "radiosity.frag"}};
  GLuint vao = 0, positions = 0, colours = 0, uvs = 0;
  GLuint edges = 0;  // the outlines: each element's three sides as GL_LINES over its corners
  GLsizei vertex_count = 0, edge_count = 0;
  std::vector<Run> runs;
  std::vector<GLuint> textures;  // per scene texture, uploaded when a run shows it (else 0)
  bool texture_detail = true;    // the last update's colours are B/pi, which the texture modulates
  int revision = 0;  // of the mesh uploaded
  Bounds bounds;  // of the elements' vertices
  std::unique_ptr<gl::Framebuffer> target;
  std::vector<Rgb> corner_colours;

  Impl(const Scene& s, const PatchMesh& m) : scene(s), mesh(m), textures(s.textures.size(), 0) {}
  ~Impl() {
    if (vao) glDeleteVertexArrays(1, &vao);
    if (positions) glDeleteBuffers(1, &positions);
    if (colours) glDeleteBuffers(1, &colours);
    if (uvs) glDeleteBuffers(1, &uvs);
    if (edges) glDeleteBuffers(1, &edges);
    for (GLuint t : textures)
      if (t) glDeleteTextures(1, &t);
  }
};

namespace {

// The barycentrics (b1, b2) of point p in the triangle a, b, c it lies in (or over).
glm::vec2 barycentrics_of(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 e1 = b - a, e2 = c - a, w = p - a;
  const float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
  const float w1 = glm::dot(w, e1), w2 = glm::dot(w, e2);
  const float denominator = d11 * d22 - d12 * d12;
  if (!(denominator > 0.0f)) return glm::vec2(0.0f);
  return glm::vec2(d22 * w1 - d12 * w2, d11 * w2 - d12 * w1) / denominator;
}

}  // namespace

static const Scene& with_gl_loaded(const Scene& scene) {
  if (!glCreateProgram)
    throw Error(ErrorKind::gl, "the radiosity renderer needs a current OpenGL context made "
                               "before it");
  return scene;
}

RadiosityRenderer::RadiosityRenderer(const Scene& scene, const PatchMesh& mesh)
    : impl_(std::make_unique<Impl>(with_gl_loaded(scene), mesh)) {
  Impl& s = *impl_;
  glGenVertexArrays(1, &s.vao);
  glGenBuffers(1, &s.positions);
  glGenBuffers(1, &s.colours);
  glGenBuffers(1, &s.uvs);
  glGenBuffers(1, &s.edges);
  upload_elements();
}

// Non-indexed: three corners per element, so a flat picture can give each its own colour.
// Drawn grouped by shooting patch (PatchMesh::members), so a patch is a range of primitives; the
// patches of a mesh are consecutive (PatchMesh::build makes them mesh by mesh), so are its runs.
// A textured mesh's corners carry their texture coordinates, interpolated from the source
// triangle's at the corner.
void RadiosityRenderer::upload_elements() {
  Impl& s = *impl_;
  const PatchMesh& mesh = s.mesh;
  std::vector<glm::vec3> corners;
  std::vector<glm::vec2> corner_uvs;
  corners.reserve(3 * mesh.size());
  corner_uvs.reserve(3 * mesh.size());
  s.runs.clear();
  Bounds bounds;
  for (const uint32_t e : mesh.members) {
    const Patch& p = mesh.patches[e];
    const Texture* texture = s.mesh.detail.texture_of(p.mesh);
    if (s.runs.empty() || s.runs.back().texture != texture)
      s.runs.push_back({GLint(corners.size()), 0, texture, p.mesh});
    s.runs.back().count += 3;
    const Mesh& source = s.scene.meshes[size_t(p.mesh)];
    const size_t t = size_t(p.triangle);
    for (const uint32_t v : p.vertices) {
      corners.push_back(mesh.vertices[v]);
      bounds.grow(mesh.vertices[v]);
      glm::vec2 uv(0.0f);
      if (texture) {
        const glm::vec3 a = source.positions[source.indices[3 * t]], b = source.positions[source.indices[3 * t + 1]],
                        c = source.positions[source.indices[3 * t + 2]];
        uv = source.uv_at(t, barycentrics_of(mesh.vertices[v], a, b, c));
      }
      corner_uvs.push_back(uv);
    }
  }
  for (const Run& run : s.runs)
    if (run.texture) {
      GLuint& id = s.textures[size_t(run.texture - s.scene.textures.data())];
      if (!id) id = gl::upload_texture(*run.texture);
    }
  s.vertex_count = GLsizei(corners.size());
  s.corner_colours.assign(corners.size(), Rgb(0.0f));
  s.revision = mesh.revision;

  glBindVertexArray(s.vao);
  glBindBuffer(GL_ARRAY_BUFFER, s.positions);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(corners.size() * sizeof(glm::vec3)), corners.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, s.colours);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(s.corner_colours.size() * sizeof(Rgb)),
               s.corner_colours.data(), GL_DYNAMIC_DRAW);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Rgb), nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, s.uvs);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(corner_uvs.size() * sizeof(glm::vec2)), corner_uvs.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), nullptr);
  // The outlines as lines, not as polygons drawn in GL_LINE mode: GL ES has no glPolygonMode, and
  // the lines are the same pixels on both targets (an edge shared by two elements drawn twice).
  std::vector<uint32_t> sides;
  sides.reserve(2 * corners.size());
  for (uint32_t first = 0; first + 2 < uint32_t(corners.size()); first += 3)
    for (const uint32_t k : {0u, 1u, 1u, 2u, 2u, 0u}) sides.push_back(first + k);
  s.edge_count = GLsizei(sides.size());
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s.edges);  // kept by the vertex array
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(sides.size() * sizeof(uint32_t)), sides.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  s.bounds = bounds;
}

RadiosityRenderer::~RadiosityRenderer() = default;

void RadiosityRenderer::update(const RadianceField& field, const RadiosityOptions& options, bool texture_detail) {
  Impl& s = *impl_;
  s.texture_detail = texture_detail;
  if (s.revision != s.mesh.revision) upload_elements();  // adaptive subdivision cut elements
  for (size_t drawn = 0; drawn < s.mesh.size(); ++drawn) {
    const uint32_t e = s.mesh.members[drawn];
    for (int k = 0; k < 3; ++k)
      s.corner_colours[3 * drawn + size_t(k)] =
          options.flat_patches ? field.patch[e] : field.corner[3 * e + size_t(k)];
  }
  glBindBuffer(GL_ARRAY_BUFFER, s.colours);
  glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(s.corner_colours.size() * sizeof(Rgb)),
                  s.corner_colours.data());
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void RadiosityRenderer::draw(const Camera& camera, int width, int height,
                             const RadiosityOptions& options, int highlight, glm::vec2 shift) {
  Impl& s = *impl_;
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  const float background[4] = {s.scene.background.r, s.scene.background.g, s.scene.background.b,
                               1.0f};
  const float far_depth = 1.0f;
  glClearBufferfv(GL_COLOR, 0, background);
  glClearBufferfv(GL_DEPTH, 0, &far_depth);

  const float aspect = float(width) / float(height);
  s.program.use();
  // A shift of (dx, dy) pixels is 2 dx / width in normalised device coordinates.
  const glm::mat4 shifted = glm::translate(
      glm::mat4(1.0f), glm::vec3(2.0f * shift.x / float(width), 2.0f * shift.y / float(height), 0.0f));
  s.program.set("u_view_projection",
                shifted * camera.projection(aspect, s.bounds) * camera.view());
  s.program.set("u_outline", false);
  const bool lit = highlight >= 0 && size_t(highlight) < s.mesh.shooters.size();
  s.program.set("u_highlight_first", lit ? int(s.mesh.shooters[size_t(highlight)].first) : -1);
  s.program.set("u_highlight_count", lit ? int(s.mesh.shooters[size_t(highlight)].count) : 0);
  s.program.set("u_highlight_colour", glm::vec3(4.0f, 0.0f, 4.0f));  // magenta, bright
  glBindVertexArray(s.vao);
  if (options.outlines) {  // push the filled patches back so the lines win the depth test
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
  }
  if (glPolygonMode) glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);  // GL ES has only filled polygons
  s.program.set("u_kd_texture", 0);
  glActiveTexture(GL_TEXTURE0);
  for (const Run& run : s.runs) {
    const bool textured = s.texture_detail && run.texture;
    s.program.set("u_textured", textured);
    if (textured) {
      glBindTexture(GL_TEXTURE_2D, s.textures[size_t(run.texture - s.scene.textures.data())]);
      s.program.set("u_inverse_mean", s.mesh.detail.inverse_mean(run.mesh));
    }
    glDrawArrays(GL_TRIANGLES, run.first, run.count);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  if (options.outlines) {
    glDisable(GL_POLYGON_OFFSET_FILL);
    s.program.set("u_outline", true);
    s.program.set("u_outline_colour", glm::vec3(0.02f));
    glDrawElements(GL_LINES, s.edge_count, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
  glUseProgram(0);
}

Image RadiosityRenderer::render(const Camera& camera, int width, int height,
                                const RadiosityOptions& options, int highlight) {
  Impl& s = *impl_;
  if (!s.target || s.target->width() != width || s.target->height() != height)
    s.target = std::make_unique<gl::Framebuffer>(width, height);
  const gl::KeptBinding kept;
  s.target->bind();
  const int root = std::max(1, int(std::lround(std::sqrt(double(options.pixel_samples)))));
  Image image(width, height);
  for (int sy = 0; sy < root; ++sy)
    for (int sx = 0; sx < root; ++sx) {  // cell centres of a root x root grid, about the pixel's
      const glm::vec2 shift((float(sx) + 0.5f) / float(root) - 0.5f, (float(sy) + 0.5f) / float(root) - 0.5f);
      draw(camera, width, height, options, highlight, shift);
      const Image pass = s.target->read();
      for (size_t k = 0; k < image.pixels.size(); ++k) image.pixels[k] += pass.pixels[k];
    }
  const float weight = 1.0f / float(root * root);
  for (Rgb& p : image.pixels) p *= weight;
  return image;
}

}  // namespace luz
