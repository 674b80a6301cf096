#include "core/camera.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/i18n.h"
#include "core/scene.h"

namespace luz {

glm::vec3 Camera::position() const { return glm::vec3(to_world[3]); }

glm::vec3 Camera::forward() const { return glm::normalize(-glm::vec3(to_world[2])); }

glm::mat4 Camera::view() const { return glm::inverse(to_world); }

glm::mat4 Camera::projection(float image_aspect, const Bounds& scene) const {
  const float near = near_plane(scene, image_aspect);
  return glm::perspective(yfov, image_aspect, near, std::max(far_plane(scene), 2.0f * near));
}

float Camera::near_plane(const Bounds& bounds, float image_aspect) const {
  if (bounds.empty()) return znear;
  // Every point of the box is at least `distance` from the eye, and a point the image shows
  // lies within the frustum's corner angle of the axis: its depth is at least distance x cos.
  const glm::vec3 eye = position();
  const float distance = glm::length(eye - glm::clamp(eye, bounds.min, bounds.max));
  const float tan_y = std::tan(0.5f * yfov), tan_x = image_aspect * tan_y;
  const float cos_corner = 1.0f / std::sqrt(1.0f + tan_x * tan_x + tan_y * tan_y);
  return std::max(znear, 0.99f * distance * cos_corner);
}

float Camera::far_plane(const Bounds& bounds) const {
  if (zfar > 0.0f) return zfar;
  if (bounds.empty()) return 1000.0f;
  const glm::vec3 eye = position();
  float farthest = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p(corner & 1 ? bounds.max.x : bounds.min.x, corner & 2 ? bounds.max.y : bounds.min.y,
                      corner & 4 ? bounds.max.z : bounds.min.z);
    farthest = std::max(farthest, glm::length(p - eye));
  }
  return std::max(1.1f * farthest, 1e-3f);
}

std::string Camera::to_string() const {
  const glm::vec3 p = position(), f = forward();
  return fmt::format("Camera \"{}\" [at ({:.3g}, {:.3g}, {:.3g}) looking ({:.3g}, {:.3g}, {:.3g}) "
                     "yfov {:.3g} rad]", name, p.x, p.y, p.z, f.x, f.y, f.z, yfov);
}

float Camera::framing_elevation(const Bounds& bounds) {
  const glm::vec3 e = bounds.extent();
  const float wide = std::max(e.x, e.z);
  if (!(wide > 0.0f)) return 0.0f;
  // Height over width: 0 for a ground plane, 1/2 or more for anything as tall as half its width.
  const float flatness = std::clamp(e.y / wide, 0.0f, 0.5f);
  return kMaxFramingElevation * (1.0f - 2.0f * flatness);
}

Camera Camera::framing(const Bounds& bounds) {
  Camera camera;
  camera.name = i18n::tr("framing");
  const glm::vec3 centre = bounds.centre();
  const float radius = std::max(0.5f * glm::length(bounds.extent()), 1e-3f);
  // Far enough back that the bounding sphere fits the vertical field of view, from +Z raised by
  // the elevation about +X (a flat, wide scene is seen from above, not edge-on).
  const float distance = radius / std::sin(0.5f * camera.yfov);
  const float elevation = framing_elevation(bounds);
  camera.to_world = glm::translate(glm::mat4(1.0f), centre) *
                    glm::rotate(glm::mat4(1.0f), -elevation, glm::vec3(1, 0, 0)) *
                    glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, distance));
  camera.znear = std::max(distance - radius, distance * 1e-3f) * 0.5f;
  camera.zfar = distance + 2.0f * radius;
  return camera;
}

}  // namespace luz
