#include "gltf_fixture.h"

#include <array>
#include <cstring>
#include <fstream>

namespace luz::test {

using nlohmann::json;

Primitive triangle(int material) {
  Primitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  p.indices = {0, 1, 2};
  p.material = material;
  return p;
}

GltfBuilder::GltfBuilder() {
  doc["asset"] = {{"version", "2.0"}};
  doc["scene"] = 0;
  doc["scenes"] = json::array({{{"nodes", json::array()}}});
}

int GltfBuilder::add_view(const void* data, size_t size, size_t stride) {
  while (bin.size() % 4 != 0) bin.push_back(0);
  const size_t offset = bin.size();
  bin.resize(offset + size);
  if (size > 0) std::memcpy(bin.data() + offset, data, size);
  json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}};
  if (stride != 0) view["byteStride"] = stride;
  doc["bufferViews"].push_back(view);
  return int(doc["bufferViews"].size() - 1);
}

int GltfBuilder::add_accessor(int view, int component_type, size_t count, const std::string& type,
                              size_t byte_offset, bool normalized) {
  json accessor = {{"bufferView", view}, {"componentType", component_type}, {"count", count},
                   {"type", type}};
  if (byte_offset != 0) accessor["byteOffset"] = byte_offset;
  if (normalized) accessor["normalized"] = true;
  doc["accessors"].push_back(accessor);
  return int(doc["accessors"].size() - 1);
}

int GltfBuilder::add_vec3(const std::vector<glm::vec3>& values) {
  const int view = add_view(values.data(), values.size() * sizeof(glm::vec3));
  return add_accessor(view, kFloat, values.size(), "VEC3");
}

int GltfBuilder::add_vec2(const std::vector<glm::vec2>& values) {
  const int view = add_view(values.data(), values.size() * sizeof(glm::vec2));
  return add_accessor(view, kFloat, values.size(), "VEC2");
}

int GltfBuilder::add_indices(const std::vector<uint32_t>& values, int component_type) {
  std::vector<unsigned char> bytes;
  for (uint32_t v : values) {
    if (component_type == kUnsignedByte) {
      bytes.push_back(static_cast<unsigned char>(v));
    } else if (component_type == kUnsignedShort) {
      const uint16_t s = static_cast<uint16_t>(v);
      bytes.insert(bytes.end(), reinterpret_cast<const unsigned char*>(&s),
                   reinterpret_cast<const unsigned char*>(&s) + 2);
    } else {
      bytes.insert(bytes.end(), reinterpret_cast<const unsigned char*>(&v),
                   reinterpret_cast<const unsigned char*>(&v) + 4);
    }
  }
  const int view = add_view(bytes.data(), bytes.size());
  return add_accessor(view, component_type, values.size(), "SCALAR");
}

int GltfBuilder::mesh(const std::vector<Primitive>& primitives, const std::string& name) {
  json mesh = {{"primitives", json::array()}};
  if (!name.empty()) mesh["name"] = name;
  for (const Primitive& p : primitives) {
    json primitive = {{"attributes", {{"POSITION", add_vec3(p.positions)}}}};
    if (!p.normals.empty()) primitive["attributes"]["NORMAL"] = add_vec3(p.normals);
    if (!p.uvs.empty()) primitive["attributes"]["TEXCOORD_0"] = add_vec2(p.uvs);
    if (!p.colors.empty()) primitive["attributes"]["COLOR_0"] = add_vec3(p.colors);
    if (!p.indices.empty()) primitive["indices"] = add_indices(p.indices, p.index_type);
    if (p.material != -1) primitive["material"] = p.material;
    if (p.mode != -1) primitive["mode"] = p.mode;
    mesh["primitives"].push_back(primitive);
  }
  doc["meshes"].push_back(mesh);
  return int(doc["meshes"].size() - 1);
}

int GltfBuilder::material(const json& material) {
  doc["materials"].push_back(material);
  return int(doc["materials"].size() - 1);
}

int GltfBuilder::camera(const json& camera) {
  doc["cameras"].push_back(camera);
  return int(doc["cameras"].size() - 1);
}

int GltfBuilder::light(const json& light) {
  json& lights = doc["extensions"]["KHR_lights_punctual"]["lights"];
  lights.push_back(light);
  doc["extensionsUsed"] = json::array({"KHR_lights_punctual"});
  return int(lights.size() - 1);
}

int GltfBuilder::texture_from_file(const std::string& uri, const std::vector<unsigned char>& bytes) {
  files_.emplace_back(uri, bytes);
  doc["images"].push_back({{"uri", uri}});
  doc["textures"].push_back({{"source", doc["images"].size() - 1}});
  return int(doc["textures"].size() - 1);
}

int GltfBuilder::node(const json& node, bool root) {
  doc["nodes"].push_back(node);
  const int index = int(doc["nodes"].size() - 1);
  if (root) doc["scenes"][0]["nodes"].push_back(index);
  return index;
}

static std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t b0 = bytes[i];
    const uint32_t b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0u;
    const uint32_t b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0u;
    const uint32_t triple = (b0 << 16) | (b1 << 8) | b2;
    out += alphabet[(triple >> 18) & 63];
    out += alphabet[(triple >> 12) & 63];
    out += i + 1 < bytes.size() ? alphabet[(triple >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? alphabet[triple & 63] : '=';
  }
  return out;
}

std::filesystem::path GltfBuilder::write_gltf(const ScratchDir& dir, const std::string& name,
                                              bool embed_buffer) const {
  json out = doc;
  if (!bin.empty() && !out.contains("buffers")) {
    const std::string bin_name = std::filesystem::path(name).stem().string() + ".bin";
    const std::string uri =
        embed_buffer ? "data:application/octet-stream;base64," + base64(bin) : bin_name;
    out["buffers"] = json::array({{{"uri", uri}, {"byteLength", bin.size()}}});
    if (!embed_buffer) write_file(dir / bin_name, bin);
  }
  for (const auto& [uri, bytes] : files_) write_file(dir / uri, bytes);
  write_file(dir / name, out.dump(1));
  return dir / name;
}

std::filesystem::path GltfBuilder::write_glb(const ScratchDir& dir, const std::string& name) const {
  json out = doc;
  if (!bin.empty() && !out.contains("buffers")) out["buffers"] = json::array({{{"byteLength", bin.size()}}});
  for (const auto& [uri, bytes] : files_) write_file(dir / uri, bytes);
  std::string text = out.dump();
  while (text.size() % 4 != 0) text += ' ';  // the JSON chunk is padded with spaces
  std::vector<unsigned char> chunk = bin;
  while (chunk.size() % 4 != 0) chunk.push_back(0);

  std::vector<unsigned char> glb;
  auto u32 = [&](uint32_t v) {
    glb.insert(glb.end(), reinterpret_cast<unsigned char*>(&v), reinterpret_cast<unsigned char*>(&v) + 4);
  };
  const size_t total = 12 + 8 + text.size() + (chunk.empty() ? 0 : 8 + chunk.size());
  glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
  u32(2);
  u32(uint32_t(total));
  u32(uint32_t(text.size()));
  u32(0x4E4F534Au);  // "JSON"
  glb.insert(glb.end(), text.begin(), text.end());
  if (!chunk.empty()) {
    u32(uint32_t(chunk.size()));
    u32(0x004E4942u);  // "BIN\0"
    glb.insert(glb.end(), chunk.begin(), chunk.end());
  }
  write_file(dir / name, glb);
  return dir / name;
}

GltfBuilder one_triangle(const json& material) {
  GltfBuilder b;
  const int m = material.is_null() ? -1 : b.material(material);
  b.node({{"mesh", b.mesh({triangle(m)})}});
  return b;
}

// --- A minimal PNG writer: zlib "stored" blocks need no compressor -----------------------------

static uint32_t crc32(const unsigned char* data, size_t size, uint32_t crc = 0) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (size_t i = 0; i < size; ++i) crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

std::vector<unsigned char> png_rgb8(int width, int height, const std::vector<unsigned char>& rgb) {
  std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  auto be32 = [](std::vector<unsigned char>& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>(v >> shift));
  };
  auto chunk = [&](const char* type, const std::vector<unsigned char>& data) {
    be32(png, uint32_t(data.size()));
    std::vector<unsigned char> typed(type, type + 4);
    typed.insert(typed.end(), data.begin(), data.end());
    png.insert(png.end(), typed.begin(), typed.end());
    be32(png, crc32(typed.data(), typed.size()));
  };
  std::vector<unsigned char> header;
  be32(header, uint32_t(width));
  be32(header, uint32_t(height));
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bit, RGB, deflate, no filter, no interlace
  chunk("IHDR", header);

  std::vector<unsigned char> raw;  // each row: filter byte 0, then the pixels
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);
    const auto row = rgb.begin() + long(y) * width * 3;
    raw.insert(raw.end(), row, row + long(width) * 3);
  }
  std::vector<unsigned char> z = {0x78, 0x01};  // zlib header
  for (size_t at = 0; at < raw.size() || at == 0; at += 65535) {
    const size_t n = std::min<size_t>(65535, raw.size() - at);
    z.push_back(at + n >= raw.size() ? 1 : 0);  // final block?
    z.push_back(static_cast<unsigned char>(n & 0xFF));
    z.push_back(static_cast<unsigned char>(n >> 8));
    z.push_back(static_cast<unsigned char>(~n & 0xFF));
    z.push_back(static_cast<unsigned char>((~n >> 8) & 0xFF));
    z.insert(z.end(), raw.begin() + long(at), raw.begin() + long(at + n));
    if (raw.empty()) break;
  }
  uint32_t a = 1, b = 0;  // Adler-32 of the raw data
  for (unsigned char c : raw) {
    a = (a + c) % 65521;
    b = (b + a) % 65521;
  }
  be32(z, (b << 16) | a);
  chunk("IDAT", z);
  chunk("IEND", {});
  return png;
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

void write_file(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// A closed room 4 x 3 x 6 m (x, y, z), its six walls facing inwards, with a camera inside near
// its front wall looking down -Z at the back wall, as Blender exports a room.
GltfBuilder closed_room() {
  GltfBuilder b;
  const int white = b.material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}},
                                                          {"metallicFactor", 0.0}}}});
  const glm::vec3 lo(-2, 0, -3), hi(2, 3, 3);
  // Each wall as two triangles, counter-clockwise seen from inside.
  auto wall = [&](glm::vec3 a, glm::vec3 b1, glm::vec3 c, glm::vec3 d) {
    Primitive p;
    p.positions = {a, b1, c, d};
    p.indices = {0, 1, 2, 0, 2, 3};
    p.material = white;
    return p;
  };
  const std::vector<Primitive> walls = {
      wall({lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}),  // back
      wall({lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z}),  // front
      wall({lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}),  // floor
      wall({lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}),  // ceiling
      wall({lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {lo.x, lo.y, hi.z}),  // left
      wall({hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z})}; // right
  b.node({{"mesh", b.mesh(walls, "room")}});
  b.node({{"camera", b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.05}}}})},
          {"translation", {0, 1.5, 2.5}}});
  return b;
}

}  // namespace luz::test
