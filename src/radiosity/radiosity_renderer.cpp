#include "radiosity/radiosity_renderer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "gl/framebuffer.h"
#include "gl/functions.h"
#include "gl/shader.h"

namespace luz {

struct RadiosityRenderer::Impl {
  const Scene& scene;
  const PatchMesh& mesh;
  gl::Program program{{"radiosity.vert", "radiosity.frag"}};
  GLuint vao = 0, positions = 0, colours = 0;
  GLsizei vertex_count = 0;
  int revision = 0;  // of the mesh uploaded
  float far = 1.0f;
  std::unique_ptr<gl::Framebuffer> target;
  std::vector<Rgb> corner_colours;

  Impl(const Scene& s, const PatchMesh& m) : scene(s), mesh(m) {}
  ~Impl() {
    if (vao) glDeleteVertexArrays(1, &vao);
    if (positions) glDeleteBuffers(1, &positions);
    if (colours) glDeleteBuffers(1, &colours);
  }
};

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
  upload_elements();
}

// Non-indexed: three corners per element, so a flat picture can give each its own colour.
// Drawn grouped by shooting patch (PatchMesh::members), so a patch is a range of primitives.
void RadiosityRenderer::upload_elements() {
  Impl& s = *impl_;
  const PatchMesh& mesh = s.mesh;
  std::vector<glm::vec3> corners;
  corners.reserve(3 * mesh.size());
  Bounds bounds;
  for (const uint32_t e : mesh.members)
    for (const uint32_t v : mesh.patches[e].vertices) {
      corners.push_back(mesh.vertices[v]);
      bounds.grow(mesh.vertices[v]);
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
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  s.far = bounds.empty() ? 1.0f : glm::length(bounds.extent());
}

RadiosityRenderer::~RadiosityRenderer() = default;

void RadiosityRenderer::update(const RadianceField& field, const RadiosityOptions& options) {
  Impl& s = *impl_;
  if (s.revision != s.mesh.revision) upload_elements();  // adaptive subdivision cut elements
  for (size_t drawn = 0; drawn < s.mesh.size(); ++drawn) {
    const uint32_t e = s.mesh.members[drawn];
    for (int k = 0; k < 3; ++k)
      s.corner_colours[3 * drawn + size_t(k)] =
          options.flat_patches ? field.patch[e] : field.vertex[s.mesh.patches[e].vertices[k]];
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

  // A finite far plane past the farthest patch from the camera.
  const float far = glm::length(camera.position() - s.mesh.vertices.front()) + 2.0f * s.far;
  s.program.use();
  // A shift of (dx, dy) pixels is 2 dx / width in normalised device coordinates.
  const glm::mat4 shifted = glm::translate(
      glm::mat4(1.0f), glm::vec3(2.0f * shift.x / float(width), 2.0f * shift.y / float(height), 0.0f));
  s.program.set("u_view_projection",
                shifted * camera.projection(float(width) / float(height), far) * camera.view());
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
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDrawArrays(GL_TRIANGLES, 0, s.vertex_count);
  if (options.outlines) {
    glDisable(GL_POLYGON_OFFSET_FILL);
    s.program.set("u_outline", true);
    s.program.set("u_outline_colour", glm::vec3(0.02f));
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glDrawArrays(GL_TRIANGLES, 0, s.vertex_count);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }
  glBindVertexArray(0);
  glUseProgram(0);
}

Image RadiosityRenderer::render(const Camera& camera, int width, int height,
                                const RadiosityOptions& options, int highlight) {
  Impl& s = *impl_;
  if (!s.target || s.target->width() != width || s.target->height() != height)
    s.target = std::make_unique<gl::Framebuffer>(width, height);
  GLint previous = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
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
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
  return image;
}

}  // namespace luz
