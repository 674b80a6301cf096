// Punctual lights shot through a cube of item buffers (see point_source.h for the derivation).
#include "radiosity/point_source.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/i18n.h"
#include "gl/framebuffer.h"
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
    throw Error(ErrorKind::bad_value, i18n::trf("light cube resolution {} must be even and in {} .. {}", res,
                                                kMinHemicubeRes, kMaxHemicubeRes));
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

  {
    const gl::KeptBinding kept;
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
  }

  // Sum spot(direction) * d_omega per patch, pixel by pixel.
  sums_.assign(mesh_.size(), 0.0);  // adaptive subdivision adds elements between shots
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
        sums_[id - 1] += weight;
      }
  }
  // Patches too small for the cube's pixels (a sphere's facets seen from metres away cover less
  // than a pixel) would alias into blotches: for them, the expected solid angle
  // A cos(theta) / d^2 times the spot factor, if the cube's depth buffer, used as a shadow map,
  // shows nothing nearer the light than the patch centre.
  std::vector<float> depth;
  target_.read_depth(depth);
  result_.clear();
  for (uint32_t j = 0; j < mesh_.size(); ++j) {
    const Patch& p = mesh_.patches[j];
    const glm::vec3 v = p.centre - light.position;
    const float d = glm::length(v);
    const float cos_theta = -glm::dot(p.normal, v) / std::max(d, 1e-30f);
    const double measured = sums_[j];
    sums_[j] = 0.0;
    if (!(cos_theta > 0.0f) || d <= 0.0f) continue;  // the back of the patch faces the light
    // The cube face the centre projects to: the one of v's largest component.
    int face = 0;
    for (int k = 1; k < kFaces; ++k)
      if (glm::dot(v, kCube[k].forward) > glm::dot(v, kCube[face].forward)) face = k;
    const glm::vec3 f = kCube[face].forward, u = kCube[face].up, r = glm::cross(f, u);
    const float along = glm::dot(v, f);
    const double x = glm::dot(v, r) / along, y = glm::dot(v, u) / along;
    const double r2 = x * x + y * y + 1.0;
    const double pixel_solid_angle = dA / (r2 * std::sqrt(r2));
    const double expected = double(p.area) * double(cos_theta) / double(d * d);
    if (expected >= kResolvedPixels * pixel_solid_angle) {
      if (measured > 0.0) result_.push_back({j, float(measured)});
      continue;
    }
    const int px = std::clamp(int((x + 1.0) / step), 0, res_ - 1);
    const int py = std::clamp(int((y + 1.0) / step), 0, res_ - 1);
    const float window = depth[size_t((face / 3) * res_ + py) * size_t(width) +
                               size_t((face % 3) * res_ + px)];
    // Window depth back to the distance along the face's axis (perspective divide undone).
    const float nearest = 2.0f * far * near / (far + near - (2.0f * window - 1.0f) * (far - near));
    // Slope-scaled bias: a pixel of a surface at angle theta spans footprint * tan(theta) in depth.
    const float tangent = std::min(std::sqrt(1.0f - cos_theta * cos_theta) / cos_theta, 20.0f);
    // (plus half a pixel for curved surfaces whose centre sample lies off the patch).
    const float bias = along * (float(step) * (1.5f * tangent + 0.5f) + 1e-3f);
    if (along > nearest + bias) continue;  // in shadow
    const double spot = light.spot_factor(v / d);
    if (spot > 0.0) result_.push_back({j, float(spot * expected)});
  }
  return result_;
}

}  // namespace luz
