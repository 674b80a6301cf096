#include "radiosity/texture_detail.h"

namespace luz {

TextureDetail::TextureDetail(const Scene& scene) : scene_(scene) {
  for (const Texture& texture : scene.textures) {
    const Rgb mean = texture.mean();
    Rgb inverse(0.0f);
    for (int c = 0; c < 3; ++c) inverse[c] = mean[c] > 0.0f ? 1.0f / mean[c] : 0.0f;
    inverse_means_.push_back(inverse);
  }
}

const Texture* TextureDetail::texture_of(int mesh) const {
  const Mesh& m = scene_.meshes[size_t(mesh)];
  if (m.uvs.empty() || m.material < 0 || size_t(m.material) >= scene_.materials.size()) return nullptr;
  const int texture = scene_.materials[size_t(m.material)].kd_texture;
  return texture >= 0 && size_t(texture) < scene_.textures.size() ? &scene_.textures[size_t(texture)] : nullptr;
}

Rgb TextureDetail::inverse_mean(int mesh) const {
  const Texture* texture = texture_of(mesh);
  return texture ? inverse_means_[size_t(texture - scene_.textures.data())] : Rgb(1.0f);
}

Rgb TextureDetail::at(int mesh, int triangle, glm::vec2 b) const {
  const Texture* texture = texture_of(mesh);
  if (!texture) return Rgb(1.0f);
  const glm::vec2 uv = scene_.meshes[size_t(mesh)].uv_at(size_t(triangle), b);
  return texture->sample(uv) * inverse_mean(mesh);
}

}  // namespace luz
