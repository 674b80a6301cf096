#pragma once
// Which surface is under a pixel, for the inspector: a GL pass draws mesh and triangle ids
// (shaders/pick.*), then the ray through the pixel's centre is intersected with that triangle on
// the CPU. The ray hit gives the same barycentrics the rasteriser interpolates with (perspective
// correct), so P, N and uv are those the Phong fragment shader saw at that pixel.
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/scene.h"
#include "gl/framebuffer.h"
#include "gl/face_buffers.h"
#include "gl/shader.h"

namespace luz::app {

struct Pick {
  int x = 0, y = 0;             // the pixel, row 0 at the top of the view
  int mesh = -1;                // index into Scene::meshes
  int triangle = -1;            // triangle of that mesh
  glm::vec3 barycentric{0.0f};  // weights of the triangle's vertices 0, 1, 2
  glm::vec3 P{0.0f};            // world position
  glm::vec3 N{0.0f};            // the interpolated vertex normal, unit (not turned to the eye)
  glm::vec3 face{0.0f};         // the face normal, unit, by the triangle's winding
  glm::vec2 uv{0.0f};
  glm::vec3 eye{0.0f};          // the camera's position when picked
};

// The ray from the eye through the centre of pixel (x, y) of a width x height view.
glm::vec3 pixel_ray(const Camera& camera, int width, int height, float x, float y);

// Fills P, N, face, uv and barycentric of `pick` (mesh and triangle set) from the pixel ray.
// False when the ray misses the triangle's plane.
bool intersect_pick(const Scene& scene, const Camera& camera, int width, int height, Pick& pick);

class Picker {
public:
  explicit Picker(const Scene& scene);  // uploads the geometry; needs a current GL context
  // The surface under pixel (x, y) of the view drawn with `camera`; nullopt for the background.
  std::optional<Pick> pick(const Camera& camera, int width, int height, int x, int y);

private:
  void draw_ids(const Camera& camera, int width, int height);
  const Scene& scene_;
  // Unindexed, so that a triangle is its first vertex / 3 (shaders/pick.vert): GLSL ES, the
  // page's, has no gl_PrimitiveID.
  std::vector<gl::FaceBuffers> meshes_;
  gl::Program program_{{"pick.vert", "pick.frag"}};
  std::unique_ptr<gl::Framebuffer> target_;
  std::optional<Camera> drawn_with_;  // the id buffer is redrawn only when the view changes
};

}  // namespace luz::app
