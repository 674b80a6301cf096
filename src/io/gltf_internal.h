#pragma once
// What the parts of the glTF loader share (gltf_loader.cpp, gltf_geometry.cpp,
// gltf_materials.cpp). Private to src/io: only these files include tiny_gltf.h.
#include <filesystem>
#include <map>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <tiny_gltf.h>

#include "core/error.h"
#include "core/i18n.h"
#include "core/scene.h"
#include "io/gltf_uris.h"

namespace luz::io::gltf {

// Every message of the loader is in the user's language (tr, trf: core/i18n.h); the glTF names
// it quotes (node 3 "lamp", baseColorFactor, KHR_lights_punctual) stay as the file has them.
using i18n::N_;
using i18n::tr;
using i18n::trf;

// Messages are one line: control characters (a newline in a material's name, say) become '?'.
inline std::string one_line(std::string text) {
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = '?';
  return text;
}

// The file being loaded, the parsed model and where warnings go. Every message starts with the
// file as the user gave it, so that each one reads "FILE: problem" (STYLE.md 7).
struct Context {
  std::string file;
  std::filesystem::path folder;  // the scene's, absolute and canonical
  const tinygltf::Model& model;
  std::vector<std::string>& warnings;
  // Encoded bytes of every image tinygltf handed to our image loader, by image index. An image
  // that is absent here could not be read (tinygltf only warned).
  std::map<int, std::vector<unsigned char>> image_bytes;
  mutable std::unordered_set<std::string> told;  // the warnings given so far
  // Zero-area triangles dropped, by mesh index: the mesh's name and the count. Told in one
  // warning when the file is read (CAD exports drop some in hundreds of meshes).
  mutable std::map<int, std::pair<std::string, size_t>> zero_area;

  [[noreturn]] void fail(ErrorKind kind, const std::string& problem) const {
    throw Error(kind, one_line(file + ": " + problem));
  }
  // A mesh drawn by several nodes is read once per node: its problem is told once.
  void warn(const std::string& problem) const {
    std::string line = one_line(file + ": " + problem);
    if (told.insert(line).second) warnings.push_back(std::move(line));
  }

  // Throws index_out_of_range unless 0 <= index < size; `what` names the referring element,
  // e.g. `node 3 "lamp": mesh` -> `node 3 "lamp": mesh 7 is out of range (5 meshes)`.
  void check_index(int index, size_t size, const std::string& what,
                   const std::string& array) const;
};

// The largest emitted radiance Le and light intensity accepted (per channel): sums of many such
// terms, times pi and areas, stay far inside float's range (3.4e38), so no renderer overflows.
inline constexpr float kMaxEmitted = 1e18f;

// `kind index "name"` or `kind index` when the element has no name, for messages.
std::string describe(const std::string& kind, size_t index, const std::string& name);

// Reads `value` (a glTF extras/extension member) as a finite float; `what` names it for errors.
float read_number(const Context& ctx, const tinygltf::Value& value, const std::string& what);
// A scalar (grey) or [r, g, b].
Rgb read_rgb(const Context& ctx, const tinygltf::Value& value, const std::string& what);
// The member `key` of an object value, or nullptr when the value is not an object or lacks it.
const tinygltf::Value* member(const tinygltf::Value& object, const std::string& key);
// The extension object `name` in an extension map, or nullptr.
const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions,
                                 const std::string& name);

// gltf_geometry.cpp: the triangle primitives of glTF mesh `mesh_index`, flattened to world space
// by `to_world`, appended to scene.meshes. `default_material` is the index that primitives
// without a material get.
void add_mesh_instance(const Context& ctx, int mesh_index, const glm::dmat4& to_world,
                       int default_material, Scene& scene);
// The zero-area triangles the meshes dropped, as one warning: the mesh and its count when one
// mesh dropped some, else the total, the number of meshes and the three that dropped most.
void warn_zero_area(const Context& ctx);

// gltf_lights_cameras.cpp: the node's perspective camera (orthographic ones are skipped with a
// warning) and its KHR_lights_punctual light, if any; `node_what` names the node in messages.
void add_camera(const Context& ctx, const tinygltf::Node& node, const glm::dmat4& to_world,
                Scene& scene);
void add_light(const Context& ctx, const tinygltf::Node& node, const std::string& node_what,
               const glm::dmat4& to_world, Scene& scene);

// gltf_materials.cpp: applies the KHR_texture_transform of material `material`'s
// baseColorTexture, if it has one, to a primitive's TEXCOORD_0 (the program samples the texture
// at the transformed coordinates).
void apply_texture_transform(const Context& ctx, int material, std::vector<glm::vec2>& uvs);

// gltf_materials.cpp: glTF materials -> scene.materials (same indices), and the base colour
// textures they use -> scene.textures.
void add_materials(Context& ctx, Scene& scene);

}  // namespace luz::io::gltf
