// glTF materials -> the lecture's coefficients, row by row of SCENES.md "Materials":
//
//   kd  = baseColorFactor.rgb x baseColorTexture x (1 - metallicFactor) x (1 - transmission)
//         (texture: kd_texture)
//   ka  = extras.ka, else kd
//   ks  = extras.ks, else baseColor x metallicFactor unless the material is a mirror (Metals)
//   n   = extras.shininess, else 2/r^4 - 2 clamped to [1, 10000], r = roughnessFactor
//   kr  = extras.kr, else baseColor when metallic >= 0.5 and roughness <= 0.05, else 0
//   kt  = extras.kt, else transmission x baseColor x (1 - metallicFactor), where transmission is
//         KHR_materials_transmission.transmissionFactor, else 0
//   eta = extras.ior, else KHR_materials_ior.ior, else 1.5
//   Le  = emissiveFactor x emissiveTexture x KHR_materials_emissive_strength.emissiveStrength
//         (texture: emission_texture)
//
// A base colour texture whose image is missing is left out with a warning (the material keeps its
// colour); one whose image cannot be decoded becomes a 1x1 white texture with a warning. Either
// way the scene still loads, only the texture's detail is lost.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "io/gltf_internal.h"
#include "io/image_io.h"

namespace luz::io::gltf {

namespace {

// glTF stores factors as doubles; the program works in float, so a value beyond float's range
// (1e39, say) is as unusable as infinity and is reported as such.
float to_float(const Context& ctx, double value, const std::string& what) {
  const float f = float(value);
  if (std::isnan(f)) ctx.fail(ErrorKind::not_finite, trf("{} is NaN", what));
  if (!std::isfinite(f)) ctx.fail(ErrorKind::not_finite, trf("{} is infinite", what));
  return f;
}

Rgb to_rgb(const Context& ctx, const std::vector<double>& values, size_t expected,
           const std::string& what) {
  if (values.size() != expected)
    ctx.fail(ErrorKind::bad_value, trf("{} has {} numbers, not {}", what, values.size(), expected));
  return Rgb(to_float(ctx, values[0], what), to_float(ctx, values[1], what),
             to_float(ctx, values[2], what));
}

// A reflectance above 1 reflects more light than arrives; far above (1e30) it makes radiosity's
// sums and the tracer's ray weights overflow to inf and NaN. Each channel is clamped to 1 with
// a warning, so every renderer stays finite. (glTF limits baseColorFactor to [0, 1] itself.)
Rgb clamp_to_one(const Context& ctx, Rgb c, const std::string& what) {
  if (c.r <= 1.0f && c.g <= 1.0f && c.b <= 1.0f) return c;
  ctx.warn(trf("{} ({:.3g}, {:.3g}, {:.3g}) is above 1; clamped to 1", what, c.r, c.g, c.b));
  for (int i = 0; i < 3; ++i) c[i] = std::min(c[i], 1.0f);
  return c;
}

void require_non_negative(const Context& ctx, const Rgb& c, const std::string& what) {
  if (c.r < 0.0f || c.g < 0.0f || c.b < 0.0f)
    ctx.fail(ErrorKind::bad_value, trf("{} ({}, {}, {}) is negative", what, c.r, c.g, c.b));
}

// A short label for an image in messages: its URI when it has one (data URIs are not printed,
// they can be megabytes long).
std::string image_label(const tinygltf::Image& image, size_t index) {
  if (image.uri.empty() || image.uri.rfind("data:", 0) == 0)
    return describe("image", index, image.name);
  return fmt::format("image {} \"{}\"", index, image.uri);
}

// The encoded bytes of an external image tinygltf did not read, told in one warning either way:
// a URI that leaves the scene's folder is not opened, and a file of its name beside the scene
// stands in for it (converters write `..\maps\tex.jpg` and `D:\work\tex.jpg`).
std::optional<std::vector<unsigned char>> read_image_elsewhere(const Context& ctx,
                                                               const tinygltf::Image& image,
                                                               const std::string& label) {
  if (image.uri.empty() || is_data_uri(image.uri)) {
    ctx.warn(trf("{}: cannot be read; the material is drawn without its texture", label));
    return std::nullopt;
  }
  const char* why = why_outside(ctx.folder, image.uri);
  if (!why) {
    ctx.warn(trf("{}: no such file beside the scene; the material is drawn without its texture", label));
    return std::nullopt;
  }
  const std::filesystem::path beside = beside_the_scene(ctx.folder, image.uri);
  const std::string name = beside.filename().string();
  std::error_code ec;
  if (name.empty() || !inside(ctx.folder, beside) || !std::filesystem::is_regular_file(beside, ec)) {
    ctx.warn(trf("{}: outside the scene's folder ({}), not opened, and no \"{}\" beside the "
                 "scene; the material is drawn without its texture", label, tr(why), name));
    return std::nullopt;
  }
  ctx.warn(trf("{}: outside the scene's folder ({}), not opened; using \"{}\" beside the scene",
               label, tr(why), name));
  std::ifstream in(beside, std::ios::binary);
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

// The scene texture for glTF image `index`, decoded on first use; -1 when the image cannot be
// read (the material keeps its colour, without the texture).
int texture_for_image(const Context& ctx, int index, std::map<int, int>& textures, Scene& scene) {
  if (auto it = textures.find(index); it != textures.end()) return it->second;
  const tinygltf::Image& image = ctx.model.images[size_t(index)];
  const std::string label = image_label(image, size_t(index));
  std::optional<std::vector<unsigned char>> bytes;
  // tinygltf joins even an absolute URI to the folder; what it read for a URI that leaves the
  // folder is not used.
  const bool outside = !image.uri.empty() && !is_data_uri(image.uri) && why_outside(ctx.folder, image.uri);
  if (auto kept = ctx.image_bytes.find(index); kept != ctx.image_bytes.end() && !outside)
    bytes = kept->second;
  else
    bytes = read_image_elsewhere(ctx, image, label);
  if (!bytes) return textures[index] = -1;
  Texture texture;  // 1x1 white unless decoded
  std::string error;
  if (std::optional<Texture> decoded = decode_texture(*bytes, label, error))
    texture = std::move(*decoded);
  else
    ctx.warn(trf("{}: cannot be decoded ({}); using a white texture", label, error));
  texture.name = !image.name.empty() ? image.name
                 : !image.uri.empty() && !is_data_uri(image.uri)
                     ? image.uri
                     : trf("image {}", index);
  scene.textures.push_back(std::move(texture));
  textures[index] = int(scene.textures.size() - 1);
  return textures[index];
}

// KHR_materials_transmission.transmissionFactor (0 without the extension), in [0, 1].
float transmission_factor(const Context& ctx, const tinygltf::Material& source, const std::string& what) {
  const tinygltf::Value* ext = extension(source.extensions, "KHR_materials_transmission");
  const tinygltf::Value* factor = ext ? member(*ext, "transmissionFactor") : nullptr;
  if (!factor) return 0.0f;
  const float t = read_number(ctx, *factor, what);
  if (t < 0.0f || t > 1.0f) ctx.fail(ErrorKind::bad_value, trf("{} {} is outside [0, 1]", what, t));
  return t;
}

// The scene texture a material's texture reference `info` (named `slot` in messages) uses, or -1.
template <typename TextureInfo>
int scene_texture(const Context& ctx, const TextureInfo& info, const char* slot, const std::string& what,
                  std::map<int, int>& textures, Scene& scene) {
  const int t = info.index;
  if (t == -1) return -1;
  ctx.check_index(t, ctx.model.textures.size(), what + ": " + slot, "textures");
  const tinygltf::Texture& texture = ctx.model.textures[size_t(t)];
  if (texture.source == -1) {
    ctx.warn(trf("{}: texture {} has no image; ignored", what, t));
    return -1;
  }
  ctx.check_index(texture.source, ctx.model.images.size(), fmt::format("texture {}: source", t), "images");
  if (info.texCoord != 0)
    ctx.warn(trf("{}: {} uses TEXCOORD_{}; TEXCOORD_0 is read instead", what, slot, info.texCoord));
  return texture_for_image(ctx, texture.source, textures, scene);
}

Material map_material(Context& ctx, size_t index, std::map<int, int>& textures, Scene& scene) {
  const tinygltf::Material& source = ctx.model.materials[index];
  const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
  const std::string what = describe("material", index, source.name);
  auto field = [&](const std::string& name) { return what + ": " + name; };

  Material m;
  m.name = source.name.empty() ? trf("material {}", index) : source.name;

  const Rgb base = clamp_to_one(ctx, to_rgb(ctx, pbr.baseColorFactor, 4, field("baseColorFactor")),
                                field("baseColorFactor"));
  const float metallic = to_float(ctx, pbr.metallicFactor, field("metallicFactor"));
  const float roughness = to_float(ctx, pbr.roughnessFactor, field("roughnessFactor"));
  if (metallic < 0.0f || metallic > 1.0f)
    ctx.fail(ErrorKind::bad_value, trf("{} {} is outside [0, 1]", field("metallicFactor"), metallic));
  if (roughness < 0.0f || roughness > 1.0f)
    ctx.fail(ErrorKind::bad_value, trf("{} {} is outside [0, 1]", field("roughnessFactor"), roughness));

  const tinygltf::Value& extras = source.extras;
  const float transmission = transmission_factor(ctx, source, field("transmissionFactor"));
  // glTF's transmission takes its share from the dielectric (non-metallic) base: what is
  // transmitted is not diffusely reflected, and it is tinted by the base colour. Blender's
  // default glass (white, transmission 1) is kd = 0, kt = 1.
  const Rgb dielectric = base * (1.0f - metallic);
  m.kd = dielectric * (1.0f - transmission);
  const tinygltf::Value* v = member(extras, "ka");
  m.ka = v ? read_rgb(ctx, *v, field("extras.ka")) : m.kd;
  // A smooth metal is the mirror of the classic model, tinted by its base colour.
  const bool mirror = metallic >= 0.5f && roughness <= 0.05f;
  // SCENES.md "Metals": the metallic share of the base colour is specular, never diffuse; a
  // metal that is not a mirror keeps it as the highlight, so a glTF that leaves metallicFactor at
  // its default 1 does not render black.
  v = member(extras, "ks");
  m.ks = v ? read_rgb(ctx, *v, field("extras.ks")) : mirror ? Rgb(0.0f) : base * metallic;
  v = member(extras, "shininess");
  m.shininess = v ? read_number(ctx, *v, field("extras.shininess")) : shininess_from_roughness(roughness);
  v = member(extras, "kr");
  m.kr = v ? read_rgb(ctx, *v, field("extras.kr")) : mirror ? base : Rgb(0.0f);

  v = member(extras, "kt");
  m.kt = v ? read_rgb(ctx, *v, field("extras.kt")) : dielectric * transmission;

  if ((v = member(extras, "ior"))) {
    m.ior = read_number(ctx, *v, field("ior"));
  } else if (const tinygltf::Value* ext = extension(source.extensions, "KHR_materials_ior")) {
    if (const tinygltf::Value* ior = member(*ext, "ior")) m.ior = read_number(ctx, *ior, field("ior"));
  }

  float strength = 1.0f;
  if (const tinygltf::Value* ext = extension(source.extensions, "KHR_materials_emissive_strength"))
    if (const tinygltf::Value* s = member(*ext, "emissiveStrength"))
      strength = read_number(ctx, *s, field("emissiveStrength"));
  if (!source.emissiveFactor.empty())  // absent: black
    m.emission = to_rgb(ctx, source.emissiveFactor, 3, field("emissiveFactor")) * strength;
  if (!is_finite(m.emission)) ctx.fail(ErrorKind::not_finite, field(tr("emitted radiance is infinite")));
  if (std::max({m.emission.r, m.emission.g, m.emission.b}) > kMaxEmitted)
    ctx.fail(ErrorKind::bad_value, trf("{} ({:.3g}) is above {:.0e}; sums of it would overflow",
                                       field("emitted radiance"),
                                       std::max({m.emission.r, m.emission.g, m.emission.b}), kMaxEmitted));

  m.ka = clamp_to_one(ctx, m.ka, field("ka"));
  m.ks = clamp_to_one(ctx, m.ks, field("ks"));
  m.kr = clamp_to_one(ctx, m.kr, field("kr"));
  m.kt = clamp_to_one(ctx, m.kt, field("kt"));
  // Domains: coefficients are reflectances (>= 0), eta is a ratio of speeds (> 0).
  require_non_negative(ctx, m.kd, field("kd"));
  require_non_negative(ctx, m.ka, field("ka"));
  require_non_negative(ctx, m.ks, field("ks"));
  require_non_negative(ctx, m.kr, field("kr"));
  require_non_negative(ctx, m.kt, field("kt"));
  require_non_negative(ctx, m.emission, field("emission"));
  require_non_negative(ctx, strength * Rgb(1.0f), field("emissiveStrength"));
  if (m.shininess < 0.0f)
    ctx.fail(ErrorKind::bad_value, trf("{} {} is negative", field("shininess"), m.shininess));
  if (!(m.ior > 0.0f))
    ctx.fail(ErrorKind::bad_value, trf("{} {} is not positive", field("ior"), m.ior));

  m.kd_texture = scene_texture(ctx, pbr.baseColorTexture, "baseColorTexture", what, textures, scene);
  // Le = emissiveFactor x emissiveTexture x strength: the texture only scales what the factor
  // gives (glTF's emissiveFactor defaults to black, so a texture alone emits nothing).
  if (m.is_emissive())
    m.emission_texture = scene_texture(ctx, source.emissiveTexture, "emissiveTexture", what, textures, scene);
  return m;
}

// SCENES.md: kd + kr + kt <= 1 per channel is expected of a physically sensible material; a
// scene that breaks it loads, with a warning.
void check_energy(const Context& ctx, const Material& m, const std::string& what) {
  const Rgb sum = m.kd + m.kr + m.kt;
  constexpr float kSlack = 1e-5f;  // float rounding of sums that are exactly 1 on paper
  if (sum.r > 1.0f + kSlack || sum.g > 1.0f + kSlack || sum.b > 1.0f + kSlack)
    ctx.warn(trf("{}: kd + kr + kt = ({:.3g}, {:.3g}, {:.3g}) exceeds 1; it reflects more "
                 "light than it receives", what, sum.r, sum.g, sum.b));
}

}  // namespace

// KHR_texture_transform: uv' = T(offset) * R(rotation) * S(scale) * uv, the extension's matrix,
// with R = [cos sin; -sin cos] (rows): turning the image counter-clockwise on screen, where v
// points down, turns the coordinates the other way. The sample model TextureTransformTest's
// markers (green: right, red: rotated the wrong way) check the sign.
void apply_texture_transform(const Context& ctx, int material, std::vector<glm::vec2>& uvs) {
  const tinygltf::Material& source = ctx.model.materials[size_t(material)];
  const tinygltf::TextureInfo& info = source.pbrMetallicRoughness.baseColorTexture;
  if (info.index == -1) return;
  const tinygltf::Value* transform = extension(info.extensions, "KHR_texture_transform");
  if (!transform) return;
  const std::string what = describe("material", size_t(material), source.name) +
                           ": baseColorTexture KHR_texture_transform";
  auto pair = [&](const char* key, glm::vec2 fallback) {
    const tinygltf::Value* v = member(*transform, key);
    if (!v) return fallback;
    if (!v->IsArray() || v->ArrayLen() != 2)
      ctx.fail(ErrorKind::bad_value, trf("{}.{} must be [u, v]", what, key));
    return glm::vec2(read_number(ctx, v->Get(0), what + "." + key),
                     read_number(ctx, v->Get(1), what + "." + key));
  };
  const glm::vec2 offset = pair("offset", glm::vec2(0.0f));
  const glm::vec2 scale = pair("scale", glm::vec2(1.0f));
  const tinygltf::Value* r = member(*transform, "rotation");
  const float rotation = r ? read_number(ctx, *r, what + ".rotation") : 0.0f;
  if (const tinygltf::Value* t = member(*transform, "texCoord"); t && t->IsNumber() && t->GetNumberAsInt() != 0)
    ctx.warn(trf("{}.texCoord {} is ignored; TEXCOORD_0 is read", what, t->GetNumberAsInt()));
  const float c = std::cos(rotation), s = std::sin(rotation);
  for (glm::vec2& uv : uvs) {
    const glm::vec2 scaled = scale * uv;
    uv = offset + glm::vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y);
  }
}

void add_materials(Context& ctx, Scene& scene) {
  std::map<int, int> textures;  // glTF image -> index in scene.textures
  for (size_t i = 0; i < ctx.model.materials.size(); ++i) {
    scene.materials.push_back(map_material(ctx, i, textures, scene));
    check_energy(ctx, scene.materials.back(), describe("material", i, ctx.model.materials[i].name));
  }
}

}  // namespace luz::io::gltf
