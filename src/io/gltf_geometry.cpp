// glTF geometry -> world-space triangle meshes (SCENES.md "Format").
//
// [SECTION] Accessors: every read is bounds-checked here, because tinygltf 2.7 checks neither that
//           an accessor fits its bufferView nor that a bufferView fits its buffer.
// [SECTION] Primitives: triangles (lists, strips and fans), flattened by the node's world matrix,
//           flat normals when the file has none, zero-area triangles dropped.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "io/gltf_internal.h"

namespace luz::io::gltf {

namespace {

// ------------------------------------------------------------------------------------------------
// [SECTION] Accessors
// ------------------------------------------------------------------------------------------------

size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

size_t component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

// a + b and a * b for the "needs N bytes" of messages, saturating instead of wrapping so that a
// hostile count cannot make a huge accessor look small.
constexpr size_t kMaxSize = std::numeric_limits<size_t>::max();
size_t add_sat(size_t a, size_t b) { return a > kMaxSize - b ? kMaxSize : a + b; }
size_t mul_sat(size_t a, size_t b) { return b != 0 && a > kMaxSize / b ? kMaxSize : a * b; }

// An accessor whose every element is known to lie inside its buffer.
struct AccessorView {
  std::string name;                      // "accessor 3" for messages
  const unsigned char* first = nullptr;  // nullptr: no bufferView, every element is zero (glTF)
  size_t stride = 0;
  size_t count = 0;
  int component_type = 0;
  bool normalized = false;
  // A sparse accessor's elements, made dense here (first points into it).
  std::shared_ptr<std::vector<unsigned char>> dense;

  const unsigned char* element(size_t i) const { return first + i * stride; }
};

// The bytes of bufferView `index` after checking that it lies inside its buffer.
const unsigned char* view_bytes(const Context& ctx, int index, const std::string& what,
                                const tinygltf::BufferView*& buffer_view) {
  const tinygltf::Model& model = ctx.model;
  ctx.check_index(index, model.bufferViews.size(), what + ": bufferView", "bufferViews");
  buffer_view = &model.bufferViews[size_t(index)];
  const std::string view_name = fmt::format("bufferView {}", index);
  ctx.check_index(buffer_view->buffer, model.buffers.size(), view_name + ": buffer", "buffers");
  const std::vector<unsigned char>& data = model.buffers[size_t(buffer_view->buffer)].data;
  const size_t view_end = add_sat(buffer_view->byteOffset, buffer_view->byteLength);
  if (view_end > data.size())
    ctx.fail(ErrorKind::truncated_buffer,
             trf("{} reaches past the end of buffer {} (needs {} bytes, has {})", view_name,
                 buffer_view->buffer, view_end, data.size()));
  return data.data() + buffer_view->byteOffset;
}

// `count` tightly packed elements of `size` bytes at `offset` in bufferView `index`, checked to fit.
const unsigned char* packed_run(const Context& ctx, int index, size_t offset, size_t count,
                                size_t size, const std::string& what) {
  const tinygltf::BufferView* buffer_view = nullptr;
  const unsigned char* bytes = view_bytes(ctx, index, what, buffer_view);
  const size_t needs = add_sat(offset, mul_sat(count, size));
  if (needs > buffer_view->byteLength)
    ctx.fail(ErrorKind::truncated_buffer,
             trf("{} reaches past the end of bufferView {} (needs {} bytes, has {})", what,
                 index, needs, buffer_view->byteLength));
  return bytes + offset;
}

// glTF 2.0 sparse accessors (morph targets use them): the base elements (the bufferView's, or
// zeros), then `sparse.count` of them replaced, at the listed indices, by the listed values.
void make_dense(const Context& ctx, const tinygltf::Accessor& accessor, size_t element_size,
                AccessorView& view) {
  const auto& sparse = accessor.sparse;
  const std::string what = view.name + ": sparse";
  if (sparse.count < 1)
    ctx.fail(ErrorKind::bad_value, trf("{} count {} is not positive", what, sparse.count));
  const size_t count = size_t(sparse.count);
  if (count > view.count)
    ctx.fail(ErrorKind::bad_value, trf("{} count {} exceeds the accessor's {} elements", what,
                                       count, view.count));
  const int index_type = sparse.indices.componentType;
  const size_t index_size = index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                            : index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                            : index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                   : 0;
  if (index_size == 0)
    ctx.fail(ErrorKind::bad_value, trf("{}.indices must be unsigned bytes, shorts or ints", what));
  const unsigned char* indices = packed_run(ctx, sparse.indices.bufferView,
                                            size_t(std::max(sparse.indices.byteOffset, 0)), count,
                                            index_size, what + ".indices");
  const unsigned char* values = packed_run(ctx, sparse.values.bufferView,
                                           size_t(std::max(sparse.values.byteOffset, 0)), count,
                                           element_size, what + ".values");

  auto dense = std::make_shared<std::vector<unsigned char>>(mul_sat(view.count, element_size), 0);
  if (view.first)
    for (size_t i = 0; i < view.count; ++i)
      std::memcpy(dense->data() + i * element_size, view.element(i), element_size);
  for (size_t k = 0; k < count; ++k) {
    uint32_t target = 0;
    if (index_size == 1) target = indices[k];
    else if (index_size == 2) { uint16_t v; std::memcpy(&v, indices + 2 * k, 2); target = v; }
    else std::memcpy(&target, indices + 4 * k, 4);
    if (target >= view.count)
      ctx.fail(ErrorKind::index_out_of_range,
               trf("{}.indices: element {} is {}, past the {} elements", what, k, target, view.count));
    std::memcpy(dense->data() + size_t(target) * element_size, values + k * element_size, element_size);
  }
  view.dense = std::move(dense);
  view.first = view.dense->data();
  view.stride = element_size;
}

AccessorView view_accessor(const Context& ctx, int index, const std::string& what) {
  const tinygltf::Model& model = ctx.model;
  ctx.check_index(index, model.accessors.size(), what, "accessors");
  const tinygltf::Accessor& accessor = model.accessors[size_t(index)];
  AccessorView view;
  view.name = describe("accessor", size_t(index), accessor.name);
  view.count = accessor.count;
  view.component_type = accessor.componentType;
  view.normalized = accessor.normalized;
  const size_t element_size = component_size(accessor.componentType) * component_count(accessor.type);
  if (element_size == 0)
    ctx.fail(ErrorKind::bad_value, trf("{}: unknown componentType {} or type {}", view.name,
                                       accessor.componentType, accessor.type));
  view.stride = element_size;
  if (accessor.bufferView != -1) {
    // The bufferView must lie inside its buffer ...
    const tinygltf::BufferView* buffer_view = nullptr;
    const unsigned char* bytes = view_bytes(ctx, accessor.bufferView, view.name, buffer_view);
    const std::string view_name = fmt::format("bufferView {}", accessor.bufferView);
    if (buffer_view->byteStride != 0) {
      if (buffer_view->byteStride < element_size)
        ctx.fail(ErrorKind::bad_value,
                 trf("{}: byteStride {} is smaller than the {}-byte elements of {}", view_name,
                     buffer_view->byteStride, element_size, view.name));
      view.stride = buffer_view->byteStride;
    }
    // ... and the accessor inside its bufferView: byteOffset + stride * (count - 1) + element size.
    if (view.count > 0) {
      const size_t needs = add_sat(add_sat(accessor.byteOffset, mul_sat(view.stride, view.count - 1)),
                                   element_size);
      if (needs > buffer_view->byteLength)
        ctx.fail(ErrorKind::truncated_buffer,
                 trf("{} reaches past the end of {} (needs {} bytes, has {})", view.name,
                     view_name, needs, buffer_view->byteLength));
    }
    view.first = bytes + accessor.byteOffset;
  }
  if (accessor.sparse.isSparse) make_dense(ctx, accessor, element_size, view);
  return view;
}

void require_type(const Context& ctx, int index, const AccessorView& view, int type,
                  const char* type_name, const std::string& what) {
  if (ctx.model.accessors[size_t(index)].type != type)
    ctx.fail(ErrorKind::bad_value, trf("{}: {} must be {}", what, view.name, type_name));
}

// What is wrong with a number an attribute may not hold, in the user's language.
const char* what_number_is(float v) {
  return tr(std::isnan(v) ? N_("NaN") : std::isinf(v) ? N_("infinite") : N_("negative"));
}

// One component as a float; normalized integers map to [0, 1] (or [-1, 1]) as glTF defines.
float read_component(const unsigned char* p, int component_type, bool normalized) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float v;
      std::memcpy(&v, p, sizeof v);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const float v = float(*p);
      return normalized ? v / 255.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, sizeof v);
      return normalized ? float(v) / 65535.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {  // signed: -128 and -127 both map to -1
      int8_t v;
      std::memcpy(&v, p, sizeof v);
      return normalized ? std::max(float(v) / 127.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, sizeof v);
      return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
    }
    default: return 0.0f;  // callers only pass the types they accepted
  }
}

bool is_small_integer(int component_type) {
  return component_type == TINYGLTF_COMPONENT_TYPE_BYTE || component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         component_type == TINYGLTF_COMPONENT_TYPE_SHORT || component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

// What core glTF allows TEXCOORD_0 and COLOR_0 to hold: floats, or normalized unsigned bytes or
// shorts.
bool float_or_normalized_unsigned(const AccessorView& view) {
  const bool unsigned_integer = view.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                view.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  return view.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT || (unsigned_integer && view.normalized);
}

// KHR_mesh_quantization lets POSITION, NORMAL and TEXCOORD_0 hold 8- and 16-bit integers,
// normalized or not; the nodes' transforms scale them back (gltfpack writes such files).
bool quantized(const Context& ctx) {
  const std::vector<std::string>& used = ctx.model.extensionsUsed;
  return std::find(used.begin(), used.end(), "KHR_mesh_quantization") != used.end();
}

// VEC3 (POSITION, NORMAL) of floats, or with KHR_mesh_quantization of small integers; each
// component finite.
std::vector<glm::vec3> read_vec3(const Context& ctx, int index, const std::string& what) {
  const AccessorView view = view_accessor(ctx, index, what);
  require_type(ctx, index, view, TINYGLTF_TYPE_VEC3, "VEC3", what);
  if (is_small_integer(view.component_type) && !quantized(ctx))
    ctx.fail(ErrorKind::bad_value, trf("{}: {} holds integers, which need the extension KHR_mesh_quantization",
                                       what, view.name));
  if (view.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT && !is_small_integer(view.component_type))
    ctx.fail(ErrorKind::bad_value, trf("{}: {} must hold floats", what, view.name));
  std::vector<glm::vec3> out(view.count, glm::vec3(0.0f));
  if (!view.first) return out;
  const size_t size = component_size(view.component_type);
  for (size_t i = 0; i < view.count; ++i) {
    const unsigned char* p = view.element(i);
    for (int c = 0; c < 3; ++c) {
      out[i][c] = read_component(p + size * size_t(c), view.component_type, view.normalized);
      if (!std::isfinite(out[i][c]))
        ctx.fail(ErrorKind::not_finite, trf("{}: element {} is {}", what, i, what_number_is(out[i][c])));
    }
  }
  return out;
}

// TEXCOORD_0: float VEC2, or normalized unsigned byte / short as the glTF spec allows, or with
// KHR_mesh_quantization any small integers.
std::vector<glm::vec2> read_texcoords(const Context& ctx, int index, const std::string& what) {
  const AccessorView view = view_accessor(ctx, index, what);
  require_type(ctx, index, view, TINYGLTF_TYPE_VEC2, "VEC2", what);
  if (!float_or_normalized_unsigned(view) && !(quantized(ctx) && is_small_integer(view.component_type)))
    ctx.fail(ErrorKind::bad_value,
             trf("{}: {} must hold floats or normalized unsigned bytes/shorts", what, view.name));
  std::vector<glm::vec2> out(view.count, glm::vec2(0.0f));
  if (!view.first) return out;
  const size_t size = component_size(view.component_type);
  for (size_t i = 0; i < view.count; ++i) {
    for (int c = 0; c < 2; ++c) {
      out[i][c] = read_component(view.element(i) + size * size_t(c), view.component_type, view.normalized);
      if (!std::isfinite(out[i][c]))
        ctx.fail(ErrorKind::not_finite, trf("{}: element {} is {}", what, i, what_number_is(out[i][c])));
    }
  }
  return out;
}

// COLOR_0: RGB or RGBA (alpha dropped), float or normalized unsigned byte / short (glTF).
std::vector<Rgb> read_colors(const Context& ctx, int index, const std::string& what) {
  const AccessorView view = view_accessor(ctx, index, what);
  const int type = ctx.model.accessors[size_t(index)].type;
  if (type != TINYGLTF_TYPE_VEC3 && type != TINYGLTF_TYPE_VEC4)
    ctx.fail(ErrorKind::bad_value, trf("{}: {} must be VEC3 or VEC4", what, view.name));
  if (!float_or_normalized_unsigned(view))
    ctx.fail(ErrorKind::bad_value,
             trf("{}: {} must hold floats or normalized unsigned bytes/shorts", what, view.name));
  std::vector<Rgb> out(view.count, Rgb(0.0f));
  if (!view.first) return out;
  const size_t size = component_size(view.component_type);
  for (size_t i = 0; i < view.count; ++i) {
    for (int c = 0; c < 3; ++c) {
      const float v = read_component(view.element(i) + size * size_t(c), view.component_type, true);
      if (!std::isfinite(v) || v < 0.0f)
        ctx.fail(v < 0.0f ? ErrorKind::bad_value : ErrorKind::not_finite,
                 trf("{}: element {} is {}", what, i, what_number_is(v)));
      out[i][c] = v;
    }
  }
  return out;
}

// Indices: scalar unsigned byte, short or int.
std::vector<uint32_t> read_indices(const Context& ctx, int index, const std::string& what) {
  const AccessorView view = view_accessor(ctx, index, what);
  require_type(ctx, index, view, TINYGLTF_TYPE_SCALAR, "SCALAR", what);
  std::vector<uint32_t> out(view.count, 0u);
  if (!view.first) return out;
  for (size_t i = 0; i < view.count; ++i) {
    const unsigned char* p = view.element(i);
    switch (view.component_type) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: out[i] = *p; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p, sizeof v);
        out[i] = v;
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: std::memcpy(&out[i], p, sizeof(uint32_t)); break;
      default:
        ctx.fail(ErrorKind::bad_value,
                 trf("{}: {} must hold unsigned bytes, shorts or ints", what, view.name));
    }
  }
  return out;
}

bool is_finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// ------------------------------------------------------------------------------------------------
// [SECTION] Primitives
// ------------------------------------------------------------------------------------------------

// A triangle is dropped as zero-area when sin(angle at its first corner) <= 1e-6, i.e.
// |e1 x e2|^2 <= 1e-12 |e1|^2 |e2|^2: exactly zero for repeated or collinear vertices, and
// still zero after float rounding has moved collinear vertices by an ulp or so.
bool is_degenerate(const glm::vec3& e1, const glm::vec3& e2) {
  const glm::vec3 c = glm::cross(e1, e2);
  const double lhs = double(glm::dot(c, c));
  const double rhs = 1e-12 * double(glm::dot(e1, e1)) * double(glm::dot(e2, e2));
  return lhs <= rhs;
}

// glTF 2.0 "Topology types": triangle i of a strip is (v_i, v_{i+1+i%2}, v_{i+2-i%2}), so every
// other triangle takes its last two corners swapped and all of them wind as the first does;
// triangle i of a fan is (v_{i+1}, v_{i+2}, v_0). A strip's triangles that repeat a vertex are the
// joins between strips, degenerate on purpose, and are left out without a word.
std::vector<uint32_t> as_triangle_list(int mode, const std::vector<uint32_t>& v) {
  std::vector<uint32_t> list;
  for (size_t i = 0; i + 2 < v.size(); ++i) {
    const uint32_t a = mode == TINYGLTF_MODE_TRIANGLE_FAN ? v[i + 1] : v[i];
    const uint32_t b = mode == TINYGLTF_MODE_TRIANGLE_FAN ? v[i + 2] : v[i + 1 + i % 2];
    const uint32_t c = mode == TINYGLTF_MODE_TRIANGLE_FAN ? v[0] : v[i + 2 - i % 2];
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP && (a == b || b == c || a == c)) continue;
    list.insert(list.end(), {a, b, c});
  }
  return list;
}

// The primitive modes Luz does not draw, in words for the warning (glTF's modes 0 to 3).
const char* mode_in_words(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS: return N_("points");
    case TINYGLTF_MODE_LINE: return N_("lines");
    case TINYGLTF_MODE_LINE_LOOP: return N_("line loops");
    case TINYGLTF_MODE_LINE_STRIP: return N_("line strips");
    default: return N_("primitives of an unknown mode");
  }
}

bool is_triangles(int mode) {
  return mode == -1 || mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
         mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

}  // namespace

void add_mesh_instance(const Context& ctx, int mesh_index, const glm::dmat4& to_world,
                       int default_material, Scene& scene) {
  const tinygltf::Mesh& gltf_mesh = ctx.model.meshes[size_t(mesh_index)];
  const std::string mesh_name = describe("mesh", size_t(mesh_index), gltf_mesh.name);

  // Positions go by the node matrix, normals by its inverse transpose (then renormalised). A
  // mirroring matrix (negative determinant) turns counter-clockwise faces clockwise: swapping two
  // corners of every triangle keeps the front faces counter-clockwise as glTF wants.
  const glm::dmat3 linear(to_world);
  const double determinant = glm::determinant(linear);
  const bool flip_winding = determinant < 0.0;
  const glm::mat4 position_matrix(to_world);
  const glm::mat3 normal_matrix =
      determinant != 0.0 ? glm::mat3(glm::transpose(glm::inverse(linear))) : glm::mat3(1.0f);

  // Points and lines have no area to light: one warning per mesh names what it skipped.
  std::vector<int> skipped_modes;
  for (const tinygltf::Primitive& primitive : gltf_mesh.primitives)
    if (!is_triangles(primitive.mode) &&
        std::find(skipped_modes.begin(), skipped_modes.end(), primitive.mode) == skipped_modes.end())
      skipped_modes.push_back(primitive.mode);
  if (!skipped_modes.empty()) {
    std::string what;
    for (int mode : skipped_modes)
      what += fmt::format("{}{} (mode {})", what.empty() ? "" : ", ", tr(mode_in_words(mode)), mode);
    ctx.warn(trf("{}: skipped its {}; only triangles are drawn", mesh_name, what));
  }

  size_t dropped = 0;
  for (size_t p = 0; p < gltf_mesh.primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = gltf_mesh.primitives[p];
    if (!is_triangles(primitive.mode)) continue;
    const std::string where = fmt::format("{} primitive {}", mesh_name, p);
    auto attribute = [&](const char* name) {
      auto it = primitive.attributes.find(name);
      return it == primitive.attributes.end() ? -1 : it->second;
    };
    const int position_accessor = attribute("POSITION");
    if (position_accessor == -1) ctx.fail(ErrorKind::bad_value, trf("{}: has no POSITION", where));

    std::vector<glm::vec3> positions = read_vec3(ctx, position_accessor, where + ": POSITION");
    const size_t vertex_count = positions.size();
    std::vector<glm::vec3> normals;
    if (const int a = attribute("NORMAL"); a != -1) normals = read_vec3(ctx, a, where + ": NORMAL");
    std::vector<glm::vec2> uvs;
    if (const int a = attribute("TEXCOORD_0"); a != -1)
      uvs = read_texcoords(ctx, a, where + ": TEXCOORD_0");
    std::vector<Rgb> colors;
    if (const int a = attribute("COLOR_0"); a != -1) colors = read_colors(ctx, a, where + ": COLOR_0");
    if (!uvs.empty() && primitive.material != -1 &&
        size_t(primitive.material) < ctx.model.materials.size())
      apply_texture_transform(ctx, primitive.material, uvs);
    auto same_count = [&](size_t n, const char* name) {
      if (n != 0 && n != vertex_count)
        ctx.fail(ErrorKind::bad_value, trf("{}: {} has {} elements but POSITION has {}",
                                           where, name, n, vertex_count));
    };
    same_count(normals.size(), "NORMAL");
    same_count(uvs.size(), "TEXCOORD_0");
    same_count(colors.size(), "COLOR_0");
    // Normals to world space. One with no direction (zero, or crushed by the node's matrix)
    // cannot light its vertex: the primitive is drawn with its faces' normals, as without NORMAL.
    for (size_t i = 0; i < normals.size(); ++i) {
      const glm::vec3 n = normal_matrix * normals[i];
      const float length = glm::length(n);
      if (!(length > 0.0f) || !std::isfinite(length)) {
        ctx.warn(trf("{}: NORMAL {} has no direction; the faces' normals are used", where, i));
        normals.clear();
        break;
      }
      normals[i] = n / length;
    }
    const bool has_normals = !normals.empty();

    std::vector<uint32_t> indices;
    if (primitive.indices != -1) {
      indices = read_indices(ctx, primitive.indices, where + ": indices");
    } else {  // non-indexed: vertices 0, 1, 2 make the first triangle, and so on
      indices.resize(vertex_count);
      for (size_t i = 0; i < vertex_count; ++i) indices[i] = uint32_t(i);
    }
    const bool list = primitive.mode == -1 || primitive.mode == TINYGLTF_MODE_TRIANGLES;
    if (list && indices.size() % 3 != 0)
      ctx.fail(ErrorKind::bad_value, trf("{}: {} indices are not a whole number of "
                                         "triangles", where, indices.size()));
    for (size_t i = 0; i < indices.size(); ++i)
      if (indices[i] >= vertex_count)
        ctx.fail(ErrorKind::index_out_of_range,
                 trf("{}: index {} (element {}) is past the {} vertices", where, indices[i],
                     i, vertex_count));
    if (!list) indices = as_triangle_list(primitive.mode, indices);

    // To world space.
    for (size_t i = 0; i < vertex_count; ++i) {
      positions[i] = glm::vec3(position_matrix * glm::vec4(positions[i], 1.0f));
      if (!is_finite(positions[i]))
        ctx.fail(ErrorKind::not_finite,
                 trf("{}: vertex {} is not finite in world space", where, i));
    }

    Mesh mesh;
    mesh.name = gltf_mesh.name.empty() ? trf("mesh {}", mesh_index) : gltf_mesh.name;
    if (primitive.material == -1) {
      mesh.material = default_material;
    } else {
      ctx.check_index(primitive.material, ctx.model.materials.size(), where + ": material",
                      "materials");
      mesh.material = primitive.material;
    }
    if (has_normals) {
      mesh.positions = std::move(positions);
      mesh.normals = std::move(normals);
      mesh.uvs = std::move(uvs);
      mesh.colors = std::move(colors);
    }
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
      uint32_t corner[3] = {indices[t], indices[t + 1], indices[t + 2]};
      if (flip_winding) std::swap(corner[1], corner[2]);
      const glm::vec3 a = has_normals ? mesh.positions[corner[0]] : positions[corner[0]];
      const glm::vec3 b = has_normals ? mesh.positions[corner[1]] : positions[corner[1]];
      const glm::vec3 c = has_normals ? mesh.positions[corner[2]] : positions[corner[2]];
      if (is_degenerate(b - a, c - a)) {
        ++dropped;
        continue;
      }
      if (has_normals) {
        mesh.indices.insert(mesh.indices.end(), corner, corner + 3);
        continue;
      }
      // No NORMAL: the face normal (glTF spec), so each face gets vertices of its own.
      const glm::vec3 face_normal = glm::normalize(glm::cross(b - a, c - a));
      for (uint32_t k : corner) {
        mesh.indices.push_back(uint32_t(mesh.positions.size()));
        mesh.positions.push_back(positions[k]);
        mesh.normals.push_back(face_normal);
        if (!uvs.empty()) mesh.uvs.push_back(uvs[k]);
        if (!colors.empty()) mesh.colors.push_back(colors[k]);
      }
    }
    if (!mesh.indices.empty()) scene.meshes.push_back(std::move(mesh));
  }
  if (dropped > 0) ctx.zero_area[mesh_index] = {mesh_name, dropped};
}

void warn_zero_area(const Context& ctx) {
  if (ctx.zero_area.empty()) return;
  if (ctx.zero_area.size() == 1) {
    const auto& [name, dropped] = ctx.zero_area.begin()->second;
    ctx.warn(dropped == 1 ? trf("{}: dropped 1 zero-area triangle", name)
                          : trf("{}: dropped {} zero-area triangles", name, dropped));
    return;
  }
  std::vector<std::pair<std::string, size_t>> meshes;
  size_t total = 0;
  for (const auto& [index, mesh] : ctx.zero_area) {
    meshes.push_back(mesh);
    total += mesh.second;
  }
  std::stable_sort(meshes.begin(), meshes.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  constexpr size_t kNamed = 3;
  const size_t named = std::min(kNamed, meshes.size());
  std::string list;
  for (size_t i = 0; i < named; ++i)
    list += fmt::format("{}{} ({})", i == 0 ? "" : ", ", meshes[i].first, meshes[i].second);
  ctx.warn(meshes.size() > kNamed
               ? trf("dropped {} zero-area triangles in {} meshes, most in {}", total, meshes.size(), list)
               : trf("dropped {} zero-area triangles in {} meshes: {}", total, meshes.size(), list));
}

}  // namespace luz::io::gltf
