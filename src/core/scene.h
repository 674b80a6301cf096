#pragma once
// The scene every model reads (SCENES.md): world-space triangle meshes, materials, textures,
// punctual lights, emissive triangles as area lights, cameras and the scene-wide settings.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/color.h"
#include "core/image.h"
#include "core/light.h"
#include "core/material.h"

namespace luz {

struct Bounds {
  glm::vec3 min{1e30f};
  glm::vec3 max{-1e30f};
  void grow(const glm::vec3& p);
  bool empty() const { return min.x > max.x; }
  glm::vec3 centre() const { return 0.5f * (min + max); }
  glm::vec3 extent() const { return max - min; }
};

// Linear RGB texels (sRGB-decoded on load), row 0 at the top of the image as glTF's UVs expect
// (u right, v down).
struct Texture {
  std::string name;
  int width = 1;
  int height = 1;
  Pixels texels{Rgb(1.0f)};
  Rgb texel(int x, int y) const { return texels[size_t(y) * width + x]; }
  // At uv: bilinear, repeating, texel centres at (i + 0.5) / width, what GL's linear filter does
  // on the base level.
  Rgb sample(glm::vec2 uv) const;
  Rgb mean() const;  // of all its texels
};

// One glTF primitive, flattened to world space. Every vertex has a normal: the file's, or the
// face normal when the file has none (vertices are then not shared between faces).
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;       // empty when the primitive has no TEXCOORD_0
  std::vector<Rgb> colors;          // COLOR_0, multiplies kd; empty when the primitive has none
  std::vector<uint32_t> indices;    // three per triangle
  int material = 0;                 // index into Scene::materials

  size_t triangle_count() const { return indices.size() / 3; }
  // COLOR_0 at barycentrics (u, v) of `triangle` (weights 1 - u - v, u, v of its three corners),
  // white when the mesh has no vertex colours: the factor every model multiplies kd by.
  Rgb colour_at(size_t triangle, const glm::vec2& barycentrics) const;
  // TEXCOORD_0 at barycentrics (u, v) of `triangle`, (0, 0) when the mesh has none.
  glm::vec2 uv_at(size_t triangle, const glm::vec2& barycentrics) const;
};

// An emissive triangle seen as a light (SCENES.md "Emissive triangles are area lights").
struct AreaLight {
  int mesh = 0;
  int triangle = 0;
  glm::vec3 centroid{0.0f};
  glm::vec3 normal{0, 1, 0};  // unit, the side it emits from
  float area = 0.0f;
  Rgb radiance{0.0f};         // Le
};

struct Scene {
  std::string path;                  // the file it came from, for messages
  std::vector<Mesh> meshes;
  std::vector<Material> materials;   // at least one: meshes without material use the default
  std::vector<Texture> textures;
  std::vector<Light> lights;
  std::vector<AreaLight> area_lights;
  std::vector<Camera> cameras;       // never empty after loading (a framing camera is added)
  Rgb ambient{0.0f};                 // I_a
  Rgb background{0.0f};              // radiance of rays that hit nothing
  float exposure = 0.0f;             // EV of the scene's pictures
  std::string generator;             // asset.generator: the program that wrote the file
  bool default_lights = false;       // the file had no light: add_default_lights placed `lights`

  Bounds bounds() const;
  size_t triangle_count() const;
  // Collects the emissive triangles into area_lights (called by the loader).
  void find_area_lights();
  // The camera called `name_or_index` (a name, or its index in node order); -1 when none.
  int find_camera(const std::string& name_or_index) const;
  // The index in `textures` of the kd texture `mesh` shows with `material`, or -1: none, or the
  // mesh has no TEXCOORD_0 to place it by. Every model shows a texture by this rule.
  int shown_texture(const Mesh& mesh, const Material& material) const;
  // The same for the emissive texture, which multiplies Le.
  int shown_emission_texture(const Mesh& mesh, const Material& material) const;
  // Le at barycentrics (u, v) of triangle `triangle` of meshes[mesh]: the material's emission
  // times the emissive texel there (what the local models, Whitted and the path tracer show).
  Rgb emission_at(int mesh, size_t triangle, glm::vec2 barycentrics) const;
  // The mean of Le over the part of that triangle whose corners have barycentrics `corners`
  // (the whole triangle: (0, 0), (1, 0), (0, 1)): what radiosity shoots from an element and what
  // an area light emits.
  Rgb mean_emission(int mesh, size_t triangle, const std::array<glm::vec2, 3>& corners) const;
  std::string to_string() const;
};

}  // namespace luz
