#include "core/scene.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace luz {

Rgb Texture::sample(glm::vec2 uv) const {
  const float x = uv.x * float(width) - 0.5f, y = uv.y * float(height) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float ax = x - fx, ay = y - fy;
  const auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
  const int x0 = wrap(int(fx), width), x1 = wrap(int(fx) + 1, width);
  const int y0 = wrap(int(fy), height), y1 = wrap(int(fy) + 1, height);
  return (1 - ax) * (1 - ay) * texel(x0, y0) + ax * (1 - ay) * texel(x1, y0) + (1 - ax) * ay * texel(x0, y1) +
         ax * ay * texel(x1, y1);
}

Rgb Texture::mean() const {
  Rgb sum(0.0f);
  for (const Rgb& t : texels) sum += t;
  return sum / float(std::max<size_t>(1, texels.size()));
}

int Scene::shown_texture(const Mesh& mesh, const Material& material) const {
  const int t = material.kd_texture;
  return t >= 0 && size_t(t) < textures.size() && !mesh.uvs.empty() ? t : -1;
}

int Scene::shown_emission_texture(const Mesh& mesh, const Material& material) const {
  const int t = material.emission_texture;
  return t >= 0 && size_t(t) < textures.size() && !mesh.uvs.empty() ? t : -1;
}

Rgb Scene::emission_at(int mesh_index, size_t triangle, glm::vec2 barycentrics) const {
  const Mesh& mesh = meshes[size_t(mesh_index)];
  const Material& material = materials[size_t(mesh.material)];
  const int t = shown_emission_texture(mesh, material);
  if (t < 0) return material.emission;
  return material.emission * textures[size_t(t)].sample(mesh.uv_at(triangle, barycentrics));
}

// The mean by the midpoint rule on a regular grid: the part is cut into kCuts^2 triangles of equal
// area and Le is read at each one's centroid. Exact for a uniform texture; for a bilinear
// texture, exact but for the cells a texel's kink crosses.
Rgb Scene::mean_emission(int mesh_index, size_t triangle, const std::array<glm::vec2, 3>& corners) const {
  const Mesh& mesh = meshes[size_t(mesh_index)];
  const Material& material = materials[size_t(mesh.material)];
  if (shown_emission_texture(mesh, material) < 0) return material.emission;
  constexpr int kCuts = 8;
  const glm::vec2 a = corners[0], du = (corners[1] - a) / float(kCuts), dv = (corners[2] - a) / float(kCuts);
  Rgb sum(0.0f);
  for (int j = 0; j < kCuts; ++j)
    for (int i = 0; i + j < kCuts; ++i) {
      const glm::vec2 cell = a + float(i) * du + float(j) * dv;
      sum += emission_at(mesh_index, triangle, cell + (du + dv) / 3.0f);  // the cell pointing up
      if (i + j < kCuts - 1) sum += emission_at(mesh_index, triangle, cell + 2.0f * (du + dv) / 3.0f);
    }
  return sum / float(kCuts * kCuts);
}

Rgb Mesh::colour_at(size_t triangle, const glm::vec2& barycentrics) const {
  if (colors.empty()) return Rgb(1.0f);
  const float u = barycentrics.x, v = barycentrics.y;
  return (1.0f - u - v) * colors[indices[3 * triangle]] + u * colors[indices[3 * triangle + 1]] +
         v * colors[indices[3 * triangle + 2]];
}

glm::vec2 Mesh::uv_at(size_t triangle, const glm::vec2& barycentrics) const {
  if (uvs.empty()) return glm::vec2(0.0f);
  const float u = barycentrics.x, v = barycentrics.y;
  return (1.0f - u - v) * uvs[indices[3 * triangle]] + u * uvs[indices[3 * triangle + 1]] +
         v * uvs[indices[3 * triangle + 2]];
}

void Bounds::grow(const glm::vec3& p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

Bounds Scene::bounds() const {
  Bounds b;
  for (const Mesh& mesh : meshes)
    for (const glm::vec3& p : mesh.positions) b.grow(p);
  return b;
}

size_t Scene::triangle_count() const {
  size_t n = 0;
  for (const Mesh& mesh : meshes) n += mesh.triangle_count();
  return n;
}

void Scene::find_area_lights() {
  area_lights.clear();
  for (size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = meshes[m];
    const Material& material = materials[mesh.material];
    if (!material.is_emissive()) continue;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      const glm::vec3& a = mesh.positions[mesh.indices[3 * t]];
      const glm::vec3& b = mesh.positions[mesh.indices[3 * t + 1]];
      const glm::vec3& c = mesh.positions[mesh.indices[3 * t + 2]];
      const glm::vec3 cross = glm::cross(b - a, c - a);
      const float twice_area = glm::length(cross);
      if (twice_area <= 0.0f) continue;
      AreaLight light;
      light.mesh = int(m);
      light.triangle = int(t);
      light.centroid = (a + b + c) / 3.0f;
      light.normal = cross / twice_area;  // counter-clockwise front face, as glTF
      light.area = 0.5f * twice_area;
      // An emissive texture: the triangle emits its mean; a black part of it is no light.
      light.radiance = mean_emission(int(m), t, {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1)});
      if (!(light.radiance.r > 0.0f || light.radiance.g > 0.0f || light.radiance.b > 0.0f)) continue;
      area_lights.push_back(light);
    }
  }
}

int Scene::find_camera(const std::string& name_or_index) const {
  for (size_t i = 0; i < cameras.size(); ++i)
    if (cameras[i].name == name_or_index) return int(i);
  int index = -1;
  const char* end = name_or_index.data() + name_or_index.size();
  auto [ptr, ec] = std::from_chars(name_or_index.data(), end, index);
  if (ec == std::errc() && ptr == end && index >= 0 && size_t(index) < cameras.size()) return index;
  return -1;
}

std::string Scene::to_string() const {
  return fmt::format("Scene \"{}\" [{} meshes, {} triangles, {} materials, {} textures, {} lights, "
                     "{} emissive triangles, {} cameras]", path, meshes.size(), triangle_count(),
                     materials.size(), textures.size(), lights.size(), area_lights.size(),
                     cameras.size());
}

}  // namespace luz
