// glTF 2.0 (.gltf / .glb) -> Scene, following SCENES.md.
//
// [SECTION] Shared helpers: messages, indices, extras values
// [SECTION] Before tinygltf: read the file, check the JSON, the URIs and the buffer sizes
// [SECTION] tinygltf: file system and image callbacks, its errors turned into our kinds
// [SECTION] Node tree: transforms composed down the hierarchy; meshes, cameras and lights at
//           the nodes (gltf_geometry.cpp, gltf_lights_cameras.cpp)
// [SECTION] load_gltf
//
// Decisions the contract leaves open:
// - glTF material i is Scene::materials[i]. The default material ("default", kd 0.8 grey) is
//   appended after them only when some primitive has no material, so indices stay the file's.
// - Unsupported but legal glTF (quantized positions, an extension the file requires) is refused
//   as bad_value rather than drawn wrongly. Orthographic cameras, points and lines are skipped with
//   a warning, as SCENES.md says.
// - tinygltf 2.7 trusts the file in places (an image's bufferView is read without checking it
//   fits its buffer, accessors are not checked at all), so those bounds are checked here, and
//   every external URI is checked before tinygltf may read it.
#include "io/gltf_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include <fmt/format.h>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "io/default_lights.h"
#include "io/gltf_internal.h"

namespace luz::io {

namespace fs = std::filesystem;
using gltf::Context;
using gltf::describe;
using i18n::N_;
using i18n::tr;
using i18n::trf;

// ------------------------------------------------------------------------------------------------
// [SECTION] Shared helpers
// ------------------------------------------------------------------------------------------------

namespace gltf {

void Context::check_index(int index, size_t size, const std::string& what,
                          const std::string& array) const {
  if (index < 0 || size_t(index) >= size)
    fail(ErrorKind::index_out_of_range,
         trf("{} {} is out of range ({} {})", what, index, size, array));
}

std::string describe(const std::string& kind, size_t index, const std::string& name) {
  return name.empty() ? fmt::format("{} {}", kind, index)
                      : fmt::format("{} {} \"{}\"", kind, index, name);
}

float read_number(const Context& ctx, const tinygltf::Value& value, const std::string& what) {
  if (!value.IsNumber()) ctx.fail(ErrorKind::bad_value, trf("{} must be a number", what));
  // The program computes in float: a value beyond its range is as unusable as infinity.
  const float f = float(value.GetNumberAsDouble());
  if (std::isnan(f)) ctx.fail(ErrorKind::not_finite, trf("{} is NaN", what));
  if (!std::isfinite(f)) ctx.fail(ErrorKind::not_finite, trf("{} is infinite", what));
  return f;
}

Rgb read_rgb(const Context& ctx, const tinygltf::Value& value, const std::string& what) {
  if (value.IsNumber()) return Rgb(read_number(ctx, value, what));  // a scalar means grey
  if (!value.IsArray() || value.ArrayLen() != 3)
    ctx.fail(ErrorKind::bad_value, trf("{} must be a number or [r, g, b]", what));
  return Rgb(read_number(ctx, value.Get(0), what), read_number(ctx, value.Get(1), what),
             read_number(ctx, value.Get(2), what));
}

const tinygltf::Value* member(const tinygltf::Value& object, const std::string& key) {
  if (!object.IsObject() || !object.Has(key)) return nullptr;
  return &object.Get(key);
}

const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions,
                                 const std::string& name) {
  auto it = extensions.find(name);
  return it == extensions.end() ? nullptr : &it->second;
}

}  // namespace gltf

namespace {

// ------------------------------------------------------------------------------------------------
// [SECTION] Before tinygltf
// ------------------------------------------------------------------------------------------------

// What the checks before parsing know: the file name for messages and the scene's folder.
struct Source {
  std::string file;
  fs::path folder;  // absolute, canonical
  [[noreturn]] void fail(ErrorKind kind, const std::string& problem) const {
    throw Error(kind, gltf::one_line(file + ": " + problem));
  }
};

// nlohmann's message without its "[json.exception.parse_error.101] " prefix, and with the raw
// input bytes it quotes ("last read: ...") made printable, so that it stays one clean line.
std::string json_error(const nlohmann::json::exception& e) {
  std::string message = e.what();
  if (const size_t end = message.find("] "); message.rfind("[json.exception", 0) == 0 && end != std::string::npos)
    message.erase(0, end + 2);
  for (char& c : message)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) c = '?';
  return message;
}

std::vector<unsigned char> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

// SCENES.md: external URIs resolve relative to the scene file and may not leave its folder.
void check_uri(const Source& source, const std::string& element, const std::string& uri) {
  if (const char* why = gltf::why_outside(source.folder, uri))
    source.fail(ErrorKind::uri_outside_folder,
                trf("{}: URI \"{}\" {}; only files in the scene's folder are read", element, uri, tr(why)));
}

// The size of the data a base64 data URI holds, or -1 when it is not base64.
long long data_uri_size(const std::string& uri) {
  const size_t comma = uri.find(',');
  if (comma == std::string::npos || uri.rfind(";base64", comma) == std::string::npos) return -1;
  const size_t length = uri.size() - comma - 1;
  if (length % 4 != 0) return -1;
  size_t padding = 0;
  for (size_t i = uri.size(); i > comma + 1 && uri[i - 1] == '=' && padding < 2; --i) ++padding;
  // RFC 4648's alphabet, with '=' only as the padding at the end.
  for (size_t i = comma + 1; i < uri.size() - padding; ++i) {
    const unsigned char c = static_cast<unsigned char>(uri[i]);
    if (!std::isalnum(c) && c != '+' && c != '/') return -1;
  }
  return static_cast<long long>(length / 4 * 3 - padding);
}

// A non-negative integer member of a JSON object, or -1 when absent or of another type (tinygltf
// then reports the problem itself).
long long json_size(const nlohmann::json& object, const char* key) {
  if (!object.is_object()) return -1;
  auto it = object.find(key);
  if (it == object.end() || !it->is_number_integer()) return -1;
  return it->get<long long>();
}

// The JSON text of a .gltf, or the JSON chunk of a .glb (whose header is checked here, tinygltf
// trusts the length fields).
std::string json_text(const Source& source, const std::vector<unsigned char>& bytes, bool binary) {
  if (!binary) return std::string(bytes.begin(), bytes.end());
  auto u32 = [&](size_t at) {
    uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
  };
  if (bytes.size() < 20) source.fail(ErrorKind::truncated_buffer, tr("the GLB header is cut short"));
  if (u32(4) != 2) source.fail(ErrorKind::not_gltf, trf("GLB version {} is not 2", u32(4)));
  if (u32(8) > bytes.size())
    source.fail(ErrorKind::truncated_buffer, trf("the GLB header says {} bytes, the file "
                                                 "has {}", u32(8), bytes.size()));
  const size_t json_length = u32(12);
  if (u32(16) != 0x4E4F534Au)  // "JSON"
    source.fail(ErrorKind::not_gltf, tr("the first GLB chunk is not JSON"));
  if (json_length > bytes.size() - 20)
    source.fail(ErrorKind::truncated_buffer, trf("the GLB JSON chunk needs {} bytes, the "
                                                 "file has {}", json_length, bytes.size() - 20));
  // A BIN chunk of no bytes is no buffer (a glTF buffer holds at least one byte); tinygltf
  // refuses it in words that contradict themselves.
  const size_t bin_at = 20 + json_length;
  if (bytes.size() - bin_at >= 8 && u32(bin_at + 4) == 0x004E4942u /* "BIN\0" */ && u32(bin_at) == 0)
    source.fail(ErrorKind::bad_value, tr("the GLB's BIN chunk is empty (a glTF buffer holds at least one byte)"));
  return std::string(bytes.begin() + 20, bytes.begin() + 20 + long(json_length));
}

// glTF 1.0 (asset.version "1.0", or no asset and the 1.0 layout of objects keyed by name) is
// a different format; only 2.x is read.
void check_version(const Source& source, const nlohmann::json& doc) {
  auto asset = doc.find("asset");
  if (asset == doc.end() || !asset->is_object()) {
    for (const char* array : {"meshes", "nodes", "scenes", "accessors", "materials"})
      if (auto it = doc.find(array); it != doc.end() && it->is_object())
        source.fail(ErrorKind::not_gltf, tr("glTF 1.0 is not supported (Luz reads glTF 2.0)"));
    return;  // tinygltf reports the missing asset object
  }
  auto version = asset->find("version");
  if (version == asset->end() || !version->is_string()) return;  // tinygltf reports it
  const std::string text = version->get<std::string>();
  if (text.rfind("1.", 0) == 0 || text == "1")
    source.fail(ErrorKind::not_gltf, trf("glTF 1.0 is not supported (asset.version \"{}\"; "
                                         "Luz reads glTF 2.0)", text));
  if (text.rfind("2.", 0) != 0)
    source.fail(ErrorKind::not_gltf, trf("glTF version \"{}\" is not supported (Luz reads "
                                         "glTF 2.0)", gltf::one_line(text)));
}

// The glTF extensions Luz reads. One that a file lists in extensionsRequired and that is not
// here means the file cannot be drawn correctly without it, so the file is refused (glTF spec
// 3.12); one that is only in extensionsUsed is ignored with a warning (see load_gltf).
constexpr const char* kImplementedExtensions[] = {
    "KHR_lights_punctual",         "KHR_materials_emissive_strength", "KHR_materials_ior",
    "KHR_materials_transmission",  "KHR_mesh_quantization",           "KHR_texture_transform",
};

bool is_implemented(const std::string& extension) {
  return std::any_of(std::begin(kImplementedExtensions), std::end(kImplementedExtensions),
                     [&](const char* name) { return extension == name; });
}

void check_required_extensions(const Source& source, const nlohmann::json& doc) {
  auto required = doc.find("extensionsRequired");
  if (required == doc.end() || !required->is_array()) return;
  for (const nlohmann::json& name : *required)
    if (name.is_string() && !is_implemented(name.get<std::string>()))
      source.fail(ErrorKind::bad_value,
                  trf("requires the glTF extension {}, which Luz does not implement",
                      gltf::one_line(name.get<std::string>())));
}

// glTF: aspectRatio, when present, is > 0 (tinygltf reads an absent one as 0, which the camera
// takes as "use the image's aspect", so a written 0 is caught here).
void check_camera_aspects(const Source& source, const nlohmann::json& doc) {
  auto cameras = doc.find("cameras");
  if (cameras == doc.end() || !cameras->is_array()) return;
  for (size_t i = 0; i < cameras->size(); ++i) {
    const nlohmann::json& camera = (*cameras)[i];
    if (!camera.is_object() || !camera.contains("perspective") || !camera["perspective"].is_object())
      continue;
    const nlohmann::json& p = camera["perspective"];
    if (auto a = p.find("aspectRatio"); a != p.end() && a->is_number() && !(a->get<double>() > 0.0))
      source.fail(ErrorKind::bad_value,
                  trf("camera {}: aspectRatio {} is not positive (leave it out to use the "
                      "image's aspect)", i, a->dump()));
  }
}

// Checks what tinygltf would read without checking: the URIs and sizes of buffers, and that an
// image's bufferView lies inside its buffer. Also turns JSON syntax errors into not_gltf and
// numbers beyond double's range (1e999) into not_finite.
void check_before_parsing(const Source& source, const std::string& text) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::out_of_range& e) {  // 406: number overflow, e.g. 1e999
    source.fail(ErrorKind::not_finite, trf("a number is not finite ({})", json_error(e)));
  } catch (const nlohmann::json::exception& e) {
    source.fail(ErrorKind::not_gltf, trf("not glTF: the JSON does not parse ({})", json_error(e)));
  }
  if (!doc.is_object()) source.fail(ErrorKind::not_gltf, tr("not glTF: the JSON is not an object"));
  check_version(source, doc);
  check_required_extensions(source, doc);
  check_camera_aspects(source, doc);

  std::vector<long long> buffer_lengths;
  if (auto buffers = doc.find("buffers"); buffers != doc.end() && buffers->is_array()) {
    for (size_t i = 0; i < buffers->size(); ++i) {
      const nlohmann::json& buffer = (*buffers)[i];
      const long long declared = json_size(buffer, "byteLength");
      buffer_lengths.push_back(declared);
      if (!buffer.is_object() || !buffer.contains("uri") || !buffer["uri"].is_string()) continue;
      const std::string uri = buffer["uri"].get<std::string>();
      const std::string element = fmt::format("buffer {}", i);
      long long has = -1;
      if (gltf::is_data_uri(uri)) {
        has = data_uri_size(uri);
        if (has < 0) source.fail(ErrorKind::not_gltf, trf("{}: its data URI is not base64", element));
      } else {
        check_uri(source, element, uri);
        const fs::path file = source.folder / gltf::uri_path(uri);
        std::error_code ec;
        if (!fs::is_regular_file(file, ec))
          source.fail(ErrorKind::file_missing,
                      trf("{}: \"{}\" does not exist or is not a file", element, uri));
        has = static_cast<long long>(fs::file_size(file, ec));
      }
      if (declared >= 0 && has < declared)
        source.fail(ErrorKind::truncated_buffer,
                    trf("{} \"{}\" is cut short (has {} bytes, byteLength says {})", element,
                        gltf::is_data_uri(uri) ? "data URI" : uri, has, declared));
      if (declared >= 0 && has > declared)  // tinygltf insists on the exact size
        source.fail(ErrorKind::bad_value,
                    trf("{} \"{}\" has {} bytes but byteLength says {}", element,
                        gltf::is_data_uri(uri) ? "data URI" : uri, has, declared));
    }
  }

  const nlohmann::json* views = nullptr;
  if (auto it = doc.find("bufferViews"); it != doc.end() && it->is_array()) views = &*it;
  if (auto images = doc.find("images"); images != doc.end() && images->is_array()) {
    for (size_t i = 0; i < images->size(); ++i) {
      const nlohmann::json& image = (*images)[i];
      const std::string element = fmt::format("image {}", i);
      if (!image.is_object()) continue;
      if (image.contains("uri") && image["uri"].is_string()) {
        // An image outside the folder is not refused: it is looked for beside the scene
        // (gltf_materials.cpp), and a missing image is only a warning.
        const std::string uri = image["uri"].get<std::string>();
        if (gltf::is_data_uri(uri) && uri.rfind(";base64,") != std::string::npos && data_uri_size(uri) < 0)
          source.fail(ErrorKind::not_gltf, trf("{}: its data URI is not base64", element));
      }
      const long long view = json_size(image, "bufferView");
      if (!image.contains("bufferView")) continue;
      const size_t view_count = views ? views->size() : 0;
      if (view < 0 || size_t(view) >= view_count)
        source.fail(ErrorKind::index_out_of_range,
                    trf("{}: bufferView {} is out of range ({} bufferViews)", element,
                        image["bufferView"].dump(), view_count));
      const nlohmann::json& bv = (*views)[size_t(view)];
      const long long buffer = json_size(bv, "buffer");
      if (buffer < 0 || size_t(buffer) >= buffer_lengths.size())
        source.fail(ErrorKind::index_out_of_range,
                    trf("bufferView {}: buffer {} is out of range ({} buffers)", view,
                        buffer, buffer_lengths.size()));
      const long long offset = std::max(json_size(bv, "byteOffset"), 0LL);
      const long long length = json_size(bv, "byteLength");
      const long long available = buffer_lengths[size_t(buffer)];
      if (length < 1 || available < 0 || offset > available || length > available - offset)
        source.fail(ErrorKind::truncated_buffer,
                    trf("bufferView {} of {} reaches past the end of buffer {} (needs {} "
                        "bytes, has {})", view, element, buffer, offset + length, available));
    }
  }
}

// ------------------------------------------------------------------------------------------------
// [SECTION] tinygltf callbacks and errors
// ------------------------------------------------------------------------------------------------

// File system callbacks: paths are taken as they are (no ~ or $VAR expansion) and nothing outside
// the scene's folder exists for tinygltf, which otherwise also searches the working directory.
bool file_exists(const std::string& path, void* folder) {
  std::error_code ec;
  return gltf::inside(*static_cast<const fs::path*>(folder), path) && fs::is_regular_file(path, ec);
}

// The URI part of the path tinygltf joined to the folder: its backslashes are separators.
std::string expand_file_path(const std::string& path, void* folder) {
  const std::string base = static_cast<const fs::path*>(folder)->string();
  if (path.rfind(base, 0) != 0) return path;
  std::string rest = path.substr(base.size());  // tinygltf has percent-decoded it already
  std::replace(rest.begin(), rest.end(), '\\', '/');
  return base + rest;
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* folder) {
  if (!file_exists(path, folder)) {
    if (err) *err += "cannot read " + path;
    return false;
  }
  *out = read_bytes(path);
  return true;
}

// The image "loader" only keeps the encoded bytes; decoding (and the white fallback) happens
// afterwards with io::decode_texture, where a bad image is a warning and not a failed load.
bool keep_image_bytes(tinygltf::Image*, const int index, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* images) {
  auto& kept = *static_cast<std::map<int, std::vector<unsigned char>>*>(images);
  kept[index] = std::vector<unsigned char>(bytes, bytes + std::max(size, 0));
  return true;
}

std::string first_line(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line;
}

// tinygltf reports in prose; the few failures left after the checks above map to our kinds.
ErrorKind kind_of_tinygltf_error(const std::string& err) {
  for (const char* truncated : {"File size mismatch", "Invalid `byteLength'", "Insufficient",
                                "exceeds the GLB size", "Too short data size"})
    if (err.find(truncated) != std::string::npos) return ErrorKind::truncated_buffer;
  if (err.find("File not found") != std::string::npos) return ErrorKind::file_missing;
  return ErrorKind::not_gltf;
}

// ------------------------------------------------------------------------------------------------
// [SECTION] Node tree
// ------------------------------------------------------------------------------------------------

void check_float_range(const Context& ctx, const std::vector<double>& values, const std::string& what) {
  for (double v : values)
    if (!std::isfinite(float(v)))
      ctx.fail(ErrorKind::not_finite, trf("{} is not finite ({} is beyond float range)", what, v));
}

// The node's local matrix: `matrix`, or T * R * S (glTF).
glm::dmat4 local_transform(const Context& ctx, const tinygltf::Node& node, const std::string& what) {
  check_float_range(ctx, node.matrix, what + ": matrix");
  check_float_range(ctx, node.translation, what + ": translation");
  check_float_range(ctx, node.rotation, what + ": rotation");
  check_float_range(ctx, node.scale, what + ": scale");
  if (node.matrix.size() == 16) {
    // glTF node matrices are affine: the last row (elements 3, 7, 11, 15, column-major) is
    // 0 0 0 1. Another last row (0 0 0 0 collapses every point onto w = 0) is no placement.
    const std::vector<double>& m = node.matrix;
    if (m[3] != 0.0 || m[7] != 0.0 || m[11] != 0.0 || m[15] != 1.0)
      ctx.fail(ErrorKind::bad_value, trf("{}: matrix's last row is {} {} {} {}, not 0 0 0 1",
                                         what, m[3], m[7], m[11], m[15]));
    return glm::make_mat4(node.matrix.data());  // column-major, as glTF
  }
  if (!node.matrix.empty())
    ctx.fail(ErrorKind::bad_value, trf("{}: matrix has {} numbers, not 16", what, node.matrix.size()));
  glm::dmat4 t(1.0), r(1.0), s(1.0);
  if (node.translation.size() == 3) t[3] = glm::dvec4(glm::make_vec3(node.translation.data()), 1.0);
  else if (!node.translation.empty()) ctx.fail(ErrorKind::bad_value, trf("{}: translation needs 3 numbers", what));
  if (node.rotation.size() == 4) {
    // glTF stores x, y, z, w; glm's constructor takes w first.
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    if (!(glm::length(q) > 0.0)) ctx.fail(ErrorKind::bad_value, trf("{}: rotation is a zero quaternion", what));
    r = glm::mat4_cast(glm::normalize(q));
  } else if (!node.rotation.empty()) {
    ctx.fail(ErrorKind::bad_value, trf("{}: rotation needs 4 numbers", what));
  }
  if (node.scale.size() == 3) s = glm::scale(glm::dmat4(1.0), glm::make_vec3(node.scale.data()));
  else if (!node.scale.empty()) ctx.fail(ErrorKind::bad_value, trf("{}: scale needs 3 numbers", what));
  return t * r * s;
}

// Walks the default scene's node trees depth first, in file order, so that "the first camera in
// node order" is the first one met. An explicit stack: a deep file cannot overflow ours.
void walk_nodes(const Context& ctx, int default_material, Scene& scene) {
  const tinygltf::Model& model = ctx.model;
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const int chosen = model.defaultScene == -1 ? 0 : model.defaultScene;
    ctx.check_index(chosen, model.scenes.size(), "the default scene", "scenes");
    roots = model.scenes[size_t(chosen)].nodes;
    for (int root : roots)
      ctx.check_index(root, model.nodes.size(), describe("scene", size_t(chosen), model.scenes[size_t(chosen)].name) + ": node", "nodes");
  } else {  // no scene: every node that is nobody's child is a root
    std::vector<bool> is_child(model.nodes.size(), false);
    for (const tinygltf::Node& node : model.nodes)
      for (int child : node.children)
        if (child >= 0 && size_t(child) < is_child.size()) is_child[size_t(child)] = true;
    for (size_t i = 0; i < model.nodes.size(); ++i)
      if (!is_child[i]) roots.push_back(int(i));
  }

  struct Pending {
    int node;
    glm::dmat4 parent_to_world;
  };
  std::vector<Pending> stack;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::dmat4(1.0)});
  std::vector<bool> visited(model.nodes.size(), false);
  while (!stack.empty()) {
    const Pending pending = stack.back();
    stack.pop_back();
    const tinygltf::Node& node = model.nodes[size_t(pending.node)];
    const std::string what = describe("node", size_t(pending.node), node.name);
    if (visited[size_t(pending.node)])
      ctx.fail(ErrorKind::bad_value, trf("{}: reached twice; the node hierarchy must be a tree", what));
    visited[size_t(pending.node)] = true;

    const glm::dmat4 to_world = pending.parent_to_world * local_transform(ctx, node, what);
    if (node.mesh != -1) {
      ctx.check_index(node.mesh, model.meshes.size(), what + ": mesh", "meshes");
      gltf::add_mesh_instance(ctx, node.mesh, to_world, default_material, scene);
    }
    if (node.camera != -1) {
      ctx.check_index(node.camera, model.cameras.size(), what + ": camera", "cameras");
      gltf::add_camera(ctx, node, to_world, scene);
    }
    gltf::add_light(ctx, node, what, to_world, scene);
    for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
      ctx.check_index(*it, model.nodes.size(), what + ": child", "nodes");
      stack.push_back({*it, to_world});
    }
  }
}

// SCENES.md "Scene-wide settings": ambient, background (RGB or scalar), exposure.
void read_scene_extras(const Context& ctx, Scene& scene) {
  const tinygltf::Model& model = ctx.model;
  if (model.scenes.empty()) return;
  const int chosen = model.defaultScene == -1 ? 0 : model.defaultScene;
  const tinygltf::Value& extras = model.scenes[size_t(chosen)].extras;
  const std::string what = describe("scene", size_t(chosen), model.scenes[size_t(chosen)].name);
  if (const tinygltf::Value* v = gltf::member(extras, "ambient"))
    scene.ambient = gltf::read_rgb(ctx, *v, what + ": extras.ambient");
  if (const tinygltf::Value* v = gltf::member(extras, "background"))
    scene.background = gltf::read_rgb(ctx, *v, what + ": extras.background");
  if (const tinygltf::Value* v = gltf::member(extras, "exposure"))
    scene.exposure = gltf::read_number(ctx, *v, what + ": extras.exposure");
  for (const Rgb* c : {&scene.ambient, &scene.background})
    if (c->r < 0.0f || c->g < 0.0f || c->b < 0.0f)
      ctx.fail(ErrorKind::bad_value, trf("{}: extras.ambient and extras.background must not be negative", what));
}

}  // namespace

// ------------------------------------------------------------------------------------------------
// [SECTION] load_gltf
// ------------------------------------------------------------------------------------------------

LoadedScene load_gltf(const fs::path& path) {
  Source source;
  source.file = path.string();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    source.fail(ErrorKind::file_missing, tr("no such file (or not a regular file)"));
  source.folder = fs::weakly_canonical(fs::absolute(path).parent_path(), ec);
  std::ifstream probe(path, std::ios::binary);
  if (!probe) source.fail(ErrorKind::file_missing, tr("cannot be read"));
  const std::vector<unsigned char> bytes = read_bytes(path);
  if (bytes.size() > 0xFFFFFFF0u) source.fail(ErrorKind::bad_value, tr("files over 4 GB are not supported"));

  // A .glb starts with the magic "glTF"; anything else is taken as JSON text.
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  check_before_parsing(source, json_text(source, bytes, binary));

  LoadedScene loaded;
  tinygltf::Model model;
  Context ctx{source.file, source.folder, model, loaded.warnings, {}, {}, {}};

  tinygltf::TinyGLTF parser;
  parser.SetImageLoader(&keep_image_bytes, &ctx.image_bytes);
  fs::path folder = source.folder;
  parser.SetFsCallbacks({&file_exists, &expand_file_path, &read_whole_file, nullptr, &folder});
  std::string err, warn;
  const std::string base_dir = source.folder.string();
  const unsigned size = unsigned(bytes.size());
  const bool ok = binary ? parser.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), size, base_dir)
                         : parser.LoadASCIIFromString(&model, &err, &warn,
                                                      reinterpret_cast<const char*>(bytes.data()),
                                                      size, base_dir);
  if (!ok) {
    const ErrorKind kind = kind_of_tinygltf_error(err);
    source.fail(kind, trf("{} (tinygltf: {})",
                          kind == ErrorKind::not_gltf ? tr("not valid glTF 2.0") : tr("cannot load"),
                          first_line(err)));
  }
  // tinygltf's warnings about images are replaced by ours (which name the URI and say what is
  // used instead); the others are passed on.
  std::istringstream warn_lines(warn);
  for (std::string line; std::getline(warn_lines, line);)
    if (!line.empty() && line.find("image") == std::string::npos &&
        line.find("File not found") == std::string::npos && line.find("File read error") == std::string::npos)
      ctx.warn("tinygltf: " + first_line(line));

  for (const std::string& name : model.extensionsUsed)
    if (!is_implemented(name)) ctx.warn(trf("the glTF extension {} is not implemented; ignored", name));

  Scene& scene = loaded.scene;
  scene.path = source.file;
  gltf::add_materials(ctx, scene);
  const int default_material = int(scene.materials.size());
  walk_nodes(ctx, default_material, scene);
  gltf::warn_zero_area(ctx);
  if (scene.triangle_count() == 0) {
    // The meshes' own warnings (primitives of another mode, all triangles degenerate) say why.
    std::string why;
    for (const std::string& warning : loaded.warnings)
      if (warning.rfind(source.file + ": mesh ", 0) == 0 || warning.rfind(source.file + ": dropped ", 0) == 0)
        why += "; " + warning.substr(source.file.size() + 2);
    source.fail(ErrorKind::no_triangles, tr("no triangles to draw in the default scene") + why);
  }
  if (std::any_of(scene.meshes.begin(), scene.meshes.end(),
                  [&](const Mesh& m) { return m.material == default_material; }))
    scene.materials.push_back(Material{});  // "default": kd 0.8 grey (SCENES.md)
  read_scene_extras(ctx, scene);
  scene.generator = ctx.model.asset.generator;
  if (scene.cameras.empty()) {
    scene.cameras.push_back(Camera::framing(scene.bounds()));
    ctx.warn(tr(kNoCameraNotice));
  }
  scene.find_area_lights();
  if (io::has_no_lights(scene)) {
    io::add_default_lights(scene);
    ctx.warn(tr(io::kDefaultLightsNotice));
  }
  return loaded;
}

}  // namespace luz::io
