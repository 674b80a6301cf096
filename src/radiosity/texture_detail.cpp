#include "radiosity/texture_detail.h"

namespace luz {
namespace {

// The index in scene.textures of the kd texture scene mesh `mesh` shows, or -1 (a mesh without
// a material of the scene's has the default one, which has no texture).
int shown_texture(const Scene& scene, int mesh) {
  const Mesh& m = scene.meshes[size_t(mesh)];
  if (m.material < 0 || size_t(m.material) >= scene.materials.size()) return -1;
  return scene.shown_texture(m, scene.materials[size_t(m.material)]);
}

}  // namespace

TextureDetail::TextureDetail(const Scene& scene, bool textures) : scene_(&scene), textures_(textures) {
  if (!textures) return;
  for (const Texture& texture : scene.textures) {
    const Rgb mean = texture.mean();
    Rgb inverse(0.0f);
    for (int c = 0; c < 3; ++c) inverse[c] = mean[c] > 0.0f ? 1.0f / mean[c] : 0.0f;
    means_.push_back(mean);
    inverse_means_.push_back(inverse);
  }
}

bool TextureDetail::any_shown(const Scene& scene) {
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (shown_texture(scene, int(m)) >= 0) return true;
  return false;
}

int TextureDetail::index_of(int mesh) const { return textures_ ? shown_texture(*scene_, mesh) : -1; }

const Texture* TextureDetail::texture_of(int mesh) const {
  const int i = index_of(mesh);
  return i >= 0 ? &scene_->textures[size_t(i)] : nullptr;
}

Rgb TextureDetail::mean(int mesh) const {
  const int i = index_of(mesh);
  return i >= 0 ? means_[size_t(i)] : Rgb(1.0f);
}

Rgb TextureDetail::inverse_mean(int mesh) const {
  const int i = index_of(mesh);
  return i >= 0 ? inverse_means_[size_t(i)] : Rgb(1.0f);
}

Rgb TextureDetail::at(int mesh, int triangle, glm::vec2 b) const {
  const int i = index_of(mesh);
  if (i < 0) return Rgb(1.0f);
  const glm::vec2 uv = scene_->meshes[size_t(mesh)].uv_at(size_t(triangle), b);
  return scene_->textures[size_t(i)].sample(uv) * inverse_means_[size_t(i)];
}

}  // namespace luz
