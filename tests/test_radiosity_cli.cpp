// `luz render --model radiosity` as a user calls it: its flags, their usage errors (exit 2),
// the residual history in CSV, and `luz bench radiosity`'s table.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "gltf_fixture.h"
#include "support.h"

namespace luz {
namespace {

using test::run_luz;

std::string cornell() { return (test::scene_dir() / "cornell_box.gltf").string(); }
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A box of 1 m with its own vertices and normal per face (24 corners, as COLLADA2GLTF writes it).
test::Primitive box(int material) {
  test::Primitive p;
  p.material = material;
  for (int axis = 0; axis < 3; ++axis)
    for (const float side : {-1.0f, 1.0f}) {
      glm::vec3 n(0.0f), u(0.0f), v(0.0f);
      n[axis] = side;
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = side;  // u x v = side * n-axis: counter-clockwise seen from outside
      const uint32_t first = uint32_t(p.positions.size());
      for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        p.positions.push_back(0.5f * (n + c.x * u + c.y * v));
        p.normals.push_back(n);
      }
      for (const uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) p.indices.push_back(first + k);
    }
  return p;
}

// Khronos's Box as its file is shaped: a root node whose matrix turns Z-up into Y-up, the mesh
// on a child, no lights (so the default ones) and no camera. `pbr`: the material's
// pbrMetallicRoughness; Box's names a red base colour and leaves metallicFactor out.
std::filesystem::path khronos_box(const test::ScratchDir& dir, const std::string& name, const nlohmann::json& pbr) {
  test::GltfBuilder b;
  const int red = b.material({{"name", "Red"}, {"pbrMetallicRoughness", pbr}});
  const int child = b.node({{"mesh", b.mesh({box(red)}, "Mesh")}}, false);
  b.node({{"children", {child}}, {"matrix", {1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1}}});
  return b.write_gltf(dir, name);
}

// The mean relative error over lit pixels that `luz compare A B` prints.
double compared(const std::filesystem::path& a, const std::filesystem::path& b) {
  const auto result = run_luz({"compare", a.string(), b.string()});
  const std::string key = "mean relative error over lit pixels: ";
  const size_t at = result.output.find(key);
  if (result.exit_code != 0 || at == std::string::npos) {
    ADD_FAILURE() << result.output;
    return 1e9;
  }
  return std::stod(result.output.substr(at + key.size()));
}

TEST(RadiosityCli, HelpListsTheFlags) {
  const auto help = run_luz({"render", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag : {"radiosity", "--shots", "--converge", "--patch-size", "--hemicube-res",
                           "--ambient-estimate", "--csv", "--form-factors", "--visibility-rays",
                           "--pixel-samples", "--meshing", "--refine-threshold", "--refine-levels", "--time"})
    EXPECT_TRUE(contains(help.output, flag)) << flag;
}

TEST(RadiosityCli, RadiosityFlagsWithAnotherModelAreUsageErrors) {
  test::ScratchDir dir;
  for (const std::vector<std::string>& flag :
       std::vector<std::vector<std::string>>{{"--shots", "5"}, {"--converge", "0.1"},
                                             {"--patch-size", "0.1"}, {"--hemicube-res", "64"},
                                             {"--ambient-estimate"}, {"--csv", "x.csv"},
                                             {"--visibility-rays", "8"}, {"--pixel-samples", "4"},
                                             {"--meshing", "uniform"}, {"--refine-threshold", "0.2"},
                                             {"--time", "1"}}) {
    std::vector<std::string> args = {"render", cornell(), "--model", "phong", "--out",
                                     (dir / "a.png").string()};
    args.insert(args.end(), flag.begin(), flag.end());
    const auto result = run_luz(args);
    EXPECT_EQ(result.exit_code, 2) << flag[0] << ": " << result.output;
    EXPECT_TRUE(contains(result.output, flag[0])) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
  }
}

TEST(RadiosityCli, BadValuesAreUsageErrors) {
  test::ScratchDir dir;
  const std::string out = (dir / "a.png").string();
  for (const std::vector<std::string>& bad :
       std::vector<std::vector<std::string>>{{"--hemicube-res", "65"}, {"--hemicube-res", "32"},
                                             {"--hemicube-res", "2048"}, {"--shots", "0"},
                                             {"--patch-size", "-1"}, {"--converge", "0"},
                                             {"--shots", "3", "--converge", "0.1"},
                                             {"--visibility-rays", "0"}, {"--visibility-rays", "65"},
                                             {"--pixel-samples", "3"}, {"--pixel-samples", "0"},
                                             {"--form-factors", "raytraced"}, {"--meshing", "fine"},
                                             {"--refine-threshold", "0"}, {"--refine-threshold", "-1"},
                                             {"--refine-levels", "0"}, {"--refine-levels", "13"},
                                             {"--time", "0"}, {"--time", "-1"}}) {
    std::vector<std::string> args = {"render", cornell(), "--model", "radiosity", "--out", out};
    args.insert(args.end(), bad.begin(), bad.end());
    EXPECT_EQ(run_luz(args).exit_code, 2) << bad[0] << " " << bad[1];
  }
}

TEST(RadiosityCli, CsvHoldsOneRowPerShot) {
  test::ScratchDir dir;
  const auto result = run_luz({"render", cornell(), "--model", "radiosity", "--out",
                               (dir / "a.png").string(), "--size", "64x64", "--patch-size", "0.2",
                               "--hemicube-res", "64", "--shots", "40", "-q", "--csv",
                               (dir / "history.csv").string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output, "") << "-q prints nothing (no progress bar either)";
  std::ifstream csv(dir / "history.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "shot,unshot_power,fraction,seconds");
  int rows = 0;
  double previous_fraction = 2.0;
  while (std::getline(csv, line)) {
    std::istringstream fields(line);
    int shot = 0;
    double power = 0, fraction = 0, seconds = 0;
    char comma = 0;
    fields >> shot >> comma >> power >> comma >> fraction >> comma >> seconds;
    EXPECT_EQ(shot, rows) << line;
    EXPECT_LE(fraction, previous_fraction) << line;
    previous_fraction = fraction;
    ++rows;
  }
  EXPECT_EQ(rows, 41) << "shot 0 (nothing shot yet) and 40 shots";
  EXPECT_GT(previous_fraction, 0.0);
  EXPECT_LT(previous_fraction, 0.9) << "40 shots move most of the lamp's power";
}

// The last row of a --csv history: shots and seconds of solving.
std::pair<int, double> last_shot(const std::filesystem::path& csv_path) {
  std::ifstream csv(csv_path);
  std::string line, last;
  while (std::getline(csv, line)) last = line;
  std::istringstream fields(last);
  int shot = -1;
  double power = 0, fraction = 0, seconds = 0;
  char comma = 0;
  fields >> shot >> comma >> power >> comma >> fraction >> comma >> seconds;
  return {shot, seconds};
}

// --time bounds the solve of a big scene: the shooting stops at the first shot past it (3000
// shots here take about 18 s), says so, and the picture is written.
TEST(RadiosityCli, TimeStopsTheShootingAndSaysSo) {
  test::ScratchDir dir;
  for (const char* model : {"radiosity", "hybrid"}) {
    const auto out = dir / (std::string(model) + ".png");
    const auto csv = dir / (std::string(model) + ".csv");
    const auto timed = run_luz({"render", cornell(), "--model", model, "--out", out.string(), "--size", "32x32",
                                "--patch-size", "0.2", "--hemicube-res", "64", "--shots", "3000", "--time", "0.5",
                                "--csv", csv.string()});
    ASSERT_EQ(timed.exit_code, 0) << model << ": " << timed.output;
    EXPECT_TRUE(contains(timed.output, "stopped by --time 0.5")) << timed.output;
    EXPECT_TRUE(std::filesystem::exists(out)) << model;
    const auto [shots, seconds] = last_shot(csv);
    EXPECT_GT(shots, 0) << model;
    EXPECT_LT(shots, 3000) << model;
    EXPECT_GE(seconds, 0.5) << model;
    EXPECT_LT(seconds, 3.0) << model << ": one shot past the time, not many";
  }
  // Stopped by --shots 1 in a shot that also outlasts the time (a 512-pixel hemicube takes
  // milliseconds): the solver's own rule is what stopped it.
  const auto counted = run_luz({"render", cornell(), "--model", "radiosity", "--out", (dir / "c.png").string(),
                                "--size", "32x32", "--form-factors", "hemicube", "--hemicube-res", "512",
                                "--shots", "1", "--time", "0.001", "--csv", (dir / "c.csv").string()});
  ASSERT_EQ(counted.exit_code, 0) << counted.output;
  EXPECT_TRUE(contains(counted.output, " 1 shots")) << counted.output;
  EXPECT_GE(last_shot(dir / "c.csv").second, 0.001) << "the shot outlasted the time";
  EXPECT_FALSE(contains(counted.output, "stopped by --time")) << counted.output;
}

// A mesh beyond the element budget is refused from its count, naming the numbers, before any
// memory is taken (1 nm patches on the Cornell box would be 1e20 elements).
TEST(RadiosityCli, AMeshBeyondTheElementBudgetIsBadInput) {
  test::ScratchDir dir;
  for (const char* model : {"radiosity", "hybrid"}) {
    const auto result = run_luz({"render", cornell(), "--model", model, "--out",
                                 (dir / "a.png").string(), "--patch-size", "1e-9"});
    EXPECT_EQ(result.exit_code, 1) << model << ": " << result.output;
    EXPECT_TRUE(contains(result.output, "budget")) << result.output;
    EXPECT_TRUE(contains(result.output, "1e-09")) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
  }
}

// Khronos's Box, BoxInterleaved and BoxTextured leave metallicFactor out, so glTF reads them as
// metals (kd = 0): radiosity, diffuse only, draws them black, and must say so and what to change.
// The node hierarchy, the default lights and the patches are not the cause: the same file with
// metallicFactor 0 gives radiosity's picture of the box as Whitted's tracer draws it (a convex box
// has no interreflection; both filter 16 samples per pixel, so what differs is the edges' pixels
// and the vertex interpolation: 1.5% measured).
TEST(RadiosityCli, AMetalByOmissionIsNamedAndADiffuseBoxUnderARotatedRootIsLit) {
  test::ScratchDir dir;
  const auto metal = khronos_box(dir, "metal.gltf", {{"baseColorFactor", {0.8, 0.0, 0.0, 1.0}}});
  const auto said = run_luz({"render", metal.string(), "--model", "radiosity", "--out",
                             (dir / "metal.png").string(), "--size", "40x30"});
  ASSERT_EQ(said.exit_code, 0) << said.output;
  EXPECT_TRUE(contains(said.output, "radiosity: material \"Red\" is a metal")) << said.output;
  EXPECT_TRUE(contains(said.output, "metallicFactor 0")) << said.output;

  const auto diffuse =
      khronos_box(dir, "diffuse.gltf", {{"baseColorFactor", {0.8, 0.0, 0.0, 1.0}}, {"metallicFactor", 0.0}});
  std::string output;
  for (const char* model : {"radiosity", "whitted"}) {
    std::vector<std::string> args = {"render", diffuse.string(), "--model", model, "--out",
                                     (dir / (std::string(model) + ".exr")).string(), "--size", "80x60"};
    if (std::string(model) == "whitted") args.insert(args.end(), {"--spp", "16"});
    const auto result = run_luz(args);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    output += result.output;
  }
  EXPECT_FALSE(contains(output, "is a metal")) << output;
  EXPECT_LT(compared(dir / "radiosity.exr", dir / "whitted.exr"), 0.03);
}

// A sun (a directional light, Blender's sun) lights radiosity and the hybrid as parallel light:
// after its one shot (--shots 1: direct light only) radiosity's picture of a block on a floor,
// sun from the side, is Whitted's direct light, shadow included, up to the mesh's resolution of
// the shadow's edges.
TEST(RadiosityCli, ASunLightsRadiosityAsWhittedsDirectLight) {
  test::ScratchDir dir;
  test::GltfBuilder b;
  const int grey = b.material({{"name", "grey"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.6, 0.6, 1.0}},
                                                                           {"metallicFactor", 0.0}}}});
  test::Primitive floor;
  floor.positions = {{-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}};
  floor.indices = {0, 1, 2, 0, 2, 3};
  floor.material = grey;
  b.node({{"mesh", b.mesh({floor}, "floor")}});
  b.node({{"mesh", b.mesh({box(grey)}, "block")}, {"translation", {0.0, 0.5, 0.0}}});
  // The sun travels along the node's -Z: turned 50 degrees down from the horizontal, toward -X.
  const int light = b.light({{"type", "directional"}, {"intensity", 3.0}, {"name", "sun"}});
  b.node({{"rotation", {-0.2988, 0.6409, 0.2988, 0.6409}},  // -Z to (-0.64, -0.77, 0)
          {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
  const int camera = b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.05}}}});
  b.node({{"camera", camera}, {"translation", {0.0, 4.0, 4.0}}, {"rotation", {-0.3827, 0.0, 0.0, 0.9239}}});
  const auto scene = b.write_gltf(dir, "sun.gltf");

  const auto radiosity = run_luz({"render", scene.string(), "--model", "radiosity", "--shots", "1", "--out",
                                  (dir / "radiosity.exr").string(), "--size", "96x72"});
  ASSERT_EQ(radiosity.exit_code, 0) << radiosity.output;
  EXPECT_FALSE(contains(radiosity.output, "not shot")) << radiosity.output;
  const auto whitted = run_luz({"render", scene.string(), "--model", "whitted", "--spp", "16", "--out",
                                (dir / "whitted.exr").string(), "--size", "96x72"});
  ASSERT_EQ(whitted.exit_code, 0) << whitted.output;
  const double error = compared(dir / "radiosity.exr", dir / "whitted.exr");
  printf("sun: radiosity against Whitted, mean relative error %.4f\n", error);
  EXPECT_LT(error, 0.05);
}

}  // namespace
}  // namespace luz
