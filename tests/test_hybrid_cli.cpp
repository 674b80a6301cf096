// `luz render --model hybrid` and `luz solvers` as a user calls them: which flags each takes,
// usage errors (exit 2), bad input (exit 1), the CSV's columns and the plot.
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/image.h"
#include "core/image_compare.h"
#include "io/image_io.h"
#include "support.h"

namespace luz {
namespace {

using test::run_luz;

std::string scene(const std::string& name) { return (test::scene_dir() / (name + ".gltf")).string(); }
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Quick settings: a coarse mesh, a small hemicube, a loose stopping rule.
const std::vector<std::string> kCoarse = {"--patch-size", "0.2", "--hemicube-res", "64", "--converge", "0.05"};

TEST(HybridCli, TakesTheWhittedAndTheRadiosityFlagsAndWritesTheRayTree) {
  test::ScratchDir dir;
  std::vector<std::string> args = {"render", scene("cornell_spheres"), "--model", "hybrid", "--size", "40x40",
                                   "--depth", "3", "--fresnel", "--light-samples", "2", "--ray-tree", "20,20",
                                   "--csv", (dir / "shots.csv").string(), "--out", (dir / "h.png").string()};
  args.insert(args.end(), kCoarse.begin(), kCoarse.end());
  const auto result = run_luz(args);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "h.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "h.ray-tree.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "shots.csv"));
  EXPECT_TRUE(contains(result.output, "radiosity:")) << "the solve's summary";
  EXPECT_TRUE(contains(result.output, "rays:")) << "the tracer's counters";
}

TEST(HybridCli, TheRadiosityPicturesDisplaySwitchesAreUsageErrors) {
  test::ScratchDir dir;
  for (const char* flag : {"--flat-patches", "--outlines"}) {
    const auto result = run_luz({"render", scene("cornell_box"), "--model", "hybrid", flag, "--out",
                                 (dir / "h.png").string()});
    EXPECT_EQ(result.exit_code, 2) << flag;
    EXPECT_TRUE(contains(result.output, flag)) << result.output;
  }
  // And the tracer's flags remain usage errors with the radiosity model.
  const auto result = run_luz({"render", scene("cornell_box"), "--model", "radiosity", "--depth", "2",
                               "--out", (dir / "r.png").string()});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(contains(result.output, "only with --model whitted, hybrid or path")) << result.output;
}

// The term switches go where the model has the term. Radiosity has no lights' terms to switch;
// in the hybrid its solution holds the emitted light and stands for the ambient term, so those
// two switches are usage errors there. Both take --no-textures: the patches then reflect kd alone.
TEST(HybridCli, TheTermSwitchesAreTakenWhereTheModelHasTheTerm) {
  test::ScratchDir dir;
  const auto refused = [&](const char* model, const char* flag, const char* takers) {
    const auto result = run_luz({"render", scene("cornell_box"), "--model", model, flag, "--out",
                                 (dir / "refused.png").string()});
    EXPECT_EQ(result.exit_code, 2) << model << " " << flag;
    EXPECT_TRUE(contains(result.output, std::string(flag) + ": only with --model " + takers)) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "refused.png"));
  };
  for (const char* flag : {"--no-diffuse", "--no-specular", "--blinn"})
    refused("radiosity", flag, "flat, gouraud, phong, whitted or hybrid");
  for (const char* flag : {"--no-ambient", "--no-emission"}) {
    refused("radiosity", flag, "flat, gouraud, phong or whitted");
    refused("hybrid", flag, "flat, gouraud, phong or whitted");
  }

  const std::filesystem::path textured = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";
  if (!std::filesystem::exists(textured)) GTEST_SKIP() << textured << " is absent (Debian package assimp-testmodels)";
  for (const char* model : {"radiosity", "hybrid"}) {
    const auto picture = [&](bool textures) {
      const std::filesystem::path out = dir / (std::string(model) + (textures ? "-textured.exr" : "-plain.exr"));
      std::vector<std::string> args = {"render", textured.string(), "--model", model, "--size", "48x48",
                                       "--out", out.string(), "-q"};
      args.insert(args.end(), kCoarse.begin(), kCoarse.end());
      if (!textures) args.push_back("--no-textures");
      const auto result = run_luz(args);
      EXPECT_EQ(result.exit_code, 0) << result.output;
      return io::read_image(out);
    };
    // The box is kd 1 with the texture's mean texel well below 1: without it, every lit pixel of
    // the box is brighter, and none shows the texture's dark print.
    const Image with = picture(true), without = picture(false);
    ASSERT_EQ(with.pixels.size(), without.pixels.size());
    double sum_with = 0.0, sum_without = 0.0;
    for (size_t i = 0; i < with.pixels.size(); ++i) {
      sum_with += rec709_luminance(with.pixels[i]);
      sum_without += rec709_luminance(without.pixels[i]);
    }
    EXPECT_GT(sum_without, 1.2 * sum_with) << model;
  }
}

TEST(SolversCli, WritesTheCurvesOfTheFourMethodsAndTheirPlot) {
  test::ScratchDir dir;
  const auto result = run_luz({"solvers", scene("cornell_box"), "--patches", "150", "--iterations", "4",
                               "--csv", (dir / "curves.csv").string(), "--png", (dir / "curves.png").string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream csv(dir / "curves.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "method,iteration,rows,seconds,residual,error");
  std::set<std::string> methods;
  for (std::string line; std::getline(csv, line);) {
    std::stringstream fields(line);
    std::string method;
    std::getline(fields, method, ',');
    methods.insert(method);
    int commas = 0;
    for (const char c : line) commas += c == ',';
    EXPECT_EQ(commas, 5) << line;
  }
  EXPECT_EQ(methods, (std::set<std::string>{"jacobi", "gauss-seidel", "southwell", "shooting"}));
  const Image plot = io::read_image(dir / "curves.png");
  EXPECT_GT(plot.width, 600);
  EXPECT_GT(plot.height, 300);
}

TEST(SolversCli, BadArgumentsAreUsageErrors) {
  test::ScratchDir dir;
  const std::string csv = (dir / "c.csv").string();
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"solvers", scene("cornell_box")},                                        // no --csv
           {"solvers", scene("cornell_box"), "--csv", csv, "--iterations", "0"},
           {"solvers", scene("cornell_box"), "--csv", csv, "--hemicube-res", "63"},
           {"solvers", scene("cornell_box"), "--csv", csv, "--patches", "100", "--patch-size", "0.1"},
           {"solvers", scene("cornell_box"), "--csv", csv, "--png", (dir / "p.jpg").string()}}) {
    const auto result = run_luz(args);
    EXPECT_EQ(result.exit_code, 2) << args.back() << ": " << result.output;
  }
  EXPECT_FALSE(std::filesystem::exists(csv));
}

TEST(SolversCli, TooManyPatchesForAFullMatrixIsBadInput) {
  test::ScratchDir dir;
  const auto result = run_luz({"solvers", scene("cornell_box"), "--patches", "6000", "--csv",
                               (dir / "c.csv").string()});
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_TRUE(contains(result.output, "at most 5000")) << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "c.csv"));
}

TEST(SolversCli, AMissingSceneIsBadInput) {
  test::ScratchDir dir;
  const auto result = run_luz({"solvers", (dir / "nope.gltf").string(), "--csv", (dir / "c.csv").string()});
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_TRUE(contains(result.output, "nope.gltf")) << result.output;
}

}  // namespace
}  // namespace luz
