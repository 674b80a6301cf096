// Punctual lights shot through a cube of item buffers (see point_source.h for the derivation).
#include "radiosity/point_source.h"

#include <cmath>

#include <fmt/format.h>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "radiosity/radiosity_options.h"

namespace luz {
namespace {

struct CubeFace {
  glm::vec3 forward, up;
};
// The six faces; right = forward x up (what glm::lookAt puts on the image's +x).
constexpr CubeFace kCube[PointSource::kFaces] = {
    {{1, 0, 0}, {0, 1, 0}},  {{-1, 0, 0}, {0, 1, 0}}, {{0, 1, 0}, {0, 0, 1}},
    {{0, -1, 0}, {0, 0, 1}}, {{0, 0, 1}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}}};

int checked(int res) {
  if (res < kMinHemicubeRes || res > kMaxHemicubeRes || res % 2 != 0)
    throw Error(ErrorKind::bad_value, fmt::format("light cube resolution {} must be even and in "
                                                  "{} .. {}", res, kMinHemicubeRes,
                                                  kMaxHemicubeRes));
  return res;
}

}  // namespace

PointSource::PointSource(const PatchMesh& mesh, const PatchItems& items, int resolution)
    : mesh_(mesh), items_(items), res_(checked(resolution)), target_(3 * res_, 2 * res_),
      sums_(mesh.size(), 0.0) {
  far_ = 1.0f;
  Bounds bounds;
  for (const glm::vec3& v : mesh.vertices) bounds.grow(v);
  if (!bounds.empty()) far_ = glm::length(bounds.extent());
}

const std::vector<FormFactor>& PointSource::solid_angles(const Light& light) {
  // The light may stand outside the patches' bounds (a sun-like lamp far above a floor).
  Bounds bounds;
  for (const glm::vec3& v : mesh_.vertices) bounds.grow(v);
  float far = far_;
  if (!bounds.empty())
    far = glm::length(glm::max(glm::abs(bounds.max - light.position),
                               glm::abs(bounds.min - light.position))) * 1.01f + 1e-3f;
  const float near = 1e-4f * far;

  GLint previous_fbo = 0, previous_viewport[4] = {};
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_fbo);
  glGetIntegerv(GL_VIEWPORT, previous_viewport);
  target_.bind_and_clear();
  items_.begin();
  const glm::mat4 projection = glm::frustum(-near, near, -near, near, near, far);
  for (int face = 0; face < kFaces; ++face) {
    glViewport((face % 3) * res_, (face / 3) * res_, res_, res_);
    items_.draw(projection * glm::lookAt(light.position, light.position + kCube[face].forward,
                                         kCube[face].up));
  }
  items_.end();
  target_.read(ids_);
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous_fbo));
  glViewport(previous_viewport[0], previous_viewport[1], previous_viewport[2], previous_viewport[3]);

  // Sum spot(direction) * d_omega per patch, pixel by pixel.
  touched_.clear();
  emitted_ = 0.0;
  const double step = 2.0 / res_, dA = step * step;
  const int width = 3 * res_;
  for (int face = 0; face < kFaces; ++face) {
    const glm::vec3 f = kCube[face].forward, u = kCube[face].up, r = glm::cross(f, u);
    for (int py = 0; py < res_; ++py)
      for (int px = 0; px < res_; ++px) {
        const double x = -1.0 + (px + 0.5) * step, y = -1.0 + (py + 0.5) * step;
        const double r2 = x * x + y * y + 1.0;
        const glm::vec3 direction = glm::normalize(f + float(x) * r + float(y) * u);
        const double weight = double(light.spot_factor(direction)) * dA / (r2 * std::sqrt(r2));
        emitted_ += weight;
        const uint32_t id = ids_[size_t((face / 3) * res_ + py) * size_t(width) +
                                 size_t((face % 3) * res_ + px)];
        if (id == 0 || weight == 0.0) continue;
        const uint32_t j = id - 1;
        if (sums_[j] == 0.0) touched_.push_back(j);
        sums_[j] += weight;
      }
  }
  result_.clear();
  for (const uint32_t j : touched_) {
    result_.push_back({j, float(sums_[j])});
    sums_[j] = 0.0;
  }
  return result_;
}

}  // namespace luz
