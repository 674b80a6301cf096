// The glTF loader against SCENES.md: one test per mapping rule, values worked by hand, and one
// test per kind of bad input (its ErrorKind, and a message that names the file).
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "core/error.h"
#include "core/i18n.h"
#include "gltf_fixture.h"
#include "io/default_lights.h"
#include "io/gltf_loader.h"

namespace luz::test {
namespace {

using nlohmann::json;

constexpr float kTol = 1e-5f;
const float kHalfSqrt2 = std::sqrt(0.5f);

#define EXPECT_VEC3(actual, ex, ey, ez)         \
  do {                                          \
    const glm::vec3 v_ = (actual);              \
    EXPECT_NEAR(v_.x, (ex), kTol) << #actual;   \
    EXPECT_NEAR(v_.y, (ey), kTol) << #actual;   \
    EXPECT_NEAR(v_.z, (ez), kTol) << #actual;   \
  } while (0)

// A material that is plain diffuse: glTF's default metallicFactor is 1, which makes kd 0.
json diffuse(double r, double g, double b) {
  return {{"pbrMetallicRoughness", {{"baseColorFactor", {r, g, b, 1.0}}, {"metallicFactor", 0.0}}}};
}

bool any_warning_contains(const io::LoadedScene& loaded, const std::string& text) {
  for (const std::string& w : loaded.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

// The warnings but the default lights' and the framing camera's notices (these scenes have no
// light and no camera on purpose).
std::vector<std::string> other_warnings(const io::LoadedScene& loaded) {
  std::vector<std::string> out;
  for (const std::string& w : loaded.warnings)
    if (w.find(io::kDefaultLightsNotice) == std::string::npos && w.find(io::kNoCameraNotice) == std::string::npos)
      out.push_back(w);
  return out;
}

// Loads `path` expecting a luz::Error of `kind` whose message names the file; returns the message.
std::string expect_error(const std::filesystem::path& path, ErrorKind kind) {
  try {
    io::load_gltf(path);
  } catch (const Error& e) {
    EXPECT_EQ(to_string(e.kind), std::string(to_string(kind))) << e.what();
    const std::string message = e.what();
    EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    return message;
  }
  ADD_FAILURE() << "no error loading " << path;
  return "";
}

// Replaces the first `from` in a file's text (for what nlohmann::json cannot write, like 1e999).
void replace_in_file(const std::filesystem::path& path, const std::string& from, const std::string& to) {
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  write_file(path, text);
}

// ================================================================================================
// Nodes and geometry
// ================================================================================================

TEST(Node, TrsComposesDownTheHierarchy) {
  // parent: translate (1,0,0) * scale 2; child: translate (0,1,0) * rotate 90 deg about +Z.
  // Child local: (1,0,0) -> (0,1,0) + (0,1,0) = (0,2,0); parent: x2 -> (0,4,0), + (1,0,0).
  GltfBuilder b;
  const int child = b.node({{"mesh", b.mesh({triangle()})},
                            {"translation", {0, 1, 0}},
                            {"rotation", {0, 0, kHalfSqrt2, kHalfSqrt2}}},
                           false);
  b.node({{"translation", {1, 0, 0}}, {"scale", {2, 2, 2}}, {"children", {child}}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  // No normals in the file: flat, so vertices follow the triangle's corners in order.
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_VEC3(mesh.positions[mesh.indices[0]], 1, 2, 0);
  EXPECT_VEC3(mesh.positions[mesh.indices[1]], 1, 4, 0);
  EXPECT_VEC3(mesh.positions[mesh.indices[2]], -1, 2, 0);
  EXPECT_VEC3(mesh.normals[0], 0, 0, 1);
}

TEST(Node, MatrixIsColumnMajor) {
  GltfBuilder b;
  b.node({{"mesh", b.mesh({triangle()})},
          {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1}}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  EXPECT_VEC3(scene.meshes[0].positions[scene.meshes[0].indices[0]], 5, 6, 7);
  EXPECT_VEC3(scene.meshes[0].positions[scene.meshes[0].indices[1]], 6, 6, 7);
}

TEST(Node, DefaultSceneIsTheOneNamed) {
  GltfBuilder b;
  const int mesh = b.mesh({triangle()});
  b.node({{"mesh", mesh}});                                       // in scene 0
  const int other = b.node({{"mesh", mesh}, {"translation", {0, 0, 9}}}, false);
  b.doc["scenes"].push_back({{"nodes", {other}}});
  b.doc["scene"] = 1;
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_NEAR(scene.meshes[0].positions[0].z, 9.0f, kTol);
}

TEST(Normals, FlatWhenAbsent) {
  // Quad (0,0,0) (1,0,0) (1,1,1) (0,1,1): e1 x e2 = (1,0,0) x (1,1,1) = (0,-1,1), over sqrt 2.
  Primitive quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 1}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  GltfBuilder b;
  b.node({{"mesh", b.mesh({quad})}});
  ScratchDir dir;
  const Mesh mesh = io::load_gltf(b.write_gltf(dir)).scene.meshes.at(0);
  // Un-indexed: every face has its own three vertices.
  ASSERT_EQ(mesh.positions.size(), 6u);
  ASSERT_EQ(mesh.normals.size(), 6u);
  ASSERT_EQ(mesh.triangle_count(), 2u);
  for (const glm::vec3& n : mesh.normals) EXPECT_VEC3(n, 0, -kHalfSqrt2, kHalfSqrt2);
  EXPECT_VEC3(mesh.positions[mesh.indices[5]], 0, 1, 1);
}

TEST(Normals, FromFileRenormalisedAndShared) {
  Primitive quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.normals = {{0, 0, 2}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  GltfBuilder b;
  b.node({{"mesh", b.mesh({quad})}});
  ScratchDir dir;
  const Mesh mesh = io::load_gltf(b.write_gltf(dir)).scene.meshes.at(0);
  EXPECT_EQ(mesh.positions.size(), 4u);  // shared, as in the file
  EXPECT_VEC3(mesh.normals[0], 0, 0, 1);
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

// A zero normal cannot light its vertex: the primitive takes its faces' normals (its vertices
// unshared, as without NORMAL) and says so once; the file's other primitives keep theirs.
TEST(Normals, AZeroNormalGivesThePrimitiveItsFacesNormals) {
  Primitive quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.normals = {{1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  Primitive fine = triangle();
  fine.normals = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  GltfBuilder b;
  b.node({{"mesh", b.mesh({quad, fine}, "bad")}});
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  const std::vector<std::string> warnings = other_warnings(loaded);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("mesh 0 \"bad\" primitive 0: NORMAL 1 has no direction"), std::string::npos)
      << warnings[0];
  ASSERT_EQ(loaded.scene.meshes.size(), 2u);
  const Mesh& faces = loaded.scene.meshes[0];
  EXPECT_EQ(faces.positions.size(), 6u);  // three vertices a triangle
  for (const glm::vec3& n : faces.normals) EXPECT_VEC3(n, 0, 0, 1);
  EXPECT_VEC3(loaded.scene.meshes[1].normals[0], 1, 0, 0);
}

TEST(Normals, ByInverseTransposeOfTheNodeMatrix) {
  // Scale (2,1,1): normals go by diag(1/2, 1, 1). (1,1,0)/sqrt2 -> (0.5,1,0)/|.| = (1,2,0)/sqrt5.
  Primitive p = triangle();
  p.normals = {{kHalfSqrt2, kHalfSqrt2, 0}, {kHalfSqrt2, kHalfSqrt2, 0}, {kHalfSqrt2, kHalfSqrt2, 0}};
  GltfBuilder b;
  b.node({{"mesh", b.mesh({p})}, {"scale", {2, 1, 1}}});
  ScratchDir dir;
  const Mesh mesh = io::load_gltf(b.write_gltf(dir)).scene.meshes.at(0);
  const float s5 = std::sqrt(5.0f);
  EXPECT_VEC3(mesh.normals[0], 1 / s5, 2 / s5, 0);
  EXPECT_VEC3(mesh.positions[1], 2, 0, 0);
}

TEST(Winding, FlippedWhenTheNodeMirrors) {
  // Scale (-1,1,1) turns the counter-clockwise triangle clockwise; the loader swaps two corners so
  // that the front face (e1 x e2) still faces +Z, where the file's normal points.
  Primitive p = triangle();
  p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  GltfBuilder b;
  b.node({{"mesh", b.mesh({p})}, {"scale", {-1, 1, 1}}});
  ScratchDir dir;
  const Mesh mesh = io::load_gltf(b.write_gltf(dir)).scene.meshes.at(0);
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 2, 1}));
  const glm::vec3 a = mesh.positions[mesh.indices[0]], b1 = mesh.positions[mesh.indices[1]],
                  c = mesh.positions[mesh.indices[2]];
  EXPECT_VEC3(glm::normalize(glm::cross(b1 - a, c - a)), 0, 0, 1);
  EXPECT_VEC3(mesh.normals[0], 0, 0, 1);  // inverse transpose of diag(-1,1,1) keeps (0,0,1)
}

TEST(Primitive, PointsAndLinesSkippedWithOneWarningNamingTheMeshAndTheModeInWords) {
  Primitive lines = triangle();
  lines.mode = 1;
  Primitive points = triangle();
  points.mode = 0;
  Primitive more_lines = triangle();
  more_lines.mode = 1;
  GltfBuilder b;
  b.node({{"mesh", b.mesh({lines, triangle(), points, more_lines}, "wires")}});
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  EXPECT_EQ(loaded.scene.triangle_count(), 1u);
  const std::vector<std::string> warnings = other_warnings(loaded);
  ASSERT_EQ(warnings.size(), 1u) << ::testing::PrintToString(loaded.warnings);
  EXPECT_EQ(warnings[0], (dir / "scene.gltf").string() +
                             ": mesh 0 \"wires\": skipped its lines (mode 1), points (mode 0); "
                             "only triangles are drawn");
}

// The corners of every triangle of the scene's meshes, and whether each one faces +Z
// (counter-clockwise seen from +Z, as glTF's front faces are).
size_t triangles_facing_plus_z(const Scene& scene) {
  size_t facing = 0;
  for (const Mesh& mesh : scene.meshes)
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                      c = mesh.positions[mesh.indices[t + 2]];
      facing += glm::cross(b - a, c - a).z > 0.0f;
    }
  return facing;
}

float total_area(const Scene& scene) {
  float area = 0.0f;
  for (const Mesh& mesh : scene.meshes)
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                      c = mesh.positions[mesh.indices[t + 2]];
      area += 0.5f * glm::length(glm::cross(b - a, c - a));
    }
  return area;
}

TEST(Primitive, TriangleStripBecomesTrianglesWoundAlike) {
  // A strip zig-zagging along x, as Mesh_PrimitiveMode_04 does: top, bottom, top, bottom, ...
  // n vertices make n - 2 triangles, each of area 1/2, every one counter-clockwise from +Z
  // (glTF: triangle i is (v_i, v_{i+1+i%2}, v_{i+2-i%2})).
  Primitive strip;
  strip.positions = {{0, 1, 0}, {0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {2, 1, 0}, {2, 0, 0}};
  strip.mode = 5;
  GltfBuilder b;
  b.node({{"mesh", b.mesh({strip}, "strip")}});
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  EXPECT_TRUE(other_warnings(loaded).empty()) << ::testing::PrintToString(loaded.warnings);
  EXPECT_EQ(loaded.scene.triangle_count(), 4u);
  EXPECT_EQ(triangles_facing_plus_z(loaded.scene), 4u);
  EXPECT_NEAR(total_area(loaded.scene), 2.0f, kTol);
}

TEST(Primitive, IndexedStripsJoinedByRepeatedVerticesLoseOnlyTheJoins) {
  // Two quads in one strip, joined the usual way (repeat the last vertex of one and the first of
  // the next): 0 1 2 3 3 4 4 5 6 7. The four triangles that repeat a vertex are joins, not
  // zero-area triangles of the model, and are not reported; the four real ones face +Z.
  Primitive strip;
  strip.positions = {{0, 1, 0}, {0, 0, 0}, {1, 1, 0}, {1, 0, 0},
                     {5, 1, 0}, {5, 0, 0}, {6, 1, 0}, {6, 0, 0}};
  strip.indices = {0, 1, 2, 3, 3, 4, 4, 5, 6, 7};
  strip.mode = 5;
  GltfBuilder b;
  b.node({{"mesh", b.mesh({strip}, "strips")}});
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  EXPECT_TRUE(other_warnings(loaded).empty()) << ::testing::PrintToString(loaded.warnings);
  EXPECT_EQ(loaded.scene.triangle_count(), 4u);
  EXPECT_EQ(triangles_facing_plus_z(loaded.scene), 4u);
  EXPECT_NEAR(total_area(loaded.scene), 2.0f, kTol);
}

TEST(Primitive, TriangleFanBecomesTrianglesAroundItsFirstVertex) {
  // A fan around the origin over a unit-radius half hexagon, counter-clockwise from +Z: n
  // vertices make n - 2 triangles (glTF: triangle i is (v_{i+1}, v_{i+2}, v_0)), with normals
  // from their faces.
  Primitive fan;
  fan.positions = {{0, 0, 0}};
  for (int k = 0; k <= 3; ++k) {
    const float angle = float(k) * std::numbers::pi_v<float> / 3.0f;
    fan.positions.push_back({std::cos(angle), std::sin(angle), 0});
  }
  fan.indices = {0, 1, 2, 3, 4};
  fan.mode = 6;
  GltfBuilder b;
  b.node({{"mesh", b.mesh({fan}, "fan")}});
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  EXPECT_TRUE(other_warnings(loaded).empty()) << ::testing::PrintToString(loaded.warnings);
  EXPECT_EQ(loaded.scene.triangle_count(), 3u);
  EXPECT_EQ(triangles_facing_plus_z(loaded.scene), 3u);
  EXPECT_NEAR(total_area(loaded.scene), 3.0f * std::sqrt(3.0f) / 4.0f, kTol);
  EXPECT_VEC3(loaded.scene.meshes[0].normals[0], 0, 0, 1);
}

TEST(Primitive, KhronosPrimitiveModeSamplesAreOneSquareFacingTheViewer) {
  // glTF-Asset-Generator's Mesh_PrimitiveMode: the same unit square facing +Z as a triangle
  // list (06, 13), strip (04, 11) and fan (05, 12), without and with indices.
  const std::filesystem::path folder =
      "/usr/share/assimp/models/glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode";
  if (!std::filesystem::is_directory(folder)) GTEST_SKIP() << folder << " is not installed";
  for (const char* n : {"04", "05", "06", "11", "12", "13"}) {
    SCOPED_TRACE(n);
    const io::LoadedScene loaded =
        io::load_gltf(folder / (std::string("Mesh_PrimitiveMode_") + n + ".gltf"));
    EXPECT_EQ(loaded.scene.triangle_count(), 2u);
    EXPECT_EQ(triangles_facing_plus_z(loaded.scene), 2u);
    EXPECT_NEAR(total_area(loaded.scene), 1.0f, kTol);
  }
}

TEST(Primitive, NonIndexedMakesATriangleOfEveryThreeVertices) {
  Primitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  GltfBuilder b;
  b.node({{"mesh", b.mesh({p})}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  EXPECT_EQ(scene.triangle_count(), 2u);
  EXPECT_VEC3(scene.meshes[0].positions[scene.meshes[0].indices[3]], 0, 0, 1);
}

TEST(Accessor, ByteStrideAndOffsetHonoured) {
  // Interleaved floats: [pad, x, y, z] per vertex; stride 16, accessor byteOffset 4.
  const std::vector<float> data = {-7, 0, 0, 0, -7, 1, 0, 0, -7, 0, 1, 0};
  GltfBuilder b;
  const int view = b.add_view(data.data(), data.size() * 4, 16);
  const int positions = b.add_accessor(view, kFloat, 3, "VEC3", 4);
  json primitive;
  primitive["attributes"]["POSITION"] = positions;
  b.doc["meshes"].push_back({{"primitives", json::array({primitive})}});
  b.node({{"mesh", 0}});
  ScratchDir dir;
  const Mesh mesh = io::load_gltf(b.write_gltf(dir)).scene.meshes.at(0);
  EXPECT_VEC3(mesh.positions[0], 0, 0, 0);
  EXPECT_VEC3(mesh.positions[1], 1, 0, 0);
  EXPECT_VEC3(mesh.positions[2], 0, 1, 0);
}

TEST(Accessor, ByteAndShortIndices) {
  Primitive bytes = triangle(), shorts = triangle();
  bytes.indices = {2, 1, 0, 0, 1, 2};
  bytes.index_type = kUnsignedByte;
  shorts.index_type = kUnsignedShort;
  Primitive with_normals = bytes;  // indices are kept as given when the file has normals
  with_normals.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  GltfBuilder b;
  b.node({{"mesh", b.mesh({bytes, shorts, with_normals})}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  ASSERT_EQ(scene.meshes.size(), 3u);
  EXPECT_EQ(scene.meshes[0].triangle_count(), 2u);
  EXPECT_EQ(scene.meshes[1].triangle_count(), 1u);
  EXPECT_EQ(scene.meshes[2].indices, (std::vector<uint32_t>{2, 1, 0, 0, 1, 2}));
}

// KHR_mesh_quantization (what gltfpack writes): POSITION as shorts scaled back by the node,
// NORMAL as normalized bytes, TEXCOORD_0 as shorts, signed and not normalized; each padded to 4
// bytes a vertex as the extension asks.
GltfBuilder quantized_triangle() {
  GltfBuilder b;
  const std::vector<int16_t> positions = {0, 0, 0, 0, 1000, 0, 0, 0, 0, 1000, -1000, 0};  // x, y, z, pad
  const std::vector<int8_t> normals = {0, 0, 127, 0, 0, 0, -128, 0, 90, 0, 90, 0};
  const std::vector<int16_t> uvs = {0, 0, 2, -3, -4, 5};
  json primitive;
  primitive["attributes"]["POSITION"] = b.add_accessor(b.add_view(positions.data(), 24, 8), kShort, 3, "VEC3");
  primitive["attributes"]["NORMAL"] = b.add_accessor(b.add_view(normals.data(), 12, 4), kByte, 3, "VEC3", 0, true);
  primitive["attributes"]["TEXCOORD_0"] = b.add_accessor(b.add_view(uvs.data(), 12), kShort, 3, "VEC2");
  b.doc["meshes"].push_back({{"primitives", json::array({primitive})}});
  b.node({{"mesh", 0}, {"scale", {0.001, 0.001, 0.001}}});
  b.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  b.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  return b;
}

TEST(Quantization, IntegerAttributesAreReadAndScaledByTheNode) {
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(quantized_triangle().write_gltf(dir));
  EXPECT_TRUE(other_warnings(loaded).empty());
  const Mesh& mesh = loaded.scene.meshes.at(0);
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_VEC3(mesh.positions[0], 0, 0, 0);
  EXPECT_VEC3(mesh.positions[1], 1, 0, 0);
  EXPECT_VEC3(mesh.positions[2], 0, 1, -1);
  // 127 -> 1 and -128 -> -1 (normalized signed bytes); (90, 0, 90) renormalized.
  EXPECT_VEC3(mesh.normals[0], 0, 0, 1);
  EXPECT_VEC3(mesh.normals[1], 0, 0, -1);
  EXPECT_VEC3(mesh.normals[2], std::sqrt(0.5f), 0, std::sqrt(0.5f));
  ASSERT_EQ(mesh.uvs.size(), 3u);
  EXPECT_EQ(mesh.uvs[1], glm::vec2(2, -3));
  EXPECT_EQ(mesh.uvs[2], glm::vec2(-4, 5));
}

TEST(Quantization, NormalizedSignedShortsAndBytesReachMinusOne) {
  GltfBuilder b;
  // POSITION as normalized shorts: -32768 and -32767 both -1, 32767 is 1.
  const std::vector<int16_t> positions = {-32768, 0, 0, 0, 32767, 0, 0, 0, -32767, 32767, 0, 0};
  json primitive;
  primitive["attributes"]["POSITION"] = b.add_accessor(b.add_view(positions.data(), 24, 8), kShort, 3, "VEC3", 0, true);
  b.doc["meshes"].push_back({{"primitives", json::array({primitive})}});
  b.node({{"mesh", 0}});
  b.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  ScratchDir dir;
  const Mesh mesh = io::load_gltf(b.write_gltf(dir)).scene.meshes.at(0);
  EXPECT_VEC3(mesh.positions[0], -1, 0, 0);
  EXPECT_VEC3(mesh.positions[1], 1, 0, 0);
  EXPECT_VEC3(mesh.positions[2], -1, 1, 0);
}

TEST(Quantization, IntegerPositionsWithoutTheExtensionAreRefusedNamingIt) {
  GltfBuilder b = quantized_triangle();
  b.doc.erase("extensionsUsed");
  b.doc.erase("extensionsRequired");
  ScratchDir dir;
  const std::string message = expect_error(b.write_gltf(dir), ErrorKind::bad_value);
  EXPECT_NE(message.find("POSITION"), std::string::npos) << message;
  EXPECT_NE(message.find("KHR_mesh_quantization"), std::string::npos) << message;
}

TEST(Texcoords, FloatAndNormalizedShorts) {
  Primitive p = triangle();
  p.uvs = {{0, 0}, {1, 0}, {0.25f, 0.5f}};
  GltfBuilder b;
  const int float_mesh = b.mesh({p});
  // The same uvs as normalized unsigned shorts: 65535 -> 1, 32768 -> 32768/65535.
  const std::vector<uint16_t> shorts = {0, 0, 65535, 0, 16384, 32768};
  const int view = b.add_view(shorts.data(), shorts.size() * 2);
  json primitive = b.doc["meshes"][float_mesh]["primitives"][0];
  primitive["attributes"]["TEXCOORD_0"] = b.add_accessor(view, kUnsignedShort, 3, "VEC2", 0, true);
  b.doc["meshes"].push_back({{"primitives", {primitive}}});
  b.node({{"mesh", float_mesh}});
  b.node({{"mesh", 1}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  ASSERT_EQ(scene.meshes.size(), 2u);
  ASSERT_EQ(scene.meshes[0].uvs.size(), 3u);
  EXPECT_NEAR(scene.meshes[0].uvs[2].x, 0.25f, kTol);
  EXPECT_NEAR(scene.meshes[0].uvs[2].y, 0.5f, kTol);
  EXPECT_NEAR(scene.meshes[1].uvs[1].x, 1.0f, kTol);
  EXPECT_NEAR(scene.meshes[1].uvs[2].y, 32768.0f / 65535.0f, 1e-6f);
}

TEST(Triangles, ZeroAreaDroppedWithOneWarningGivingTheCount) {
  Primitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
  p.indices = {0, 1, 2,   // fine
               0, 0, 2,   // repeated corner
               0, 1, 3};  // collinear
  GltfBuilder b;
  b.node({{"mesh", b.mesh({p}, "slivers")}});
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  EXPECT_EQ(loaded.scene.triangle_count(), 1u);
  const std::vector<std::string> warnings = other_warnings(loaded);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("\"slivers\""), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("dropped 2 "), std::string::npos) << warnings[0];
}

TEST(Triangles, AMeshDrawnTwiceWarnsOnce) {
  Primitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  p.indices = {0, 1, 2, 0, 0, 2};  // the second triangle has a repeated corner
  GltfBuilder b;
  const int mesh = b.mesh({p}, "slivers");
  b.node({{"mesh", mesh}});
  b.node({{"mesh", mesh}, {"translation", {3, 0, 0}}});
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  EXPECT_EQ(loaded.scene.triangle_count(), 2u);
  const std::vector<std::string> warnings = other_warnings(loaded);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("dropped 1 "), std::string::npos) << warnings[0];
}

// A CAD export drops slivers in hundreds of meshes: one warning with the total, the count of
// meshes and the three that dropped most, largest first; a mesh drawn twice counts once.
TEST(Triangles, ZeroAreaInManyMeshesIsOneWarning) {
  GltfBuilder b;
  for (int m = 0; m < 5; ++m) {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.indices = {0, 1, 2};
    for (int k = 0; k <= (m + 2) % 5; ++k) p.indices.insert(p.indices.end(), {0, 0, 2});  // 3 1 2 ... slivers
    const int mesh = b.mesh({p}, std::string(1, char('a' + m)));
    b.node({{"mesh", mesh}});
    if (m == 0) b.node({{"mesh", mesh}, {"translation", {3, 0, 0}}});
  }
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  EXPECT_EQ(loaded.scene.triangle_count(), 6u);
  const std::vector<std::string> warnings = other_warnings(loaded);
  ASSERT_EQ(warnings.size(), 1u);
  // Mesh m drops (m + 2) % 5 + 1 slivers: 3, 4, 5, 1, 2.
  EXPECT_NE(warnings[0].find("dropped 15 zero-area triangles in 5 meshes, most in mesh 2 \"c\" (5), "
                             "mesh 1 \"b\" (4), mesh 0 \"a\" (3)"),
            std::string::npos) << warnings[0];
}

TEST(Triangles, ZeroAreaInTwoMeshesNamesBoth) {
  GltfBuilder b;
  for (int m = 0; m < 2; ++m) {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.indices = {0, 1, 2, 0, 0, 2};
    b.node({{"mesh", b.mesh({p}, std::string(1, char('a' + m)))}});
  }
  ScratchDir dir;
  const std::vector<std::string> warnings = other_warnings(io::load_gltf(b.write_gltf(dir)));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("dropped 2 zero-area triangles in 2 meshes: mesh 0 \"a\" (1), mesh 1 \"b\" (1)"),
            std::string::npos) << warnings[0];
}

TEST(Glb, LoadsLikeGltf) {
  GltfBuilder b = one_triangle(diffuse(0.5, 0.25, 0.125));
  b.doc["nodes"][0]["translation"] = {1, 2, 3};
  ScratchDir dir;
  const Scene text = io::load_gltf(b.write_gltf(dir)).scene;
  const Scene binary = io::load_gltf(b.write_glb(dir)).scene;
  ASSERT_EQ(binary.meshes.size(), 1u);
  EXPECT_EQ(binary.meshes[0].positions, text.meshes[0].positions);
  EXPECT_VEC3(binary.meshes[0].positions[0], 1, 2, 3);
  EXPECT_VEC3(binary.materials[0].kd, 0.5f, 0.25f, 0.125f);
  EXPECT_EQ(binary.path, (dir / "scene.glb").string());
}

TEST(Gltf, EmbeddedDataUriBuffer) {
  GltfBuilder b = one_triangle();
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir, "embedded.gltf", true)).scene;
  EXPECT_FALSE(std::filesystem::exists(dir / "embedded.bin"));
  EXPECT_EQ(scene.triangle_count(), 1u);
  EXPECT_VEC3(scene.meshes[0].positions[scene.meshes[0].indices[2]], 0, 1, 0);
}

// ================================================================================================
// Materials
// ================================================================================================

Material load_material(const json& material) {
  ScratchDir dir;
  return io::load_gltf(one_triangle(material).write_gltf(dir)).scene.materials.at(0);
}

TEST(Material, DiffuseFromBaseColorTimesOneMinusMetallic) {
  // kd = (0.8, 0.4, 0.2) x (1 - 0.25); ka defaults to kd; the rest to SCENES.md's defaults.
  const Material m = load_material({{"name", "clay"},
                                    {"pbrMetallicRoughness",
                                     {{"baseColorFactor", {0.8, 0.4, 0.2, 1}}, {"metallicFactor", 0.25}}}});
  EXPECT_EQ(m.name, "clay");
  EXPECT_VEC3(m.kd, 0.6f, 0.3f, 0.15f);
  EXPECT_VEC3(m.ka, 0.6f, 0.3f, 0.15f);
  EXPECT_VEC3(m.ks, 0.2f, 0.1f, 0.05f);  // the metallic quarter of the base colour (Metals)
  EXPECT_VEC3(m.kr, 0, 0, 0);
  EXPECT_VEC3(m.kt, 0, 0, 0);
  EXPECT_VEC3(m.emission, 0, 0, 0);
  EXPECT_FLOAT_EQ(m.ior, 1.5f);
  EXPECT_EQ(m.kd_texture, -1);
}

TEST(Material, ShininessFromRoughness) {
  // n = 2 / r^4 - 2: r = 0.5 -> 2/0.0625 - 2 = 30; r = 1 -> 0, clamped up to 1.
  json m = diffuse(1, 1, 1);
  m["pbrMetallicRoughness"]["roughnessFactor"] = 0.5;
  EXPECT_NEAR(load_material(m).shininess, 30.0f, 1e-3f);
  m["pbrMetallicRoughness"]["roughnessFactor"] = 1.0;
  EXPECT_FLOAT_EQ(load_material(m).shininess, 1.0f);
}

TEST(Material, KrFromMetallicSmoothBaseColor) {
  // metallic 1, roughness 0.05: a mirror tinted by the base colour, and no diffuse part.
  json m = {{"pbrMetallicRoughness",
             {{"baseColorFactor", {0.9, 0.8, 0.7, 1}}, {"metallicFactor", 1.0}, {"roughnessFactor", 0.05}}}};
  const Material mirror = load_material(m);
  EXPECT_VEC3(mirror.kr, 0.9f, 0.8f, 0.7f);
  EXPECT_VEC3(mirror.kd, 0, 0, 0);
  m["pbrMetallicRoughness"]["roughnessFactor"] = 0.1;  // too rough for a mirror
  EXPECT_VEC3(load_material(m).kr, 0, 0, 0);
  m["pbrMetallicRoughness"]["roughnessFactor"] = 0.0;
  m["pbrMetallicRoughness"]["metallicFactor"] = 0.4;  // not metal enough
  EXPECT_VEC3(load_material(m).kr, 0, 0, 0);
}

TEST(Material, ExtrasScalarIsGreyAndRgbIsRgb) {
  json m = diffuse(0.2, 0.2, 0.2);
  m["extras"] = {{"ka", 0.1}, {"ks", {0.2, 0.3, 0.4}}, {"shininess", 50}, {"kr", 0.25},
                 {"kt", {0.1, 0.2, 0.3}}, {"ior", 1.33}};
  const Material mat = load_material(m);
  EXPECT_VEC3(mat.ka, 0.1f, 0.1f, 0.1f);
  EXPECT_VEC3(mat.ks, 0.2f, 0.3f, 0.4f);
  EXPECT_FLOAT_EQ(mat.shininess, 50.0f);
  EXPECT_VEC3(mat.kr, 0.25f, 0.25f, 0.25f);
  EXPECT_VEC3(mat.kt, 0.1f, 0.2f, 0.3f);
  EXPECT_FLOAT_EQ(mat.ior, 1.33f);
  EXPECT_VEC3(mat.kd, 0.2f, 0.2f, 0.2f);
}

TEST(Material, TransmissionAndIorExtensionsUnlessExtrasSayOtherwise) {
  // base (0.5, 0.4, 0.2), metallic 0.5, transmission 0.75: the dielectric half (0.25, 0.2, 0.1)
  // splits into kd = a quarter of it and kt = three quarters, tinted by the base colour.
  json m = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.4, 0.2, 1}}, {"metallicFactor", 0.5}}}};
  m["extensions"] = {{"KHR_materials_transmission", {{"transmissionFactor", 0.75}}},
                     {"KHR_materials_ior", {{"ior", 2.4}}}};
  const Material glass = load_material(m);
  EXPECT_VEC3(glass.kd, 0.0625f, 0.05f, 0.025f);
  EXPECT_VEC3(glass.kt, 0.1875f, 0.15f, 0.075f);
  EXPECT_FLOAT_EQ(glass.ior, 2.4f);
  m["extras"] = {{"kt", 0.2}, {"ior", 1.1}};
  const Material overridden = load_material(m);
  EXPECT_VEC3(overridden.kt, 0.2f, 0.2f, 0.2f);
  EXPECT_VEC3(overridden.kd, 0.0625f, 0.05f, 0.025f);  // still weighed by (1 - transmission)
  EXPECT_FLOAT_EQ(overridden.ior, 1.1f);
}

TEST(Material, BlendersDefaultGlassIsClearNotAGlowingWhiteBall) {
  // What Blender 3.4 writes for its Glass BSDF: a white base, metallic 0, roughness 0,
  // transmission 1. All of it is transmitted: kd = 0 (and ka with it), kt = 1, and kd + kr + kt
  // stays within 1, so the scene loads without the energy warning.
  json m = {{"name", "Glass"},
            {"pbrMetallicRoughness",
             {{"baseColorFactor", {1, 1, 1, 1}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.0}}},
            {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                            {"KHR_materials_ior", {{"ior", 1.45}}}}}};
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(one_triangle(m).write_gltf(dir));
  const Material& glass = loaded.scene.materials.at(0);
  EXPECT_VEC3(glass.kd, 0, 0, 0);
  EXPECT_VEC3(glass.ka, 0, 0, 0);
  EXPECT_VEC3(glass.kt, 1, 1, 1);
  EXPECT_VEC3(glass.kr, 0, 0, 0);
  EXPECT_FLOAT_EQ(glass.ior, 1.45f);
  EXPECT_TRUE(other_warnings(loaded).empty()) << ::testing::PrintToString(loaded.warnings);
}

TEST(Error, TransmissionOutsideZeroOneIsBadValue) {
  json m = diffuse(1, 1, 1);
  m["extensions"] = {{"KHR_materials_transmission", {{"transmissionFactor", 1.5}}}};
  ScratchDir dir;
  const std::string message = expect_error(one_triangle(m).write_gltf(dir), ErrorKind::bad_value);
  EXPECT_NE(message.find("transmissionFactor"), std::string::npos) << message;
}

TEST(Material, EmissionTimesStrengthMakesAreaLights) {
  json m = diffuse(0, 0, 0);
  m["emissiveFactor"] = {1.0, 0.5, 0.25};
  m["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}};
  ScratchDir dir;
  const Scene scene = io::load_gltf(one_triangle(m).write_gltf(dir)).scene;
  EXPECT_VEC3(scene.materials[0].emission, 4, 2, 1);
  ASSERT_EQ(scene.area_lights.size(), 1u);
  EXPECT_NEAR(scene.area_lights[0].area, 0.5f, kTol);
  EXPECT_VEC3(scene.area_lights[0].normal, 0, 0, 1);
  EXPECT_VEC3(scene.area_lights[0].radiance, 4, 2, 1);
}

TEST(Material, DefaultAppendedOnlyWhenAPrimitiveHasNone) {
  GltfBuilder b;
  const int red = b.material(diffuse(1, 0, 0));
  b.node({{"mesh", b.mesh({triangle(red), triangle()})}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  ASSERT_EQ(scene.materials.size(), 2u);  // the file's material keeps index 0
  EXPECT_VEC3(scene.materials[0].kd, 1, 0, 0);
  EXPECT_EQ(scene.materials[1].name, "default");
  EXPECT_VEC3(scene.materials[1].kd, 0.8f, 0.8f, 0.8f);
  EXPECT_EQ(scene.meshes[0].material, 0);
  EXPECT_EQ(scene.meshes[1].material, 1);

  ScratchDir dir2;
  EXPECT_EQ(io::load_gltf(one_triangle(diffuse(1, 0, 0)).write_gltf(dir2)).scene.materials.size(), 1u);
}

TEST(Material, EnergyAboveOneLoadsWithAWarningNamingIt) {
  json m = diffuse(0.8, 0.8, 0.8);
  m["name"] = "hot";
  m["extras"] = {{"kr", 0.5}};  // kd + kr = 1.3
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(one_triangle(m).write_gltf(dir));
  EXPECT_VEC3(loaded.scene.materials[0].kr, 0.5f, 0.5f, 0.5f);
  EXPECT_TRUE(any_warning_contains(loaded, "material 0 \"hot\"")) << ::testing::PrintToString(loaded.warnings);
  ScratchDir dir2;
  EXPECT_FALSE(any_warning_contains(io::load_gltf(one_triangle(diffuse(0.5, 0.5, 0.5)).write_gltf(dir2)),
                                   "exceeds 1"));
}

// ================================================================================================
// Textures
// ================================================================================================

TEST(Texture, SrgbDecodedBaseColor) {
  // A 2x1 PNG: red, then grey 128. sRGB-decoded: 128/255 -> ((0.50196 + 0.055) / 1.055)^2.4.
  GltfBuilder b;
  const int texture = b.texture_from_file("checker.png", png_rgb8(2, 1, {255, 0, 0, 128, 128, 128}));
  json m = diffuse(1, 1, 1);
  m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", texture}};
  Primitive p = triangle(b.material(m));
  p.uvs = {{0, 0}, {1, 0}, {0, 1}};
  b.node({{"mesh", b.mesh({p})}});
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  EXPECT_TRUE(other_warnings(loaded).empty()) << ::testing::PrintToString(loaded.warnings);
  const Scene& scene = loaded.scene;
  ASSERT_EQ(scene.materials[0].kd_texture, 0);
  const Texture& t = scene.textures.at(0);
  ASSERT_EQ(t.width, 2);
  ASSERT_EQ(t.height, 1);
  EXPECT_VEC3(t.texel(0, 0), 1, 0, 0);
  const float grey = std::pow((128.0f / 255.0f + 0.055f) / 1.055f, 2.4f);  // 0.21586
  EXPECT_NEAR(t.texel(1, 0).g, grey, 1e-4f);
  EXPECT_NEAR(grey, 0.21586f, 1e-4f);
  EXPECT_NEAR(scene.meshes[0].uvs[1].x, 1.0f, kTol);
}

TEST(Texture, MissingFileGivesWhiteAndAWarningNamingTheUri) {
  GltfBuilder b;
  b.doc["images"] = json::array({{{"uri", "nowhere.png"}}});
  b.doc["textures"] = json::array({{{"source", 0}}});
  json m = diffuse(1, 1, 1);
  m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  b.node({{"mesh", b.mesh({triangle(b.material(m))})}});
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  const std::vector<std::string> warnings = other_warnings(loaded);
  ASSERT_EQ(warnings.size(), 1u) << ::testing::PrintToString(loaded.warnings);
  EXPECT_NE(warnings[0].find("scene.gltf"), std::string::npos);
  EXPECT_NE(warnings[0].find("nowhere.png"), std::string::npos);
  EXPECT_EQ(loaded.scene.materials[0].kd_texture, -1);  // the material without its texture
  EXPECT_VEC3(loaded.scene.materials[0].kd, 1, 1, 1);
  EXPECT_TRUE(loaded.scene.textures.empty());
}

// A scene in DIR/scene/ whose one triangle uses an image of URI `uri`, with green.png's pixel
// beside the scene under `beside` (when not empty) and a red one at DIR/maps/x.png, outside.
struct WindowsPathScene {
  ScratchDir dir;
  std::filesystem::path gltf;
  io::LoadedScene loaded;
  WindowsPathScene(const std::string& uri, const std::string& beside) {
    GltfBuilder b;
    b.doc["images"] = json::array({{{"uri", uri}}});
    b.doc["textures"] = json::array({{{"source", 0}}});
    json m = diffuse(1, 1, 1);
    m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    Primitive p = triangle(b.material(m));
    p.uvs = {{0, 0}, {1, 0}, {0, 1}};
    b.node({{"mesh", b.mesh({p})}});
    gltf = b.write_gltf(dir, "scene/scene.gltf", /*embed_buffer=*/true);
    std::filesystem::create_directories(dir / "maps");
    write_file(dir / "maps" / "x.png", png_rgb8(1, 1, {255, 0, 0}));
    if (!beside.empty()) {
      std::filesystem::create_directories((dir / "scene" / beside).parent_path());
      write_file(dir / "scene" / beside, png_rgb8(1, 1, {0, 255, 0}));
    }
    loaded = io::load_gltf(gltf);
  }
  // The texel the material shows: green from beside the scene; never red, from outside it.
  glm::vec3 texel() const {
    const int t = loaded.scene.materials.at(0).kd_texture;
    return t < 0 ? glm::vec3(-1.0f) : glm::vec3(loaded.scene.textures.at(size_t(t)).texel(0, 0));
  }
};

TEST(Texture, WindowsPathInsideTheFolderIsReadWithoutAWord) {
  // assimp writes `.\SpiderTex.jpg`: the backslash is a folder separator.
  for (const auto& [uri, file] : {std::pair<std::string, std::string>{".\\x.png", "x.png"},
                                  {"maps\\x.png", "maps/x.png"},
                                  {".\\maps%5Cx.png", "maps/x.png"}}) {
    const WindowsPathScene s(uri, file);
    SCOPED_TRACE(uri);
    EXPECT_VEC3(s.texel(), 0, 1, 0);
    EXPECT_TRUE(other_warnings(s.loaded).empty()) << uri << ::testing::PrintToString(s.loaded.warnings);
  }
}

TEST(Texture, ImageOutsideTheFolderIsNotOpenedAndTheOneBesideTheSceneStandsIn) {
  // The red image at ../maps/x.png exists and is never read; x.png beside the scene is.
  for (const std::string uri : {"..\\maps\\x.png", "D:\\work\\x.png", "../maps/x.png",
                                "file:///maps/x.png", "/maps/x.png"}) {
    const WindowsPathScene s(uri, "x.png");
    SCOPED_TRACE(uri);
    EXPECT_VEC3(s.texel(), 0, 1, 0);
    const std::vector<std::string> warnings = other_warnings(s.loaded);
    ASSERT_EQ(warnings.size(), 1u) << uri << ::testing::PrintToString(s.loaded.warnings);
    EXPECT_NE(warnings[0].find("scene.gltf: image 0 \"" + uri + "\""), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("\"x.png\" beside the scene"), std::string::npos) << warnings[0];
  }
}

TEST(Texture, ImageOutsideTheFolderWithNoneBesideIsAWarningNeverARefusal) {
  for (const std::string uri : {"..\\maps\\x.png", "D:\\work\\x.png", "../../etc/secret.png"}) {
    const WindowsPathScene s(uri, "");
    EXPECT_EQ(s.loaded.scene.materials.at(0).kd_texture, -1) << uri;
    EXPECT_EQ(s.loaded.scene.triangle_count(), 1u);
    const std::vector<std::string> warnings = other_warnings(s.loaded);
    ASSERT_EQ(warnings.size(), 1u) << uri << ::testing::PrintToString(s.loaded.warnings);
    EXPECT_NE(warnings[0].find("image 0 \"" + uri + "\""), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("without its texture"), std::string::npos) << warnings[0];
  }
}

TEST(Gltf, BufferWithAWindowsPathInsideTheFolderLoads) {
  GltfBuilder b = one_triangle();
  ScratchDir dir;
  write_file(dir / "data" / "scene.bin", b.bin);
  b.doc["buffers"] = json::array({{{"uri", ".\\data\\scene.bin"}, {"byteLength", b.bin.size()}}});
  EXPECT_EQ(io::load_gltf(b.write_gltf(dir, "win.gltf")).scene.triangle_count(), 1u);
}

TEST(Texture, UndecodableGivesWhiteAndAWarning) {
  GltfBuilder b;
  const int texture = b.texture_from_file("garbage.png", {'n', 'o', 't', ' ', 'a', 'n', ' ', 'i'});
  json m = diffuse(1, 1, 1);
  m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", texture}};
  b.node({{"mesh", b.mesh({triangle(b.material(m))})}});
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  EXPECT_TRUE(any_warning_contains(loaded, "garbage.png"));
  EXPECT_VEC3(loaded.scene.textures.at(0).texel(0, 0), 1, 1, 1);
}

TEST(Texture, FromABufferViewInAGlb) {
  GltfBuilder b;
  const std::vector<unsigned char> png = png_rgb8(1, 1, {0, 255, 0});
  const int view = b.add_view(png.data(), png.size());
  b.doc["images"] = json::array({{{"bufferView", view}, {"mimeType", "image/png"}}});
  b.doc["textures"] = json::array({{{"source", 0}}});
  json m = diffuse(1, 1, 1);
  m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  b.node({{"mesh", b.mesh({triangle(b.material(m))})}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_glb(dir)).scene;
  EXPECT_VEC3(scene.textures.at(0).texel(0, 0), 0, 1, 0);
}

// ================================================================================================
// Lights
// ================================================================================================

TEST(Light, PointIsColourTimesIntensityAtItsNode) {
  GltfBuilder b = one_triangle();
  const int light = b.light({{"type", "point"}, {"name", "bulb"}, {"color", {1, 0.5, 0.25}}, {"intensity", 8}});
  b.node({{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  ASSERT_EQ(scene.lights.size(), 1u);
  const Light& l = scene.lights[0];
  EXPECT_EQ(l.name, "bulb");
  EXPECT_EQ(l.type, LightType::point);
  EXPECT_VEC3(l.intensity, 8, 4, 2);
  EXPECT_VEC3(l.position, 1, 2, 3);
  EXPECT_FALSE(l.attenuation.classroom);  // physical 1/d^2 by default
}

TEST(Light, SpotConesAndWarnExponent) {
  // Rotating -90 deg about X turns the node's -Z into -Y: the spot shines straight down.
  GltfBuilder b = one_triangle();
  const int light = b.light({{"type", "spot"},
                             {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}},
                             {"extras", {{"warn_exponent", 10}}}});
  b.node({{"name", "lamp"},
          {"rotation", {-kHalfSqrt2, 0, 0, kHalfSqrt2}},
          {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
  ScratchDir dir;
  const Light l = io::load_gltf(b.write_gltf(dir)).scene.lights.at(0);
  EXPECT_EQ(l.type, LightType::spot);
  EXPECT_EQ(l.name, "lamp");  // the light has no name: the node's
  EXPECT_FLOAT_EQ(l.inner_cone, 0.2f);
  EXPECT_FLOAT_EQ(l.outer_cone, 0.6f);
  EXPECT_FLOAT_EQ(l.warn_exponent, 10.0f);
  EXPECT_VEC3(l.direction, 0, -1, 0);
  EXPECT_VEC3(l.intensity, 1, 1, 1);  // glTF defaults: white, intensity 1
}

TEST(Light, DirectionalWithClassroomAttenuation) {
  GltfBuilder b = one_triangle();
  const int light = b.light({{"type", "directional"}, {"intensity", 3},
                             {"extras", {{"attenuation", {1, 0.5, 0.25}}}}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
  ScratchDir dir;
  const Light l = io::load_gltf(b.write_gltf(dir)).scene.lights.at(0);
  EXPECT_EQ(l.type, LightType::directional);
  EXPECT_VEC3(l.direction, 0, 0, -1);
  EXPECT_VEC3(l.intensity, 3, 3, 3);
  EXPECT_TRUE(l.attenuation.classroom);
  EXPECT_VEC3(l.attenuation.c, 1, 0.5f, 0.25f);
  EXPECT_NEAR(l.attenuation.factor(2.0f), 1.0f / (1 + 1 + 1), kTol);  // 1/(c0 + 2 c1 + 4 c2)
}

// ================================================================================================
// Cameras
// ================================================================================================

TEST(Camera, PerspectiveFieldsAndNodePose) {
  GltfBuilder b = one_triangle();
  const int camera = b.camera({{"type", "perspective"}, {"name", "eye"},
                               {"perspective", {{"yfov", 0.7}, {"aspectRatio", 1.5}, {"znear", 0.1}, {"zfar", 100}}}});
  b.node({{"camera", camera}, {"translation", {0, 1, 5}}, {"scale", {3, 3, 3}}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  ASSERT_EQ(scene.cameras.size(), 1u);
  const Camera& c = scene.cameras[0];
  EXPECT_EQ(c.name, "eye");
  EXPECT_FLOAT_EQ(c.yfov, 0.7f);
  EXPECT_FLOAT_EQ(c.aspect, 1.5f);
  EXPECT_FLOAT_EQ(c.znear, 0.1f);
  EXPECT_FLOAT_EQ(c.zfar, 100.0f);
  EXPECT_VEC3(c.position(), 0, 1, 5);
  EXPECT_VEC3(c.forward(), 0, 0, -1);
  EXPECT_NEAR(glm::length(glm::vec3(c.to_world[0])), 1.0f, kTol);  // the node's scale is dropped
}

TEST(Camera, FirstInNodeOrderIsDefault) {
  // The file lists "second" first, but the node tree meets "first" (a child of root 0) before
  // "second" (root 1).
  GltfBuilder b = one_triangle();
  const json perspective = {{"yfov", 0.5}, {"znear", 0.1}};
  const int second = b.camera({{"type", "perspective"}, {"name", "second"}, {"perspective", perspective}});
  const int first = b.camera({{"type", "perspective"}, {"name", "first"}, {"perspective", perspective}});
  const int child = b.node({{"camera", first}}, false);
  b.doc["nodes"][0]["children"] = {child};
  b.node({{"camera", second}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  ASSERT_EQ(scene.cameras.size(), 2u);
  EXPECT_EQ(scene.cameras[0].name, "first");
  EXPECT_EQ(scene.cameras[1].name, "second");
  EXPECT_EQ(scene.find_camera("second"), 1);
}

TEST(Camera, NamedAfterItsNodeWhenUnnamed) {
  GltfBuilder b = one_triangle();
  const int camera = b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}});
  b.node({{"name", "tripod"}, {"camera", camera}});
  ScratchDir dir;
  const Camera c = io::load_gltf(b.write_gltf(dir)).scene.cameras.at(0);
  EXPECT_EQ(c.name, "tripod");
  EXPECT_FLOAT_EQ(c.zfar, 0.0f);    // absent: infinite
  EXPECT_FLOAT_EQ(c.aspect, 0.0f);  // absent: none given
}

TEST(Camera, OrthographicSkippedWithWarningAndFramingAdded) {
  GltfBuilder b = one_triangle();
  const int camera = b.camera({{"type", "orthographic"}, {"name", "plan"},
                               {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}});
  b.node({{"camera", camera}});
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  EXPECT_TRUE(any_warning_contains(loaded, "\"plan\""));
  ASSERT_EQ(loaded.scene.cameras.size(), 1u);
  EXPECT_EQ(loaded.scene.cameras[0].name, "framing");
}

TEST(Camera, NoCameraIsSaidWithTheExportersOption) {
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(one_triangle().write_gltf(dir));
  EXPECT_TRUE(any_warning_contains(loaded, "scene.gltf: no camera in the scene"))
      << ::testing::PrintToString(loaded.warnings);
  EXPECT_TRUE(any_warning_contains(loaded, "\"Cameras\""));
  GltfBuilder b = one_triangle();
  b.node({{"camera", b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}})}});
  ScratchDir dir2;
  EXPECT_FALSE(any_warning_contains(io::load_gltf(b.write_gltf(dir2)), "no camera"));
}

TEST(Camera, FramingWhenNone) {
  ScratchDir dir;
  const Scene scene = io::load_gltf(one_triangle().write_gltf(dir)).scene;
  ASSERT_EQ(scene.cameras.size(), 1u);
  const Camera& c = scene.cameras[0];
  EXPECT_EQ(c.name, "framing");
  EXPECT_NEAR(c.position().x, 0.5f, kTol);  // the bounding box's centre, seen from +Z
  EXPECT_NEAR(c.position().y, 0.5f, kTol);
  EXPECT_GT(c.position().z, 0.5f);
  EXPECT_VEC3(c.forward(), 0, 0, -1);
}

// ================================================================================================
// Scene-wide settings
// ================================================================================================

TEST(Scene, ExtrasAmbientBackgroundExposure) {
  GltfBuilder b = one_triangle();
  b.doc["scenes"][0]["extras"] = {{"ambient", 0.1}, {"background", {0.2, 0.3, 0.4}}, {"exposure", -1.5}};
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  EXPECT_VEC3(scene.ambient, 0.1f, 0.1f, 0.1f);
  EXPECT_VEC3(scene.background, 0.2f, 0.3f, 0.4f);
  EXPECT_FLOAT_EQ(scene.exposure, -1.5f);
}

TEST(Scene, DefaultsAndPathAsGiven) {
  ScratchDir dir;
  const std::filesystem::path path = one_triangle().write_gltf(dir, "plain.gltf");
  const Scene scene = io::load_gltf(path).scene;
  EXPECT_EQ(scene.path, path.string());
  EXPECT_VEC3(scene.ambient, 0, 0, 0);
  EXPECT_VEC3(scene.background, 0, 0, 0);
  EXPECT_FLOAT_EQ(scene.exposure, 0.0f);
  EXPECT_TRUE(scene.area_lights.empty());
  EXPECT_EQ(scene.lights.size(), 2u);  // the default lights: the file has none
  EXPECT_TRUE(scene.default_lights);
  EXPECT_EQ(scene.generator, "");
}

// The program that wrote the file (asset.generator), and whether its lights are its own: what
// the exposure warning's hint on photometric lights reads (core/exposure.h).
TEST(Scene, TheGeneratorAndTheFilesOwnLights) {
  GltfBuilder b = one_triangle();
  b.doc["asset"]["generator"] = "Khronos glTF Blender I/O v3.4.50";
  const int light = b.light({{"type", "point"}, {"intensity", 5435.0}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  EXPECT_EQ(scene.generator, "Khronos glTF Blender I/O v3.4.50");
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_FALSE(scene.default_lights);
}

// ================================================================================================
// Bad input: one test per case, each checking the kind and that the message names the file
// ================================================================================================

TEST(Error, MissingFile) {
  ScratchDir dir;
  expect_error(dir / "absent.gltf", ErrorKind::file_missing);
}

TEST(Error, MissingBinFile) {
  ScratchDir dir;
  const auto path = one_triangle().write_gltf(dir);
  std::filesystem::remove(dir / "scene.bin");
  const std::string message = expect_error(path, ErrorKind::file_missing);
  EXPECT_NE(message.find("scene.bin"), std::string::npos) << message;
}

TEST(Error, BrokenJsonIsNotGltf) {
  ScratchDir dir;
  write_file(dir / "broken.gltf", std::string("{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [ "));
  expect_error(dir / "broken.gltf", ErrorKind::not_gltf);
}

// The loader's messages in the user's language (the catalogue's translation), with the same
// kind and the file still first: "FILE: problem".
TEST(Error, MessagesSpeakTheChosenLanguage) {
  const i18n::Catalogue& spanish = i18n::catalogue(i18n::Language::es);
  auto translation = [&](const char* id) {
    const std::string* text = spanish.find(id);
    EXPECT_NE(text, nullptr) << id;
    return text ? *text : std::string(id);
  };
  i18n::set_language(i18n::Language::es);
  ScratchDir dir;
  write_file(dir / "array.gltf", std::string("[1, 2, 3]"));
  const std::string error = expect_error(dir / "array.gltf", ErrorKind::not_gltf);
  EXPECT_EQ(error, (dir / "array.gltf").string() + ": " + translation("not glTF: the JSON is not an object"));
  const io::LoadedScene bare = io::load_gltf(one_triangle(diffuse(1, 1, 1)).write_gltf(dir));
  EXPECT_TRUE(any_warning_contains(bare, ": " + translation(io::kDefaultLightsNotice)));
  EXPECT_NE(translation(io::kDefaultLightsNotice), io::kDefaultLightsNotice);
  i18n::set_language(i18n::Language::en);
  EXPECT_EQ(expect_error(dir / "array.gltf", ErrorKind::not_gltf),
            (dir / "array.gltf").string() + ": not glTF: the JSON is not an object");
}

// What the loader names for a scene that leaves it unnamed (the framing camera, the default
// lights, "mesh 0") reads in the language the scene was loaded in.
TEST(Error, GivenNamesSpeakTheChosenLanguage) {
  const i18n::Catalogue& spanish = i18n::catalogue(i18n::Language::es);
  auto translation = [&](const char* id) {
    const std::string* text = spanish.find(id);
    EXPECT_NE(text, nullptr) << id;
    return text ? *text : std::string(id);
  };
  ScratchDir dir;
  const std::filesystem::path bare = one_triangle(diffuse(1, 1, 1)).write_gltf(dir);
  i18n::set_language(i18n::Language::es);
  const Scene scene = io::load_gltf(bare).scene;
  i18n::set_language(i18n::Language::en);
  EXPECT_EQ(scene.cameras.at(0).name, translation("framing"));
  EXPECT_NE(scene.cameras.at(0).name, "framing");
  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_EQ(scene.lights[0].name, translation("default key light"));
  EXPECT_EQ(scene.lights[1].name, translation("default fill light"));
  EXPECT_EQ(scene.meshes.at(0).name, fmt::format(fmt::runtime(translation("mesh {}")), 0));
  EXPECT_EQ(io::load_gltf(bare).scene.cameras.at(0).name, "framing");  // English again
}

TEST(Error, JsonThatIsNotGltf) {
  ScratchDir dir;
  write_file(dir / "array.gltf", std::string("[1, 2, 3]"));
  expect_error(dir / "array.gltf", ErrorKind::not_gltf);
  write_file(dir / "empty.gltf", std::string("{\"nodes\": []}"));  // no asset
  expect_error(dir / "empty.gltf", ErrorKind::not_gltf);
  write_file(dir / "picture.gltf", png_rgb8(1, 1, {0, 0, 0}));
  expect_error(dir / "picture.gltf", ErrorKind::not_gltf);
}

TEST(Error, BinShorterThanByteLengthIsTruncated) {
  ScratchDir dir;
  const auto path = one_triangle().write_gltf(dir);
  std::filesystem::resize_file(dir / "scene.bin", 20);
  const std::string message = expect_error(path, ErrorKind::truncated_buffer);
  EXPECT_NE(message.find("scene.bin"), std::string::npos) << message;
}

TEST(Error, GlbBinChunkShorterThanBufferIsTruncated) {
  GltfBuilder b = one_triangle();
  b.doc["buffers"] = json::array({{{"byteLength", b.bin.size() + 64}}});
  ScratchDir dir;
  expect_error(b.write_glb(dir), ErrorKind::truncated_buffer);
}

// gltfpack writes such a file for a scene it empties: the message says what is wrong.
TEST(Error, GlbWithAnEmptyBinChunkSaysSo) {
  GltfBuilder b;
  b.doc["buffers"] = json::array({{{"byteLength", 0}}});
  ScratchDir dir;
  const auto path = b.write_glb(dir);
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> glb((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const uint32_t empty_bin[2] = {0u, 0x004E4942u};  // length 0, "BIN\0"
  glb.insert(glb.end(), reinterpret_cast<const unsigned char*>(empty_bin),
             reinterpret_cast<const unsigned char*>(empty_bin) + 8);
  const uint32_t total = uint32_t(glb.size());
  std::memcpy(glb.data() + 8, &total, 4);
  write_file(path, glb);
  const std::string message = expect_error(path, ErrorKind::bad_value);
  EXPECT_NE(message.find("BIN chunk is empty"), std::string::npos) << message;
}

TEST(Error, GlbCutShortIsTruncated) {
  ScratchDir dir;
  const auto path = one_triangle().write_glb(dir);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 8);
  expect_error(path, ErrorKind::truncated_buffer);
}

TEST(Error, AccessorPastTheEndOfItsBufferView) {
  GltfBuilder b = one_triangle();
  b.doc["accessors"][0]["count"] = 400;  // POSITION: 400 x 12 bytes in a 36-byte view
  ScratchDir dir;
  const std::string message = expect_error(b.write_gltf(dir), ErrorKind::truncated_buffer);
  EXPECT_NE(message.find("accessor 0 reaches past the end of bufferView 0 (needs 4800 bytes, has 36)"),
            std::string::npos) << message;
}

TEST(Error, BufferViewPastTheEndOfItsBuffer) {
  GltfBuilder b = one_triangle();
  b.doc["bufferViews"][0]["byteOffset"] = 1000;
  ScratchDir dir;
  const std::string message = expect_error(b.write_gltf(dir), ErrorKind::truncated_buffer);
  EXPECT_NE(message.find("bufferView 0"), std::string::npos) << message;
}

TEST(Error, VertexIndexOutOfRange) {
  Primitive p = triangle();
  p.indices = {0, 1, 3};  // 3 vertices
  GltfBuilder b;
  b.node({{"mesh", b.mesh({p})}});
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::index_out_of_range);
}

TEST(Error, MaterialIndexOutOfRange) {
  GltfBuilder b;
  b.node({{"mesh", b.mesh({triangle(3)})}});
  ScratchDir dir;
  const std::string message = expect_error(b.write_gltf(dir), ErrorKind::index_out_of_range);
  EXPECT_NE(message.find("material 3"), std::string::npos) << message;
}

TEST(Error, AccessorIndexOutOfRange) {
  GltfBuilder b = one_triangle();
  b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 42;
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::index_out_of_range);
}

TEST(Error, BufferViewIndexOutOfRange) {
  GltfBuilder b = one_triangle();
  b.doc["accessors"][0]["bufferView"] = 9;
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::index_out_of_range);
}

TEST(Error, NodeIndexOutOfRange) {
  GltfBuilder b = one_triangle();
  b.doc["nodes"][0]["children"] = {5};
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::index_out_of_range);
  GltfBuilder root = one_triangle();
  root.doc["scenes"][0]["nodes"].push_back(7);
  ScratchDir dir2;
  expect_error(root.write_gltf(dir2), ErrorKind::index_out_of_range);
}

TEST(Error, MeshIndexOutOfRange) {
  GltfBuilder b = one_triangle();
  b.node({{"mesh", 4}});
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::index_out_of_range);
}

TEST(Error, TextureIndexOutOfRange) {
  json m = diffuse(1, 1, 1);
  m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 2}};
  ScratchDir dir;
  expect_error(one_triangle(m).write_gltf(dir), ErrorKind::index_out_of_range);
}

TEST(Error, ImageSourceIndexOutOfRange) {
  json m = diffuse(1, 1, 1);
  m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  GltfBuilder b = one_triangle(m);
  b.doc["textures"] = json::array({{{"source", 3}}});
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::index_out_of_range);
}

TEST(Error, LightIndexOutOfRange) {
  GltfBuilder b = one_triangle();
  b.light({{"type", "point"}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::index_out_of_range);
}

TEST(Error, NaNPositionIsNotFinite) {
  Primitive p = triangle();
  p.positions[1].y = std::numeric_limits<float>::quiet_NaN();
  GltfBuilder b;
  b.node({{"mesh", b.mesh({p})}});
  ScratchDir dir;
  const std::string message = expect_error(b.write_gltf(dir), ErrorKind::not_finite);
  EXPECT_NE(message.find("POSITION"), std::string::npos) << message;
}

TEST(Error, InfiniteNormalIsNotFinite) {
  Primitive p = triangle();
  p.normals = {{0, 0, 1}, {0, 0, std::numeric_limits<float>::infinity()}, {0, 0, 1}};
  GltfBuilder b;
  b.node({{"mesh", b.mesh({p})}});
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::not_finite);
}

TEST(Error, NaNTexcoordIsNotFinite) {
  Primitive p = triangle();
  p.uvs = {{0, 0}, {std::numeric_limits<float>::quiet_NaN(), 0}, {0, 1}};
  GltfBuilder b;
  b.node({{"mesh", b.mesh({p})}});
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::not_finite);
}

TEST(Error, MaterialValueBeyondFloatIsNotFinite) {
  // JSON cannot hold NaN or Inf; 1e39 is a finite double but infinite as the float we compute in.
  json m = diffuse(1, 1, 1);
  m["name"] = "glass";
  m["extras"] = {{"ior", 1e39}};
  ScratchDir dir;
  const std::string message = expect_error(one_triangle(m).write_gltf(dir), ErrorKind::not_finite);
  EXPECT_NE(message.find("material 0 \"glass\": ior is infinite"), std::string::npos) << message;
}

TEST(Error, NumberOverflowingDoubleIsNotFinite) {
  json m = diffuse(1, 1, 1);
  m["extras"] = {{"ks", 0.123456}};
  ScratchDir dir;
  const auto path = one_triangle(m).write_gltf(dir);
  replace_in_file(path, "0.123456", "1e999");
  expect_error(path, ErrorKind::not_finite);
}

TEST(Error, LightValueBeyondFloatIsNotFinite) {
  GltfBuilder b = one_triangle();
  b.light({{"type", "point"}, {"intensity", 1e39}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::not_finite);
}

TEST(Error, NodeTransformBeyondFloatIsNotFinite) {
  GltfBuilder b = one_triangle();
  b.doc["nodes"][0]["translation"] = {0, 1e39, 0};
  ScratchDir dir;
  const std::string message = expect_error(b.write_gltf(dir), ErrorKind::not_finite);
  EXPECT_NE(message.find("node 0: translation"), std::string::npos) << message;
}

TEST(Error, UriWithDotDotIsOutsideTheFolder) {
  // The file it names exists and has the right size: it is refused before it is read.
  ScratchDir dir;
  GltfBuilder b = one_triangle();
  write_file(dir / "outside.bin", b.bin);
  b.doc["buffers"] = json::array({{{"uri", "../outside.bin"}, {"byteLength", b.bin.size()}}});
  const std::string message = expect_error(b.write_gltf(dir, "sub/scene.gltf"), ErrorKind::uri_outside_folder);
  EXPECT_NE(message.find("../outside.bin"), std::string::npos) << message;
  b.doc["buffers"][0]["uri"] = "%2E%2E/outside.bin";  // percent-encoded the same
  expect_error(b.write_gltf(dir, "sub/scene.gltf"), ErrorKind::uri_outside_folder);
}

TEST(Error, AbsoluteUriIsOutsideTheFolder) {
  ScratchDir dir;
  GltfBuilder b = one_triangle();
  write_file(dir / "scene.bin", b.bin);
  b.doc["buffers"] = json::array({{{"uri", (dir / "scene.bin").string()}, {"byteLength", b.bin.size()}}});
  expect_error(b.write_gltf(dir, "abs.gltf"), ErrorKind::uri_outside_folder);
}

TEST(Error, FileSchemeUriIsOutsideTheFolder) {
  ScratchDir dir;
  GltfBuilder b = one_triangle();
  b.doc["buffers"] = json::array({{{"uri", "file://" + (dir / "scene.bin").string()}, {"byteLength", b.bin.size()}}});
  write_file(dir / "scene.bin", b.bin);
  expect_error(b.write_gltf(dir, "file.gltf"), ErrorKind::uri_outside_folder);
}

TEST(Error, BufferWithAWindowsPathOutsideTheFolderIsRefusedNamingIt) {
  // Unlike an image, a buffer has no stand-in: the scene is refused, naming the URI.
  ScratchDir dir;
  GltfBuilder b = one_triangle();
  write_file(dir / "outside.bin", b.bin);
  for (const std::string uri : {"..\\outside.bin", "D:\\work\\outside.bin"}) {
    b.doc["buffers"] = json::array({{{"uri", uri}, {"byteLength", b.bin.size()}}});
    const std::string message = expect_error(b.write_gltf(dir, "sub/scene.gltf"), ErrorKind::uri_outside_folder);
    EXPECT_NE(message.find(uri), std::string::npos) << message;
  }
  b.doc["buffers"] = json::array({{{"uri", ".\\missing.bin"}, {"byteLength", b.bin.size()}}});
  const std::string message = expect_error(b.write_gltf(dir, "sub/scene.gltf"), ErrorKind::file_missing);
  EXPECT_NE(message.find(".\\missing.bin"), std::string::npos) << message;
}

TEST(Error, NoTriangles) {
  Primitive lines = triangle();
  lines.mode = 1;
  GltfBuilder b;
  b.node({{"mesh", b.mesh({lines})}});
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::no_triangles);
  GltfBuilder empty;  // a scene with no nodes at all
  ScratchDir dir2;
  expect_error(empty.write_gltf(dir2), ErrorKind::no_triangles);
}

TEST(Error, NegativeOrZeroIorIsBadValue) {
  json m = diffuse(1, 1, 1);
  m["extras"] = {{"ior", -1.0}};
  ScratchDir dir;
  expect_error(one_triangle(m).write_gltf(dir), ErrorKind::bad_value);
  m["extras"] = json::object();
  m["extensions"] = {{"KHR_materials_ior", {{"ior", 0.0}}}};
  ScratchDir dir2;
  expect_error(one_triangle(m).write_gltf(dir2), ErrorKind::bad_value);
}

TEST(Error, NegativeCoefficientIsBadValue) {
  json m = diffuse(1, 1, 1);
  m["name"] = "weird";
  m["extras"] = {{"ks", {0.1, -0.2, 0.1}}};
  ScratchDir dir;
  const std::string message = expect_error(one_triangle(m).write_gltf(dir), ErrorKind::bad_value);
  EXPECT_NE(message.find("material 0 \"weird\""), std::string::npos) << message;
}

TEST(Error, NodeCycleIsBadValueNotAHang) {
  GltfBuilder b = one_triangle();
  b.doc["nodes"][0]["children"] = {0};
  ScratchDir dir;
  expect_error(b.write_gltf(dir), ErrorKind::bad_value);
}

// ================================================================================================
// Real files: metals, scenes without lights, vertex colours, texture transforms, sparse
// accessors, required extensions, versions
// ================================================================================================

TEST(Metal, RoughMetalKeepsItsBaseColourAsHighlight) {
  // glTF's defaults (metallic 1, roughness 1): no diffuse part, ks = baseColor, n = 1.
  const Material plain = load_material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.8, 0.7, 1}}}}});
  EXPECT_VEC3(plain.kd, 0, 0, 0);
  EXPECT_VEC3(plain.ks, 0.9f, 0.8f, 0.7f);
  EXPECT_VEC3(plain.kr, 0, 0, 0);
  EXPECT_FLOAT_EQ(plain.shininess, 1.0f);
  // roughness 0.5: the same highlight, n = 2 / 0.5^4 - 2 = 30.
  const Material satin = load_material(
      {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.8, 0.7, 1}}, {"roughnessFactor", 0.5}}}});
  EXPECT_VEC3(satin.ks, 0.9f, 0.8f, 0.7f);
  EXPECT_NEAR(satin.shininess, 30.0f, 1e-3f);
  // A smooth metal is a mirror instead, without a highlight.
  const Material mirror = load_material(
      {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.8, 0.7, 1}}, {"roughnessFactor", 0.0}}}});
  EXPECT_VEC3(mirror.kr, 0.9f, 0.8f, 0.7f);
  EXPECT_VEC3(mirror.ks, 0, 0, 0);
  // extras.ks still wins.
  json m = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.8, 0.7, 1}}}}, {"extras", {{"ks", 0.1}}}};
  EXPECT_VEC3(load_material(m).ks, 0.1f, 0.1f, 0.1f);
}

TEST(DefaultLights, AddedOnlyWithoutLightsWithTheNotice) {
  ScratchDir dir;
  const io::LoadedScene bare = io::load_gltf(one_triangle(diffuse(1, 1, 1)).write_gltf(dir));
  EXPECT_EQ(bare.scene.lights.size(), 2u);
  EXPECT_TRUE(any_warning_contains(bare, io::kDefaultLightsNotice));

  GltfBuilder lit = one_triangle(diffuse(1, 1, 1));
  lit.node({{"extensions", {{"KHR_lights_punctual", {{"light", lit.light({{"type", "point"}})}}}}}});
  ScratchDir dir2;
  const io::LoadedScene with_light = io::load_gltf(lit.write_gltf(dir2));
  EXPECT_EQ(with_light.scene.lights.size(), 1u);
  EXPECT_FALSE(any_warning_contains(with_light, io::kDefaultLightsNotice));

  json glowing = diffuse(1, 1, 1);
  glowing["emissiveFactor"] = {1, 1, 1};
  ScratchDir dir3;
  const io::LoadedScene emitter = io::load_gltf(one_triangle(glowing).write_gltf(dir3));
  EXPECT_TRUE(emitter.scene.lights.empty());  // an emissive triangle is a light
}

TEST(DefaultLights, InsideARoomTheyGoInsideAndLightTheBackWall) {
  // Outside the walls they would light nothing the camera sees. Inside: both in the room, and
  // the key sees the back wall's centre from its front side.
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(closed_room().write_gltf(dir));
  ASSERT_EQ(loaded.scene.lights.size(), 2u);
  const Bounds room = loaded.scene.bounds();
  for (const Light& light : loaded.scene.lights) {
    SCOPED_TRACE(light.name);
    EXPECT_TRUE(glm::all(glm::greaterThan(light.position, room.min)) &&
                glm::all(glm::lessThan(light.position, room.max)));
  }
  const Light& key = loaded.scene.lights[0];
  EXPECT_GT(key.position.z, -3.0f + 0.5f);  // in front of the back wall (z = -3), facing +Z
  EXPECT_GT(key.position.y, 1.5f);          // above the camera: shadows fall below what it sees
  // A white surface R from the key shows radiance 1: I = pi R^2, R half the room's diagonal.
  const float R = 0.5f * glm::length(room.extent());
  EXPECT_NEAR(key.intensity.r, std::numbers::pi_v<float> * R * R, 1e-3f * R * R);
  // The notice says how to export lights from Blender.
  EXPECT_TRUE(any_warning_contains(loaded, "\"Punctual Lights\"")) << ::testing::PrintToString(loaded.warnings);
}

TEST(DefaultLights, KeyLightGivesRadianceOneAtTheCentreFillNone) {
  // A camera turned 90 degrees about Y (looking down -X) so that the camera's axes, not the
  // world's, must place the lights. Bounds: the quad from (-1,-1,0) to (1,1,0), R = sqrt(2).
  GltfBuilder b;
  Primitive quad;
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.material = b.material(diffuse(1, 1, 1));
  b.node({{"mesh", b.mesh({quad})}});
  const double s = std::sqrt(0.5);
  b.node({{"camera", b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}})},
          {"rotation", {0, s, 0, s}}, {"translation", {5, 0, 0}}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  ASSERT_EQ(scene.lights.size(), 2u);
  const Light& key = scene.lights[0];
  const Light& fill = scene.lights[1];
  const glm::vec3 centre(0.0f);
  const float R = std::sqrt(2.0f);
  // The camera's right is world -Z, up +Y, back +X.
  const glm::vec3 right(0, 0, -1), up(0, 1, 0), back(1, 0, 0);
  EXPECT_NEAR(glm::length(key.position - centre), 2 * R, 1e-4f);
  EXPECT_NEAR(glm::length(fill.position - centre), 2 * R, 1e-4f);
  const glm::vec3 to_key = glm::normalize(key.position - centre), to_fill = glm::normalize(fill.position - centre);
  EXPECT_NEAR(glm::dot(to_key, back), 1 / std::sqrt(3.0f), 1e-5f);
  EXPECT_NEAR(glm::dot(to_key, up), 1 / std::sqrt(3.0f), 1e-5f);
  EXPECT_NEAR(glm::dot(to_key, right), 1 / std::sqrt(3.0f), 1e-5f);
  EXPECT_NEAR(glm::dot(to_fill, back), 1 / std::sqrt(2.0f), 1e-5f);
  EXPECT_NEAR(glm::dot(to_fill, right), -1 / std::sqrt(2.0f), 1e-5f);
  EXPECT_NEAR(glm::dot(to_key, to_fill), 0.0f, 1e-5f);  // the fill grazes a surface facing the key
  // Lambert in radiance, L = (kd / pi) I cos / d^2, of a white surface at c facing the key.
  const float d = glm::length(key.position - centre);
  const float L_key = key.intensity.r / std::numbers::pi_v<float> / (d * d);
  EXPECT_NEAR(L_key, 1.0f, 1e-5f);
  EXPECT_NEAR(fill.intensity.r / key.intensity.r, 0.25f, 1e-6f);
  EXPECT_EQ(key.type, LightType::point);
  EXPECT_FALSE(key.attenuation.classroom);
}

TEST(VertexColour, Color0IsReadAndInterpolated) {
  GltfBuilder b;
  Primitive p = triangle(b.material(diffuse(0.5, 0.5, 0.5)));
  p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  p.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  b.node({{"mesh", b.mesh({p})}});
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  const Mesh& mesh = scene.meshes.at(0);
  ASSERT_EQ(mesh.colors.size(), 3u);
  EXPECT_VEC3(mesh.colour_at(0, glm::vec2(0, 0)), 1, 0, 0);
  EXPECT_VEC3(mesh.colour_at(0, glm::vec2(0.25f, 0.5f)), 0.25f, 0.25f, 0.5f);
  // Without COLOR_0 the factor is white.
  ScratchDir dir2;
  EXPECT_VEC3(io::load_gltf(one_triangle().write_gltf(dir2)).scene.meshes[0].colour_at(0, glm::vec2(0.3f, 0.3f)), 1, 1, 1);
}

TEST(VertexColour, NormalizedBytesRgbaAndFlatNormals) {
  // RGBA unsigned bytes, normalized; no NORMAL, so the loader un-shares the vertices.
  GltfBuilder b = one_triangle();
  const std::vector<uint8_t> rgba = {255, 0, 0, 7, 0, 51, 0, 7, 0, 0, 255, 7};
  const int view = b.add_view(rgba.data(), rgba.size());
  b.doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = b.add_accessor(view, kUnsignedByte, 3, "VEC4", 0, true);
  ScratchDir dir;
  const Mesh mesh = io::load_gltf(b.write_gltf(dir)).scene.meshes.at(0);
  ASSERT_EQ(mesh.colors.size(), 3u);
  EXPECT_VEC3(mesh.colour_at(0, glm::vec2(1, 0)), 0, 0.2f, 0);
  // Integers that are not normalized are not colours.
  b.doc["accessors"].back()["normalized"] = false;
  ScratchDir dir2;
  expect_error(b.write_gltf(dir2), ErrorKind::bad_value);
}

TEST(TextureTransform, OffsetRotationScaleMoveTheUvs) {
  // uv' = offset + R(rotation) (scale * uv), R = [cos sin; -sin cos]: (1, 0) scaled by (2, 3)
  // is (2, 0); turned by pi/2 it is (0, -2); offset by (0.5, 0.25) it is (0.5, -1.75).
  GltfBuilder b;
  const int texture = b.texture_from_file("white.png", png_rgb8(1, 1, {255, 255, 255}));
  json m = diffuse(1, 1, 1);
  m["pbrMetallicRoughness"]["baseColorTexture"] = {
      {"index", texture},
      {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0.25}}, {"rotation", std::numbers::pi / 2},
                                                 {"scale", {2, 3}}}}}}};
  Primitive p = triangle(b.material(m));
  p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  p.uvs = {{0, 0}, {1, 0}, {0, 1}};
  b.node({{"mesh", b.mesh({p})}});
  b.doc["extensionsUsed"] = {"KHR_texture_transform"};
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(b.write_gltf(dir));
  const Mesh& mesh = loaded.scene.meshes.at(0);
  EXPECT_NEAR(mesh.uvs[0].x, 0.5f, kTol);
  EXPECT_NEAR(mesh.uvs[0].y, 0.25f, kTol);
  EXPECT_NEAR(mesh.uvs[1].x, 0.5f, kTol);
  EXPECT_NEAR(mesh.uvs[1].y, -1.75f, kTol);
  EXPECT_NEAR(mesh.uvs[2].x, 0.5f + 3.0f, kTol);  // (0, 3) turned by pi/2 is (3, 0)
  EXPECT_NEAR(mesh.uvs[2].y, 0.25f, kTol);
  EXPECT_FALSE(any_warning_contains(loaded, "KHR_texture_transform"));
}

TEST(Sparse, AccessorValuesReplaceTheBaseAtTheirIndices) {
  // POSITION's base is the unit triangle; the sparse part moves vertex 2 to (0, 2, 0).
  GltfBuilder b = one_triangle();
  const std::vector<uint16_t> index = {2};
  const std::vector<glm::vec3> value = {{0, 2, 0}};
  const int indices_view = b.add_view(index.data(), 2);
  const int values_view = b.add_view(&value[0], sizeof(glm::vec3));
  json& position = b.doc["accessors"][0];
  position["sparse"] = {{"count", 1},
                        {"indices", {{"bufferView", indices_view}, {"componentType", kUnsignedShort}}},
                        {"values", {{"bufferView", values_view}}}};
  ScratchDir dir;
  const Scene scene = io::load_gltf(b.write_gltf(dir)).scene;
  EXPECT_VEC3(scene.meshes.at(0).positions[2], 0, 2, 0);
  EXPECT_VEC3(scene.meshes.at(0).positions[1], 1, 0, 0);
  // A sparse accessor without a bufferView starts from zeros.
  position.erase("bufferView");
  position["sparse"]["count"] = 1;
  ScratchDir dir2;
  expect_error(b.write_gltf(dir2), ErrorKind::no_triangles);  // (0,0,0) (0,0,0) (0,2,0): no area
  // An index past the accessor is refused.
  position["bufferView"] = 0;
  const std::vector<uint16_t> bad = {3};
  position["sparse"]["indices"]["bufferView"] = b.add_view(bad.data(), 2);
  ScratchDir dir3;
  expect_error(b.write_gltf(dir3), ErrorKind::index_out_of_range);
}

TEST(Material, ReflectanceAboveOneIsClampedWithAWarning) {
  // 1e30 would make radiosity's sums and the tracer's weights overflow to inf and NaN.
  json m = diffuse(1e30, 0.5, 0.5);
  m["extras"] = {{"ks", {2.0, 0.5, 0.5}}};
  ScratchDir dir;
  const io::LoadedScene loaded = io::load_gltf(one_triangle(m).write_gltf(dir));
  EXPECT_VEC3(loaded.scene.materials[0].kd, 1.0f, 0.5f, 0.5f);
  EXPECT_VEC3(loaded.scene.materials[0].ks, 1.0f, 0.5f, 0.5f);
  EXPECT_TRUE(any_warning_contains(loaded, "baseColorFactor")) << ::testing::PrintToString(loaded.warnings);
  EXPECT_TRUE(any_warning_contains(loaded, "ks")) << ::testing::PrintToString(loaded.warnings);
}

TEST(Error, RequiredExtensionNotImplementedIsNamed) {
  for (const char* name : {"KHR_draco_mesh_compression", "EXT_made_up"}) {
    GltfBuilder b = one_triangle();
    b.doc["extensionsUsed"] = {name};
    b.doc["extensionsRequired"] = {name};
    ScratchDir dir;
    const std::string message = expect_error(b.write_gltf(dir), ErrorKind::bad_value);
    EXPECT_NE(message.find(name), std::string::npos) << message;
  }
  // Only used, not required: a warning naming it.
  GltfBuilder b = one_triangle();
  b.doc["extensionsUsed"] = {"EXT_made_up"};
  ScratchDir dir;
  EXPECT_TRUE(any_warning_contains(io::load_gltf(b.write_gltf(dir)), "EXT_made_up"));
  // Required and implemented: fine.
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensionsRequired"] = {"KHR_lights_punctual"};
  ScratchDir dir2;
  EXPECT_NO_THROW(io::load_gltf(b.write_gltf(dir2)));
}

TEST(Error, GltfOneIsNotSupported) {
  GltfBuilder b = one_triangle();
  b.doc["asset"]["version"] = "1.0";
  ScratchDir dir;
  EXPECT_NE(expect_error(b.write_gltf(dir), ErrorKind::not_gltf).find("glTF 1.0 is not supported"), std::string::npos);
  // A 1.0 file without an asset object: meshes keyed by name.
  ScratchDir dir2;
  write_file(dir2.path / "old.gltf", std::string(R"({"meshes": {"box": {}}, "scene": "default"})"));
  EXPECT_NE(expect_error(dir2.path / "old.gltf", ErrorKind::not_gltf).find("glTF 1.0 is not supported"),
            std::string::npos);
  b.doc["asset"]["version"] = "3.0";
  ScratchDir dir3;
  expect_error(b.write_gltf(dir3), ErrorKind::not_gltf);
}

TEST(Error, NodeMatrixWithoutAffineLastRow) {
  GltfBuilder b = one_triangle();
  b.doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0};
  ScratchDir dir;
  EXPECT_NE(expect_error(b.write_gltf(dir), ErrorKind::bad_value).find("last row"), std::string::npos);
}

TEST(Error, CameraAspectRatioZero) {
  GltfBuilder b = one_triangle();
  b.node({{"camera", b.camera({{"type", "perspective"},
                               {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"aspectRatio", 0}}}})}});
  ScratchDir dir;
  EXPECT_NE(expect_error(b.write_gltf(dir), ErrorKind::bad_value).find("aspectRatio"), std::string::npos);
}

TEST(Error, NoTrianglesNamesTheSkippedMeshes) {
  Primitive points = triangle();
  points.mode = 0;
  GltfBuilder b;
  b.node({{"mesh", b.mesh({points}, "dots")}});
  ScratchDir dir;
  const std::string message = expect_error(b.write_gltf(dir), ErrorKind::no_triangles);
  EXPECT_NE(message.find("mesh 0 \"dots\""), std::string::npos) << message;
  EXPECT_NE(message.find("mode 0"), std::string::npos) << message;
}

TEST(Error, NoTrianglesSaysTheyHadNoArea) {
  GltfBuilder b;
  for (int m = 0; m < 2; ++m) {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};  // collinear
    p.indices = {0, 1, 2};
    b.node({{"mesh", b.mesh({p}, std::string(1, char('a' + m)))}});
  }
  ScratchDir dir;
  const std::string message = expect_error(b.write_gltf(dir), ErrorKind::no_triangles);
  EXPECT_NE(message.find("dropped 2 zero-area triangles in 2 meshes"), std::string::npos) << message;
}

}  // namespace
}  // namespace luz::test
