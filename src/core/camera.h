#pragma once
// A perspective camera as glTF describes it: it looks down its node's -Z, +Y up.
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace luz {

struct Bounds;

struct Camera {
  std::string name = "camera";
  glm::mat4 to_world{1.0f};  // the camera node's world transform (rigid)
  float yfov = 0.8f;         // vertical field of view, radians
  float aspect = 0.0f;       // width / height from the file; 0 = none given
  float znear = 0.01f;
  float zfar = 0.0f;         // 0 = infinite (glTF allows it); renderers pick a finite one

  glm::vec3 position() const;
  glm::vec3 forward() const;  // unit -Z of the node
  glm::mat4 view() const;     // world -> camera
  // OpenGL clip matrix for an image of the given aspect (width / height) of a scene within
  // `scene`, its near plane at near_plane and its far plane at far_plane. Every rasterised
  // picture (the local models, radiosity, picking, the ray tree drawn over a picture's depth)
  // takes this one, so that their depth buffers agree and none keeps a file's tiny znear.
  glm::mat4 projection(float image_aspect, const Bounds& scene) const;
  // A near plane for a scene within `bounds`: znear, or just short of the nearest point of the
  // scene the image can show when that is farther. A depth buffer's steps grow as depth^2 / near:
  // a file's znear of centimetres on an engine a kilometre away leaves steps of metres, and a
  // fin's face and the dark body a metre behind it fight over the pixels.
  float near_plane(const Bounds& bounds, float image_aspect) const;
  // zfar, or for zfar 0 (infinite) just past the farthest corner of `bounds`: a finite far plane
  // keeps the depth buffer's precision and cuts nothing of the scene.
  float far_plane(const Bounds& bounds) const;
  std::string to_string() const;

  // SCENES.md: a scene without a camera gets one framing its bounding box from +Z, raised by
  // framing_elevation() so that a flat, wide scene is seen from above rather than edge-on.
  static Camera framing(const Bounds& bounds);
  // The angle above the horizon of the framing camera's view: kMaxFramingElevation for a flat
  // box (height 0 against the larger of its width and depth), falling linearly to 0 for a box
  // at least half as tall as it is wide (so a box, a figure or an upright plane is seen from +Z).
  static float framing_elevation(const Bounds& bounds);
  static constexpr float kMaxFramingElevation = 0.7853982f;  // 45 degrees
};

}  // namespace luz
