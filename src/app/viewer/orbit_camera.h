#pragma once
// The viewer's free camera: it orbits, pans and zooms around a target point and flies, keeping
// the field of view and clip planes of the scene camera it started from. The scene's own cameras
// stay untouched, so "back to the scene camera" gives exactly the picture `luz render` makes.
#include <glm/vec3.hpp>

#include "core/camera.h"

namespace luz::app {

class OrbitCamera {
public:
  // Starts where `camera` is, looking where it looks; the target is the point on its view axis
  // nearest to `centre` (the scene's middle), so orbiting turns around what is in view.
  void start_from(const Camera& camera, const glm::vec3& centre);

  // Mouse drags in window pixels over a view `view_height` pixels high.
  void orbit(float dx, float dy);                     // left drag: yaw and pitch around the target
  void pan(float dx, float dy, float view_height);    // right or middle drag: move in the view plane
  void zoom(float wheel_steps);                       // wheel: distance to the target x 0.9^steps
  // Flying: move by `amount` metres along the view (forward), right and world up axes.
  void fly(const glm::vec3& forward_right_up);

  Camera camera() const;        // the current view as a Camera
  float distance() const { return distance_; }
  const glm::vec3& target() const { return target_; }

private:
  glm::vec3 eye() const;
  Camera base_;                  // yfov, znear, zfar, name come from here
  glm::vec3 target_{0.0f};
  float distance_ = 1.0f;
  float yaw_ = 0.0f;             // around world +Y, radians; 0 looks down -Z
  float pitch_ = 0.0f;           // above the horizon, radians, kept inside (-90, 90) degrees
};

}  // namespace luz::app
