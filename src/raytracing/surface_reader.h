#pragma once
// What a ray met, read from the scene: the one place where an Embree hit (mesh, triangle,
// barycentrics) becomes a surface, for the Whitted tracer, its wavefront lanes and the path
// tracer alike ("calcular la normal" of slide 26, and what Color() reads of the object).
//
//   SurfaceReader surfaces(scene, textures);
//   const SurfacePoint p = surfaces.surface_at(ray, hit);  // position, normals, side, material
//   Rgb kd = surfaces.kd_at(p);                            // kd x COLOR_0 x baseColorTexture
//   Rgb Le = surfaces.emission_at(p);                      // the emission texel hit
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/scene.h"
#include "raytracing/ray.h"

namespace luz::rt {

// Where a ray met a surface: what Color() needs ("calcular la normal" of slide 26).
struct SurfacePoint {
  glm::vec3 position{0.0f};  // from the barycentrics, not o + t d (see offset_origin)
  glm::vec3 geometric{0.0f}; // unit face normal on the side the ray came from
  glm::vec3 N{0.0f};         // unit shading normal (interpolated), turned to the ray's side
  bool front = true;         // the ray hit the counter-clockwise (glTF front) face
  glm::vec2 uv{0.0f};
  glm::vec2 barycentrics{0.0f};  // (u, v) of the hit: point = A + u (B - A) + v (C - A)
  const Material* material = nullptr;
  int mesh = -1;
  int triangle = -1;
};

class SurfaceReader {
public:
  // `textures`: whether kd is multiplied by the material's base colour texture (the models'
  // TermSwitches::textures). The scene must outlive the reader.
  SurfaceReader(const Scene& scene, bool textures) : scene_(scene), textures_(textures) {}

  // The surface point of a ray's hit, written in place: a 72-byte point returned by value and
  // copied into a queue is read back before its stores have landed, which stalls the copy.
  void surface_at(const Ray& ray, const Hit& hit, SurfacePoint& p) const;
  SurfacePoint surface_at(const Ray& ray, const Hit& hit) const {
    SurfacePoint p;
    surface_at(ray, hit, p);
    return p;
  }

  // A mesh's material, or the default one.
  const Material& material_of(const Mesh& mesh) const {
    static const Material fallback;
    const bool known = mesh.material >= 0 && size_t(mesh.material) < scene_.materials.size();
    return known ? scene_.materials[size_t(mesh.material)] : fallback;
  }

  // kd x COLOR_0 x baseColorTexture at p.
  Rgb kd_at(const SurfacePoint& p) const;
  // The same at barycentrics (u, v) and texture coordinates uv of a triangle of material o.
  Rgb kd_at(const Material& o, int mesh, int triangle, glm::vec2 barycentrics, glm::vec2 uv) const;
  // Whether kd_at is o.kd itself all over `mesh`: no vertex colours, no texture sampled.
  bool kd_is_uniform(const Material& o, const Mesh& mesh) const {
    return mesh.colors.empty() && !samples_texture(o, mesh);
  }

  // Le at p: the emission texel hit (the material's Le where it has no emission map). Whether
  // p shows it (front side, an emissive material) is the caller's rule.
  Rgb emission_at(const SurfacePoint& p) const {
    return scene_.emission_at(p.mesh, size_t(p.triangle), p.barycentrics);
  }

private:
  // Whether kd_at multiplies kd by o's base colour texture on `mesh`.
  bool samples_texture(const Material& o, const Mesh& mesh) const {
    return textures_ && scene_.shown_texture(mesh, o) >= 0;
  }

  const Scene& scene_;
  bool textures_;
};

}  // namespace luz::rt
