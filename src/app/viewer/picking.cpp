#include "app/viewer/picking.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "gl/framebuffer.h"
#include "gl/functions.h"

namespace luz::app {

glm::vec3 pixel_ray(const Camera& camera, int width, int height, float x, float y) {
  // Normalised device coordinates of the pixel centre, +Y up.
  const float ndc_x = 2.0f * (x + 0.5f) / float(width) - 1.0f;
  const float ndc_y = 1.0f - 2.0f * (y + 0.5f) / float(height);
  const float tan_half = std::tan(0.5f * camera.yfov);
  const float aspect = float(width) / float(height);  // the renderers' aspect: the view's own
  const glm::vec3 right = glm::normalize(glm::vec3(camera.to_world[0]));
  const glm::vec3 up = glm::normalize(glm::vec3(camera.to_world[1]));
  return glm::normalize(camera.forward() + ndc_x * tan_half * aspect * right + ndc_y * tan_half * up);
}

bool intersect_pick(const Scene& scene, const Camera& camera, int width, int height, Pick& pick) {
  const Mesh& mesh = scene.meshes[size_t(pick.mesh)];
  const uint32_t* index = &mesh.indices[3 * size_t(pick.triangle)];
  const glm::vec3 p0 = mesh.positions[index[0]], p1 = mesh.positions[index[1]],
                  p2 = mesh.positions[index[2]];
  pick.eye = camera.position();
  const glm::vec3 d = pixel_ray(camera, width, height, float(pick.x), float(pick.y));
  // Moeller-Trumbore, without the inside test: the GL pass already said the pixel is on it.
  const glm::vec3 e1 = p1 - p0, e2 = p2 - p0;
  const glm::vec3 h = glm::cross(d, e2);
  const float det = glm::dot(e1, h);
  if (std::abs(det) < 1e-12f) return false;
  const glm::vec3 s = pick.eye - p0;
  const float u = glm::dot(s, h) / det;
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(d, q) / det;
  pick.barycentric = {1.0f - u - v, u, v};
  const glm::vec3& b = pick.barycentric;
  pick.P = b.x * p0 + b.y * p1 + b.z * p2;
  const glm::vec3 n = b.x * mesh.normals[index[0]] + b.y * mesh.normals[index[1]] +
                      b.z * mesh.normals[index[2]];
  pick.N = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f);
  pick.face = glm::normalize(glm::cross(e1, e2));
  if (!mesh.uvs.empty())
    pick.uv = b.x * mesh.uvs[index[0]] + b.y * mesh.uvs[index[1]] + b.z * mesh.uvs[index[2]];
  return true;
}

Picker::Picker(const Scene& scene) : scene_(scene) {
  for (const Mesh& mesh : scene.meshes) meshes_.emplace_back(mesh);
}

void Picker::draw_ids(const Camera& camera, int width, int height) {
  if (!target_ || target_->width() != width || target_->height() != height)
    target_ = std::make_unique<gl::Framebuffer>(width, height);
  drawn_with_ = camera;
  target_->bind();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  const float nothing[4] = {0, 0, 0, 0}, far_depth = 1.0f;
  glClearBufferfv(GL_COLOR, 0, nothing);
  glClearBufferfv(GL_DEPTH, 0, &far_depth);

  // The pictures' own near and far planes: a pick resolves the depth order as they drew it.
  program_.use();
  program_.set("u_view_projection", camera.projection(float(width) / float(height), scene_.bounds()) * camera.view());
  for (size_t m = 0; m < meshes_.size(); ++m) {
    program_.set("u_mesh", float(m + 1));
    meshes_[m].draw();
  }
  glUseProgram(0);
}

std::optional<Pick> Picker::pick(const Camera& camera, int width, int height, int x, int y) {
  if (x < 0 || y < 0 || x >= width || y >= height) return std::nullopt;
  const bool same_view = target_ && target_->width() == width && target_->height() == height &&
                         drawn_with_ && drawn_with_->to_world == camera.to_world &&
                         drawn_with_->yfov == camera.yfov && drawn_with_->znear == camera.znear &&
                         drawn_with_->zfar == camera.zfar;
  float id[4] = {};
  {
    const gl::KeptBinding kept;
    if (!same_view) draw_ids(camera, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, target_->id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(x, height - 1 - y, 1, 1, GL_RGBA, GL_FLOAT, id);  // GL rows go bottom-up
  }
  if (id[0] < 0.5f) return std::nullopt;

  Pick pick;
  pick.x = x;
  pick.y = y;
  pick.mesh = int(std::lround(id[0])) - 1;
  pick.triangle = int(std::lround(id[1]));
  if (size_t(pick.mesh) >= scene_.meshes.size() ||
      size_t(pick.triangle) >= scene_.meshes[size_t(pick.mesh)].triangle_count())
    return std::nullopt;
  if (!intersect_pick(scene_, camera, width, height, pick)) return std::nullopt;
  return pick;
}

}  // namespace luz::app
