#pragma once
// Blocking of the sources by occlusion (slide 19; the S_i of Whitted's formula, slide 25) with
// shadow maps. All maps are layers of one R32F array texture, so a shader needs one sampler
// whatever the number of lights (GL 3.3 core has no cube-map arrays):
//   - a point light: six layers, the faces of a cube around it (+X -X +Y -Y +Z -Z, GL's order),
//     each holding the linear distance from the light to the nearest surface;
//   - a spot light: one perspective layer over its cone, the same distance (wider cones than
//     max_spot_cone take a cube, as a point light);
//   - a directional light: one orthographic layer over the scene, holding dot(P, direction);
//   - emissive triangles (area lights seen as point lights): at most max_area_shadow_groups
//     cubes; with more emitters, consecutive ones share the cube of their group, rendered from
//     the group's power-weighted centroid. Emissive meshes are left out of these maps (a lamp
//     does not shadow its own light).
// A map texel stores the nearest surface; a point is in shadow when it is farther than that, less
// the bias (local_options.h Shadows). The lookup is written twice, in shaders/lighting.glsl
// shadow_factor() and here (shadow_factor below, the CPU twin the inspector uses), step by step
// the same.
//
// Sections: [layout of the maps] [the CPU twin] [the GL maps]
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/scene.h"
#include "local/local_options.h"

namespace luz {

namespace gl {
class MeshBuffers;
class Program;
}  // namespace gl

// ---- [layout of the maps] ----------------------------------------------------------------------
enum class ShadowKind { none = 0, cube = 1, perspective = 2, orthographic = 3 };  // as lighting.glsl

inline constexpr int max_area_shadow_groups = 8;
inline constexpr float max_spot_cone = 1.2217305f;  // 70 degrees: wider spots get a cube

// Where one light's map is and how a world point finds its texel.
struct ShadowView {
  ShadowKind kind = ShadowKind::none;
  int layer = -1;                // the first (cube: of six) layer in the array
  glm::vec3 origin{0.0f};        // the light's position (cube, perspective)
  glm::vec3 direction{0, 0, -1}; // the way the light travels (orthographic)
  glm::mat4 matrix{1.0f};        // world -> the map's clip space (perspective, orthographic)
  // The world size of one texel: per metre of distance from the light (cube, perspective), or
  // absolute (orthographic).
  float texel = 0.0f;
};

// ---- [the CPU twin] ----------------------------------------------------------------------------
// What the CPU twin needs to find S_i as the shaders do: each light's view and the maps' texels
// (read from the GPU one at a time, on demand: the inspector needs a handful per click).
struct ShadowLookup {
  Shadows settings;
  std::vector<ShadowView> lights;       // per shader light (the enabled ones, in scene order)
  std::vector<ShadowView> area_lights;  // per emitter as the renderer draws them
  int size = 0;                         // texels per side of every map
  std::function<float(int layer, int x, int y)> texel;  // y = 0 at GL's bottom row
};

// lighting.glsl shadow_factor(): 1 when the light reaches world point P (unit normal N facing
// the viewer, cos_theta = N.L > 0), 0 when the map holds something nearer the light.
float shadow_factor(const ShadowLookup& maps, const ShadowView& view, const glm::vec3& P,
                    const glm::vec3& N, float cos_theta);

// lighting.glsl cube_texel(): the face (0..5, GL's order) and texel of direction D, by the
// OpenGL specification's cube-map rule (major axis, then sc, tc).
glm::ivec3 cube_texel(const glm::vec3& D, int size);

// ---- [the GL maps] -----------------------------------------------------------------------------
class ShadowMaps {
public:
  ShadowMaps();  // needs a current GL context
  ~ShadowMaps();
  ShadowMaps(const ShadowMaps&) = delete;
  ShadowMaps& operator=(const ShadowMaps&) = delete;

  // Lays out and renders every map: the scene's enabled lights (the first `max_lights`, as the
  // shaders take them) and the emitters `area_lights`. `meshes` are the scene's meshes on the GPU
  // (index for index); those with `emissive[m]` stay out of the emitters' maps. Leaves the
  // framebuffer binding and the viewport as it found them.
  void update(const Scene& scene, std::span<const AreaLight> area_lights, int max_lights,
              const Shadows& settings, const std::vector<gl::MeshBuffers>& meshes,
              const std::vector<bool>& emissive);

  const std::vector<ShadowView>& light_views() const { return light_views_; }
  const std::vector<ShadowView>& area_views() const { return area_views_; }
  unsigned texture() const { return texture_; }  // a GL_TEXTURE_2D_ARRAY of R32F layers

  // What the last update() drew, for the CPU twin (valid while this object lives; reading a
  // texel binds framebuffers, so call it with this context current, between frames).
  ShadowLookup lookup(const Shadows& settings) const;
  float texel(int layer, int x, int y) const;

private:
  void allocate(int size, int layers);
  std::vector<ShadowView> light_views_, area_views_;
  std::unique_ptr<gl::Program> program_;
  unsigned texture_ = 0, framebuffer_ = 0, depth_ = 0;
  int size_ = 0, layers_ = 0;
};

}  // namespace luz
