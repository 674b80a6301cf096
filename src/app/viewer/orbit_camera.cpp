#include "app/viewer/orbit_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace luz::app {
namespace {

constexpr float max_pitch = 1.55f;        // just under 90 degrees: lookAt needs a horizon
// A quarter of a degree per window unit, whatever the window's size: a 160-unit drag turns the
// view by 40 degrees, a turn all the way round takes 1440 units.
constexpr float radians_per_pixel = 0.25f * 3.14159265f / 180.0f;
constexpr float min_distance = 1e-3f;

// The unit direction of a yaw and pitch: yaw 0, pitch 0 looks down -Z.
glm::vec3 direction(float yaw, float pitch) {
  return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

}  // namespace

void OrbitCamera::start_from(const Camera& camera, const glm::vec3& centre) {
  base_ = camera;
  const glm::vec3 eye = camera.position();
  const glm::vec3 forward = camera.forward();
  distance_ = std::max(glm::dot(centre - eye, forward), 0.1f);
  target_ = eye + distance_ * forward;
  pitch_ = std::clamp(std::asin(std::clamp(forward.y, -1.0f, 1.0f)), -max_pitch, max_pitch);
  yaw_ = std::atan2(-forward.x, -forward.z);
}

glm::vec3 OrbitCamera::eye() const { return target_ - distance_ * direction(yaw_, pitch_); }

void OrbitCamera::orbit(float dx, float dy) {
  // Dragging right turns the scene right, i.e. the eye goes left around the target.
  yaw_ -= dx * radians_per_pixel;
  pitch_ = std::clamp(pitch_ + dy * radians_per_pixel, -max_pitch, max_pitch);
}

void OrbitCamera::pan(float dx, float dy, float view_height) {
  // One pixel moves the target by the pixel's size at the target's distance, so the point under
  // the mouse stays under it.
  const float pixel = 2.0f * distance_ * std::tan(0.5f * base_.yfov) / std::max(view_height, 1.0f);
  const Camera view = camera();
  const glm::vec3 right = glm::vec3(view.to_world[0]);
  const glm::vec3 up = glm::vec3(view.to_world[1]);
  target_ += pixel * (-dx * right + dy * up);
}

void OrbitCamera::zoom(float wheel_steps) {
  distance_ = std::max(distance_ * std::pow(0.9f, wheel_steps), min_distance);
}

void OrbitCamera::fly(const glm::vec3& forward_right_up) {
  const Camera view = camera();
  const glm::vec3 right = glm::vec3(view.to_world[0]);
  target_ += forward_right_up.x * view.forward() + forward_right_up.y * right +
             forward_right_up.z * glm::vec3(0, 1, 0);
}

Camera OrbitCamera::camera() const {
  Camera camera = base_;
  camera.name = "orbit";
  camera.to_world = glm::inverse(glm::lookAt(eye(), target_, glm::vec3(0, 1, 0)));
  return camera;
}

}  // namespace luz::app
