#pragma once
// A patch has one reflectance (slide 32's "retazos de radiosidad constante"): where kd is a
// texture, the solver takes its mean texel (PatchMesh::build, through mean()). The picture puts the texture's
// detail back: a point shows B/pi x texel / mean texel, exact where the irradiance is constant
// across the patch, the way radiosity systems map textures onto a solution computed with average
// reflectances (Cohen & Wallace, "Radiosity and Realistic Image Synthesis", 1993). The radiosity
// picture does it per fragment (radiosity_renderer.cpp) and the hybrid's diffuse part per hit,
// both from the one the mesh was built with (PatchMesh::detail).
#include <vector>

#include <glm/vec2.hpp>

#include "core/color.h"
#include "core/scene.h"

namespace luz {

class TextureDetail {
public:
  TextureDetail() = default;  // no texture anywhere
  // The scene must outlive it. `textures` false: no mesh shows a texture (`--no-textures`).
  explicit TextureDetail(const Scene& scene, bool textures = true);
  bool textures() const { return textures_; }
  // Whether any mesh of `scene` shows a kd texture: whether `textures` changes anything.
  static bool any_shown(const Scene& scene);

  // The kd texture of scene mesh `mesh` that shows on it, or nullptr: none, or the mesh has no
  // TEXCOORD_0 to place it by.
  const Texture* texture_of(int mesh) const;
  // Its mean texel: the reflectance factor the solver gives the mesh's patches (1 without a
  // texture).
  Rgb mean(int mesh) const;
  // 1 / its mean texel, per channel (0 where the mean is 0: that channel is black throughout).
  Rgb inverse_mean(int mesh) const;
  // texel / mean texel at barycentrics (b1, b2) of triangle `triangle` of scene mesh `mesh`;
  // 1 on a mesh without a texture.
  Rgb at(int mesh, int triangle, glm::vec2 b) const;

private:
  // The index in Scene::textures of texture_of(mesh), or -1.
  int index_of(int mesh) const;

  const Scene* scene_ = nullptr;
  bool textures_ = false;
  std::vector<Rgb> means_, inverse_means_;  // per scene texture, each read once
};

}  // namespace luz
