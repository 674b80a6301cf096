#pragma once
// Builds small glTF scenes from C++ so that each loader test states its scene in a few lines:
//
//   GltfBuilder b;
//   int m = b.material({{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}});
//   b.node({{"mesh", b.mesh({triangle(m)})}});
//   io::load_gltf(b.write_gltf(dir));
//
// The JSON document is public, so a test can break it in any way it likes before writing.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "support.h"

namespace luz::test {

// glTF component types.
constexpr int kByte = 5120;
constexpr int kUnsignedByte = 5121;
constexpr int kShort = 5122;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;

// One primitive as plain arrays; empty arrays are left out of the file.
struct Primitive {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  std::vector<glm::vec3> colors;  // COLOR_0 as float VEC3
  std::vector<uint32_t> indices;
  int index_type = kUnsignedInt;  // component type of the indices
  int material = -1;              // -1: no material
  int mode = -1;                  // -1: absent (triangles)
};

// The unit right triangle (0,0,0), (1,0,0), (0,1,0) in z = 0, counter-clockwise seen from +Z.
Primitive triangle(int material = -1);

class GltfBuilder {
 public:
  nlohmann::json doc;              // the glTF document; "buffers" is filled in when writing
  std::vector<unsigned char> bin;  // the one binary buffer

  GltfBuilder();  // asset 2.0 and one scene (scene 0, the default) with no nodes yet

  // Appends bytes to the buffer (4-aligned) and a bufferView over them; returns its index.
  int add_view(const void* data, size_t size, size_t stride = 0);
  // Appends an accessor; returns its index.
  int add_accessor(int view, int component_type, size_t count, const std::string& type,
                   size_t byte_offset = 0, bool normalized = false);
  int add_vec3(const std::vector<glm::vec3>& values);  // float VEC3
  int add_vec2(const std::vector<glm::vec2>& values);  // float VEC2
  int add_indices(const std::vector<uint32_t>& values, int component_type = kUnsignedInt);

  int mesh(const std::vector<Primitive>& primitives, const std::string& name = "");
  int material(const nlohmann::json& material);
  int camera(const nlohmann::json& camera);
  int light(const nlohmann::json& light);  // a KHR_lights_punctual light
  // An image stored as a file beside the scene (written by write_gltf) and a texture using it.
  int texture_from_file(const std::string& uri, const std::vector<unsigned char>& bytes);
  // Appends a node; a root node is also listed in scene 0. Returns its index.
  int node(const nlohmann::json& node, bool root = true);

  // Writes DIR/NAME with its buffer as NAME-without-extension.bin beside it, or embedded as a
  // base64 data URI. Returns the path of the .gltf.
  std::filesystem::path write_gltf(const ScratchDir& dir, const std::string& name = "scene.gltf",
                                   bool embed_buffer = false) const;
  // Writes DIR/NAME as a binary .glb with the buffer in its BIN chunk.
  std::filesystem::path write_glb(const ScratchDir& dir, const std::string& name = "scene.glb") const;

 private:
  std::vector<std::pair<std::string, std::vector<unsigned char>>> files_;  // images beside it
};

// A scene of one triangle (material `material`, or none) at a root node.
GltfBuilder one_triangle(const nlohmann::json& material = nullptr);

// A closed room 4 x 3 x 6 m (x from -2 to 2, y from 0 to 3, z from -3 to 3), its six white
// (kd 0.8) walls facing inwards, with a camera inside at (0, 1.5, 2.5) looking down -Z at the back
// wall: a room as Blender exports it, without lights.
GltfBuilder closed_room();

// An uncompressed 8-bit RGB PNG of `width` x `height` pixels (rgb: 3 bytes per pixel, rows top
// first): just enough PNG to test texture decoding without an image library in the tests.
std::vector<unsigned char> png_rgb8(int width, int height, const std::vector<unsigned char>& rgb);

void write_file(const std::filesystem::path& path, const std::string& text);
void write_file(const std::filesystem::path& path, const std::vector<unsigned char>& bytes);

}  // namespace luz::test
