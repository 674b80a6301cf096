#pragma once
// The local-model rasteriser through OpenGL 3.3 core: flat, Gouraud and Phong shading of
//   I = Ia*ka + sum_i S_i * IL_i * [kd*cos(theta) + ks*cos^n(alpha)]   (+ Le of emissive surfaces)
//       + kr*Ir + kt*It,   then the fog
// (S_i, Ir, It and the fog only when their switches of LocalOptions are on: slide 19)
// with IL_i = I_i * f_att(d_i) / pi for point and spot lights, E_perp / pi for directional ones,
// and each emissive triangle lighting the scene as a point light at its centroid of intensity
// Le * A * cos(theta_e) (SCENES.md).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/camera.h"
#include "core/image.h"
#include "core/scene.h"
#include "local/local_options.h"
#include "local/reflection_maps.h"
#include "local/shadow_maps.h"

namespace luz {

class LocalRenderer {
public:
  // Uploads the scene's meshes and textures to the current GL context (which must stay current
  // on this thread for the renderer's lifetime). Throws luz::Error (kind gl) on shader failure.
  // The scene must outlive the renderer: lights, materials and the ambient term are read at
  // every draw, so a panel can edit them live; a change of geometry needs a new renderer.
  explicit LocalRenderer(const Scene& scene);
  ~LocalRenderer();
  LocalRenderer(const LocalRenderer&) = delete;
  LocalRenderer& operator=(const LocalRenderer&) = delete;

  // Draws into the currently bound framebuffer (the window's, or an FBO) of the given size.
  // With shadows or reflection maps on, their passes run first (into their own framebuffers).
  // Throws luz::Error when the environment image of options.reflection cannot be read.
  // With `display_scale` (2^exposure), the opaque meshes also write what the window shows of
  // them (the sRGB curve of display_scale x radiance, as the viewer's display pass computes it)
  // into colour attachment 1, which the caller has made draw buffer 1.
  void draw(const Camera& camera, int width, int height, const LocalOptions& options,
            std::optional<float> display_scale = std::nullopt);
  // Whether the last draw() left the displayed picture whole in attachment 1: asked for, and no
  // transparent mesh blended over it (blending acts on radiance, not on displayed values).
  bool drew_display() const;
  // Whether draw() with these options blends a transparent mesh over the picture.
  bool blends(const LocalOptions& options) const;
  // As draw() with `display_scale`, into the rectangle of the bound framebuffer whose lower-left
  // corner is `origin` (GL's pixels) and nothing outside it: the viewer draws what its window
  // shows straight into it, with the window's back buffer as draw buffer 1 and no draw buffer 0
  // (gl::bind_window_for_display). Only for options that do not blend (blends()).
  // `clear_everywhere`: nothing outside the rectangle is shown this frame, so the background may
  // be cleared over the whole framebuffer, which Mesa's software rasteriser does at memory speed
  // (a rectangle it clears by drawing a quad, 4-5 times slower per pixel).
  void draw_display(const Camera& camera, glm::ivec2 origin, glm::ivec2 size, const LocalOptions& options,
                    float display_scale, bool clear_everywhere = false);

  // Renders into a float framebuffer and reads back linear radiance (row 0 at the top).
  Image render(const Camera& camera, int width, int height, const LocalOptions& options);

  // What the renderer had to simplify, one sentence each (more lights than its uniform arrays
  // hold, see local_renderer.cpp); the caller prints or shows them. Each is reported once.
  const std::vector<std::string>& warnings() const;

  // The emissive triangles as the shaders receive them (merged when there are more than 64),
  // for the CPU twin of the formula (local_terms.h).
  const std::vector<AreaLight>& area_lights() const;

  // For the CPU twin (local_terms.h), what the last draw() looked up: its shadow maps (nullopt
  // when it drew without), and the reflection of mesh `mesh` (its cube map when it has one, and
  // the surroundings). Texels are read from the GPU on demand: the renderer's context must be
  // current, and the lookups are valid until the next draw().
  std::optional<ShadowLookup> shadow_lookup() const;
  ReflectionLookup reflection_lookup(int mesh) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace luz
