// Files as users bring them, rendered by `luz render` as a user would (SCENES.md).
//
// emissiveTexture (Materials, "Textured emission"): Le = emissiveFactor x the sRGB-decoded texel x
// emissiveStrength. The local models, Whitted and the path tracer read the texel
// where they hit; radiosity shoots each element with the texture's mean over it, and an area
// light emits its triangle's mean. Closed forms: a uniformly textured emitter equals the
// untextured one of the same radiance in every model; a half-black texture halves the power.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/exposure.h"
#include "core/image_compare.h"
#include "gltf_fixture.h"
#include "io/gltf_loader.h"
#include "io/image_io.h"
#include "radiosity/patch_mesh.h"

namespace luz::test {
namespace {

using nlohmann::json;

// sRGB 128 decoded: ((128/255 + 0.055) / 1.055)^2.4.
const float kGrey128 = std::pow((128.0f / 255.0f + 0.055f) / 1.055f, 2.4f);

// A 2 m square emitter facing down at height 1 over a 4 m grey floor, seen from the side by a
// camera at (0, 0.5, 3) looking down -Z. The emitter's material is `emitter`; when `texture` is
// not empty, it is a PNG its emissiveTexture uses (uv (0, 0) to (1, 1) over the square, u along x).
std::filesystem::path emitter_scene(const ScratchDir& dir, json emitter,
                                    const std::vector<unsigned char>& texture = {}) {
  GltfBuilder b;
  if (!texture.empty())
    emitter["emissiveTexture"] = {{"index", b.texture_from_file("emission.png", texture)}};
  Primitive light;
  light.positions = {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}};
  light.normals = {{0, -1, 0}, {0, -1, 0}, {0, -1, 0}, {0, -1, 0}};
  light.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  light.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from below
  light.material = b.material(emitter);
  Primitive floor;
  floor.positions = {{-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}};
  floor.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  floor.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from above
  floor.material = b.material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1}},
                                                          {"metallicFactor", 0.0}}}});
  b.node({{"mesh", b.mesh({light, floor})}});
  const int camera = b.camera({{"type", "perspective"},
                               {"perspective", {{"yfov", 1.2}, {"aspectRatio", 1.0}, {"znear", 0.01}}}});
  b.node({{"camera", camera}, {"translation", {0, 0.5, 3}}});
  return b.write_gltf(dir);
}

json emissive(double r, double g, double b) {
  return {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 0.0}}},
          {"emissiveFactor", {r, g, b}}};
}

TEST(EmissionTexture, ReadSrgbDecodedTimesFactorAndStrength) {
  ScratchDir dir;
  json m = emissive(1.0, 0.5, 0.25);
  m["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2.0}}}};
  const io::LoadedScene loaded = io::load_gltf(emitter_scene(dir, m, png_rgb8(1, 1, {128, 128, 128})));
  const Scene& scene = loaded.scene;
  const Material& material = scene.materials.at(0);
  ASSERT_GE(material.emission_texture, 0);
  EXPECT_NEAR(scene.textures.at(size_t(material.emission_texture)).texel(0, 0).r, kGrey128, 1e-5f);
  // Le = (2, 1, 0.5) x the texel, read where a ray hits and as the area lights' radiance.
  const Rgb Le = scene.emission_at(0, 1, glm::vec2(0.2f, 0.3f));
  EXPECT_NEAR(Le.r, 2.0f * kGrey128, 1e-5f);
  EXPECT_NEAR(Le.b, 0.5f * kGrey128, 1e-5f);
  ASSERT_EQ(scene.area_lights.size(), 2u);
  EXPECT_NEAR(scene.area_lights[0].radiance.g, kGrey128, 1e-5f);
}

// Radiosity's emitted power, sum of E_i A_i over the elements of the emitter.
double emitted_power(const Scene& scene) {
  const PatchMesh mesh = PatchMesh::build(scene, 0.25f, 2);
  double power = 0.0;
  for (const Patch& p : mesh.patches) power += double(p.emission.r) * double(p.area);
  return power;
}

TEST(EmissionTexture, AHalfBlackTextureHalvesTheEmittedPowerInRadiosity) {
  // Two texels, white and black: the bilinear texture's mean over the square is 1/2, so the
  // elements shoot half the untextured power in all, the white side's more than the black's.
  ScratchDir plain_dir, half_dir;
  const Scene plain = io::load_gltf(emitter_scene(plain_dir, emissive(1, 1, 1))).scene;
  const Scene half = io::load_gltf(emitter_scene(half_dir, emissive(1, 1, 1), png_rgb8(2, 1, {255, 255, 255, 0, 0, 0}))).scene;
  const double full = emitted_power(plain);
  EXPECT_NEAR(full, std::numbers::pi * 4.0, 1e-3);  // E = pi Le over 4 m^2
  EXPECT_NEAR(emitted_power(half) / full, 0.5, 0.005);
  // The area lights the other models light with: each triangle emits its mean, half in all.
  double area_power = 0.0;
  for (const AreaLight& a : half.area_lights) area_power += double(a.radiance.r) * double(a.area);
  EXPECT_NEAR(area_power / 4.0, 0.5, 0.005);
}

// Renders `scene` with `model` to an EXR in `dir` and reads it back.
Image render(const std::filesystem::path& scene, const std::string& model, const ScratchDir& dir) {
  const std::filesystem::path out = dir / (model + ".exr");
  const CommandResult r = run_luz({"render", scene.string(), "--model", model, "--size", "48x48",
                                   "--out", out.string()});
  EXPECT_EQ(r.exit_code, 0) << model << ": " << r.output;
  return io::read_image(out);
}

TEST(EmissionTexture, AUniformlyTexturedEmitterEqualsTheUntexturedOneInEveryModel) {
  // emissiveFactor 1 with every texel sRGB 128 against emissiveFactor kGrey128 and no texture:
  // the same Le everywhere, so the same picture in each model (the floor lit by the emitter,
  // and the emitter itself seen from below).
  ScratchDir dir;
  const std::filesystem::path textured =
      emitter_scene(dir, emissive(1, 1, 1), png_rgb8(2, 2, std::vector<unsigned char>(12, 128)));
  ScratchDir plain_dir;
  const std::filesystem::path plain = emitter_scene(plain_dir, emissive(kGrey128, kGrey128, kGrey128));
  for (const std::string model : {"phong", "flat", "whitted", "path", "radiosity", "hybrid"}) {
    SCOPED_TRACE(model);
    const Image a = render(textured, model, dir), b = render(plain, model, plain_dir);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    double brightest = 0.0, difference = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
      brightest = std::max(brightest, double(b.pixels[i].r));
      difference = std::max(difference, double(std::abs(a.pixels[i].r - b.pixels[i].r)));
    }
    EXPECT_NEAR(brightest, kGrey128, 0.01) << "the emitter is in view";
    EXPECT_LE(difference, 1e-3 * brightest);
  }
}

TEST(EmissionTexture, WhittedReadsTheTexelWhereItHits) {
  // The half-black emitter seen from below: its white texel's centre (u = 1/4) shows Le, its
  // black one's (u = 3/4) nothing, where the mean (1/2) would show the same on both.
  ScratchDir dir;
  GltfBuilder b;
  json m = emissive(1, 1, 1);
  m["emissiveTexture"] = {{"index", b.texture_from_file("half.png", png_rgb8(2, 1, {255, 255, 255, 0, 0, 0}))}};
  Primitive light;
  light.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  light.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  light.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  light.indices = {0, 1, 2, 0, 2, 3};
  light.material = b.material(m);
  b.node({{"mesh", b.mesh({light})}});
  // At z = 2 with a vertical field of 2 atan(1/2) the square fills the 64 x 64 picture.
  const int camera = b.camera({{"type", "perspective"},
                               {"perspective", {{"yfov", 2.0 * std::atan(0.5)}, {"aspectRatio", 1.0}, {"znear", 0.01}}}});
  b.node({{"camera", camera}, {"translation", {0, 0, 2}}});
  const std::filesystem::path scene = b.write_gltf(dir);
  for (const std::string model : {"whitted", "phong"}) {
    SCOPED_TRACE(model);
    const std::filesystem::path out = dir / (model + ".exr");
    const CommandResult r = run_luz({"render", scene.string(), "--model", model, "--size", "64x64",
                                     "--out", out.string()});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const Image image = io::read_image(out);
    EXPECT_NEAR(image.at(16, 32).r, 1.0f, 0.05f);
    EXPECT_NEAR(image.at(47, 32).r, 0.0f, 0.05f);
  }
}

// ---- Flat shading: lighting once per triangle, the texture per fragment -------------------------

TEST(FlatShading, KeepsTheKdTexturePerFragment) {
  // A square of two triangles with a white | black kd texture, filling the picture. Two pixels of
  // one triangle (below its diagonal), at u = 1/4 and u = 3/4: the same lighting, so the texture
  // alone tells them apart, white against black (one texel per triangle would make them equal).
  ScratchDir dir;
  GltfBuilder b;
  json m = {{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}, {"metallicFactor", 0.0}}}};
  m["pbrMetallicRoughness"]["baseColorTexture"] = {
      {"index", b.texture_from_file("half.png", png_rgb8(2, 1, {255, 255, 255, 0, 0, 0}))}};
  Primitive square;
  square.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  square.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  square.indices = {0, 1, 2, 0, 2, 3};
  square.material = b.material(m);
  b.node({{"mesh", b.mesh({square})}});
  const int camera = b.camera({{"type", "perspective"},
                               {"perspective", {{"yfov", 2.0 * std::atan(0.5)}, {"aspectRatio", 1.0}, {"znear", 0.01}}}});
  b.node({{"camera", camera}, {"translation", {0, 0, 2}}});
  const std::filesystem::path scene = b.write_gltf(dir);
  const std::filesystem::path out = dir / "flat.exr";
  const CommandResult r = run_luz({"render", scene.string(), "--model", "flat", "--size", "64x64",
                                   "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image image = io::read_image(out);
  const float white = image.at(16, 56).g, black = image.at(47, 56).g;
  EXPECT_GT(white, 0.05f);
  EXPECT_LT(black, 0.05f * white);
}

// ---- Scenes without lights: a room exported from Blender ------------------------------------

TEST(DefaultLights, WhittedLightsTheBackWallOfAClosedRoom) {
  // Default lights outside the room would leave the back wall black behind the front wall (in
  // Whitted's model nothing but a light's direct ray lights it). Inside, the back wall, which
  // fills the middle of the picture, is lit all over.
  ScratchDir dir;
  const std::filesystem::path scene = closed_room().write_gltf(dir);
  const std::filesystem::path out = dir / "room.exr";
  const CommandResult r = run_luz({"render", scene.string(), "--model", "whitted", "--size", "32x32",
                                   "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("Punctual Lights"), std::string::npos) << r.output;
  const Image image = io::read_image(out);
  size_t black = 0;
  for (int y = 12; y < 20; ++y)
    for (int x = 12; x < 20; ++x) black += std::max({image.at(x, y).r, image.at(x, y).g, image.at(x, y).b}) <= 0.0f;
  EXPECT_EQ(black, 0u) << "of the 64 pixels in the middle, on the back wall";
  EXPECT_GT(image.at(16, 16).r, 0.05f);
}

// ---- Photometric lights: one exposure for the panes of a grid ----------------------------------

TEST(Exposure, TheTwoModelsOfAGridShareOneFittedExposure) {
  // A Blender export in its "Standard" mode: a lamp 683 times too bright. The grid's fit is one
  // exposure, printed once; each pane is what that model renders alone at that exposure (the
  // bottom rows, below the labels), so phong and whitted compare.
  ScratchDir dir;
  GltfBuilder b;
  Primitive floor;
  floor.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  floor.indices = {0, 1, 2, 0, 2, 3};
  floor.material = b.material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}, {"metallicFactor", 0.0}}}});
  b.node({{"mesh", b.mesh({floor})}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", b.light({{"type", "point"}, {"intensity", 54351}})}}}}},
          {"translation", {0.3, 0.2, 1.0}}});
  b.doc["asset"]["generator"] = "Khronos glTF Blender I/O v3.4.50";
  const std::string scene = b.write_gltf(dir).string();
  const std::string grid = (dir / "grid.png").string();
  const CommandResult r = run_luz({"render", scene, "--model", "phong,whitted", "--size", "160x120",
                                   "--exposure", "auto", "--out", grid});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const size_t at = r.output.find("exposure ");
  ASSERT_NE(at, std::string::npos) << r.output;
  const float ev = std::stof(r.output.substr(at + 9));
  EXPECT_LT(ev, -6.0f) << r.output;  // the lamp's 683 brought down
  const Image sheet = io::read_image(grid);
  ASSERT_EQ(sheet.width, 160);  // --size is the whole sheet's: two 80x120 panes
  for (const auto& [model, left] : {std::pair<std::string, int>{"phong", 0}, {"whitted", 80}}) {
    SCOPED_TRACE(model);
    const std::string alone = (dir / (model + ".png")).string();
    const CommandResult single = run_luz({"render", scene, "--model", model, "--size", "80x120",
                                          "--exposure", fmt::format("{:g}", ev), "--out", alone});
    ASSERT_EQ(single.exit_code, 0) << single.output;
    const Image pane = io::read_image(alone);
    double difference = 0.0;
    for (int y = 90; y < 120; ++y)
      for (int x = 0; x < 80; ++x)
        difference = std::max(difference, double(std::abs(pane.at(x, y).g - sheet.at(left + x, y).g)));
    EXPECT_LE(difference, 1e-6);
  }
}

// The EV a `luz render` run printed ("exposure +1.9 EV").
float printed_exposure(const std::string& output) {
  const size_t at = output.find("exposure ");
  return at == std::string::npos ? NAN : std::stof(output.substr(at + 9));
}

TEST(Exposure, SeparateRunsOfTheModelsShareTheScenesFittedExposure) {
  // Alone, each model's picture calls for its own exposure (the local model lacks the light the
  // walls pass on, the path tracer has it). --exposure auto fits one picture of the scene, the
  // same for every model, so separate runs come out at one exposure and compare, as a grid's
  // panes do.
  ScratchDir dir;
  const std::string scene = (scene_dir() / "cornell_box.gltf").string();
  std::vector<float> own, shared;
  for (const char* model : {"phong", "whitted", "path"}) {
    SCOPED_TRACE(model);
    const std::string exr = (dir / (std::string(model) + ".exr")).string();
    const CommandResult alone = run_luz({"render", scene, "--model", model, "--size", "40x30", "--out", exr});
    ASSERT_EQ(alone.exit_code, 0) << alone.output;
    const std::optional<float> fitted = fitted_exposure(picture_key(io::read_image(exr)));
    ASSERT_TRUE(fitted);
    own.push_back(*fitted);
    const CommandResult run = run_luz({"render", scene, "--model", model, "--size", "40x30", "--exposure", "auto",
                                       "--out", (dir / (std::string(model) + ".png")).string()});
    ASSERT_EQ(run.exit_code, 0) << run.output;
    shared.push_back(printed_exposure(run.output));
  }
  EXPECT_GE(*std::max_element(own.begin(), own.end()) - *std::min_element(own.begin(), own.end()), 0.3f)
      << "the models' own fits differ";
  for (const float ev : shared) EXPECT_EQ(ev, shared.front());
  const CommandResult grid = run_luz({"render", scene, "--model", "phong,path", "--size", "80x30", "--exposure",
                                      "auto", "--out", (dir / "grid.png").string()});
  ASSERT_EQ(grid.exit_code, 0) << grid.output;
  EXPECT_EQ(printed_exposure(grid.output), shared.front()) << grid.output;
}

}  // namespace
}  // namespace luz::test
