#pragma once
// The local-model rasteriser through OpenGL 3.3 core: flat, Gouraud and Phong shading of
//   I = Ia*ka + sum_i IL_i * [kd*cos(theta) + ks*cos^n(alpha)]   (+ Le of emissive surfaces)
// with IL_i = I_i * f_att(d_i) / pi for point and spot lights, E_perp / pi for directional ones,
// and each emissive triangle lighting the scene as a point light at its centroid of intensity
// Le * A * cos(theta_e) (SCENES.md).
#include <memory>

#include "core/camera.h"
#include "core/image.h"
#include "core/scene.h"
#include "local/local_options.h"

namespace luz {

class LocalRenderer {
public:
  // Uploads the scene's meshes and textures to the current GL context (which must stay current
  // on this thread for the renderer's lifetime). Throws luz::Error (kind gl) on shader failure.
  explicit LocalRenderer(const Scene& scene);
  ~LocalRenderer();
  LocalRenderer(const LocalRenderer&) = delete;
  LocalRenderer& operator=(const LocalRenderer&) = delete;

  // Draws into the currently bound framebuffer (the window's, or an FBO) of the given size.
  void draw(const Camera& camera, int width, int height, const LocalOptions& options);

  // Renders into a float framebuffer and reads back linear radiance (row 0 at the top).
  Image render(const Camera& camera, int width, int height, const LocalOptions& options);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace luz
