#pragma once
// Slide 24's ray tree over the scene (the viewer's Whitted mode): every ray of the clicked pixel
// a segment in 3D, coloured by its kind, drawn into the picture after the scene so that it stays
// while the camera orbits around it. Rays hidden by a surface are drawn dimmer (the tree inside
// the glass sphere stays visible); a blocked shadow ray is dashed and darker.
#include <optional>

#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/scene.h"
#include "gl/shader.h"
#include "raytracing/ray_tree.h"

namespace luz::app {

// The colour of each kind of ray, display (sRGB-encoded) values: the 3D drawing and the panel's
// list use the same, so the class matches a line to its row.
glm::vec3 ray_colour(rt::RayKind kind, bool blocked_shadow = false);

class RayTreeDrawing {
public:
  RayTreeDrawing();
  ~RayTreeDrawing();
  RayTreeDrawing(const RayTreeDrawing&) = delete;
  RayTreeDrawing& operator=(const RayTreeDrawing&) = delete;

  // The segments of `tree` in `scene`: rays that leave the scene are drawn out to its size.
  void set(const rt::RayTree& tree, const Scene& scene);
  void clear();
  bool empty() const { return vertex_count_ == 0; }

  // Into the bound framebuffer of width x height pixels, whose depth buffer holds `scene` as
  // the local models drew it from `camera` (with Camera::projection, as this draws).
  // `scale` = 2^exposure: the display pass multiplies by it, this divides it out.
  void draw(const Camera& camera, const Scene& scene, int width, int height, float scale, float pixels_per_unit);

private:
  gl::Program program_{{"ray_tree.vert", "ray_tree.frag"}};
  GLuint vertex_array_ = 0, buffer_ = 0;
  int vertex_count_ = 0;
  float dash_ = 0.05f;  // metres, from the scene's size
};

}  // namespace luz::app
