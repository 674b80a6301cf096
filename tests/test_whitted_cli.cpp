// `luz render --model whitted` and `luz bench whitted` as a user runs them: flags, usage errors
// (exit 2), the counters, the ray tree JSON beside the image.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "io/image_io.h"
#include "support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;
using test::run_luz;

std::string whitted() { return (test::scene_dir() / "whitted.gltf").string(); }
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(WhittedCli, HelpListsTheTracersFlags) {
  const auto help = run_luz({"render", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag : {"whitted", "--depth", "--spp", "--adaptive", "--fresnel", "--light-samples",
                           "--brute-force", "--no-shadows", "--ray-tree", "ray-tree.json"})
    EXPECT_TRUE(contains(help.output, flag)) << flag;
  EXPECT_EQ(run_luz({"bench", "whitted", "--help"}).exit_code, 0);
}

TEST(WhittedCli, TracerFlagsWithAnotherModelAreUsageErrors) {
  test::ScratchDir dir;
  const std::string out = (dir / "x.png").string();
  for (const std::vector<std::string>& flag : std::vector<std::vector<std::string>>{
           {"--depth", "3"}, {"--spp", "4"}, {"--adaptive"}, {"--fresnel"}, {"--light-samples", "4"},
           {"--brute-force"}, {"--no-shadows"}, {"--ray-tree", "1,1"}}) {
    std::vector<std::string> args = {"render", whitted(), "--model", "phong", "--out", out};
    args.insert(args.end(), flag.begin(), flag.end());
    const auto result = run_luz(args);
    EXPECT_EQ(result.exit_code, 2) << flag[0];
    EXPECT_TRUE(contains(result.output, flag[0])) << result.output;
  }
  const auto bad = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"render", whitted(), "--model", "whitted", "--size", "16x12", "--out", out};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_luz(args).exit_code;
  };
  EXPECT_EQ(bad({"--spp", "3"}), 2);  // not a square
  EXPECT_EQ(bad({"--depth", "-1"}), 2);
  EXPECT_EQ(bad({"--light-samples", "0"}), 2);
  EXPECT_EQ(bad({"--ray-tree", "16,0"}), 2);  // outside the 16x12 image
  EXPECT_EQ(bad({"--ray-tree", "a,b"}), 2);
  EXPECT_TRUE(fs::is_empty(dir.path));
}

// --renderer chooses how the rays are traced, not what they make: both pictures are the same
// (test_whitted_streams holds them to 1e-6; an EXR keeps the floats), and the bench names its renderer.
TEST(WhittedCli, BothRenderersMakeThePictureAndTheBenchSaysWhichRan) {
  test::ScratchDir dir;
  std::vector<Image> pictures;
  for (const char* renderer : {"wavefront", "recursive"}) {
    const fs::path out = dir / (std::string(renderer) + ".exr");
    const auto result = run_luz({"render", whitted(), "--model", "whitted", "--size", "40x30", "--fresnel",
                                 "--renderer", renderer, "--out", out.string(), "-q"});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    pictures.push_back(io::read_image(out));
  }
  float worst = 0.0f;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(pictures[0].at(x, y)[c] - pictures[1].at(x, y)[c]) /
                                    std::max(1.0f, std::abs(pictures[1].at(x, y)[c])));
  EXPECT_LE(worst, 1e-6f);
  const auto wrong = run_luz({"render", whitted(), "--model", "whitted", "--renderer", "breadth",
                              "--out", (dir / "x.png").string()});
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_TRUE(contains(wrong.output, "--renderer")) << wrong.output;
  EXPECT_EQ(run_luz({"render", whitted(), "--model", "phong", "--renderer", "recursive", "--out",
                     (dir / "x.png").string()}).exit_code, 2);  // a tracer's flag with another model

  const auto bench = run_luz({"bench", "whitted", "--size", "8x6", "--repeats", "1", "--depth", "1",
                              "--scenes", "whitted", "--renderer", "recursive"});
  ASSERT_EQ(bench.exit_code, 0) << bench.output;
  EXPECT_TRUE(contains(bench.output, "renderer: recursive")) << bench.output;
  EXPECT_EQ(run_luz({"bench", "whitted", "--renderer", "breadth"}).exit_code, 2);
}

TEST(WhittedCli, RendersPrintsTheCountersAndWritesTheRayTree) {
  test::ScratchDir dir;
  const fs::path out = dir / "w.exr";
  const auto result = run_luz({"render", whitted(), "--model", "whitted", "--size", "80x60", "--depth", "4",
                               "--spp", "4", "--fresnel", "--ray-tree", "28,24", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* part : {"primary", "shadow", "reflected", "transmitted", "Mrays/s", "w.ray-tree.json"})
    EXPECT_TRUE(contains(result.output, part)) << part << " in " << result.output;
  EXPECT_FALSE(contains(result.output, "whitted [")) << "no progress bar when stderr is not a terminal";
  const Image image = io::read_image(out);
  EXPECT_EQ(image.width, 80);

  // Pixel (28, 24) looks at the glass sphere: a primary ray per sample, each with a transmitted
  // child, depths within --depth, and contributions that add up to the pixel.
  std::ifstream file(dir / "w.ray-tree.json");
  ASSERT_TRUE(file.good());
  const nlohmann::json tree = nlohmann::json::parse(file);
  EXPECT_EQ(tree["pixel"], nlohmann::json::array({28, 24}));
  int primaries = 0, transmitted = 0;
  double sum = 0.0;
  for (const auto& node : tree["nodes"]) {
    EXPECT_LE(node["depth"].get<int>(), 4);
    for (const char* key : {"id", "parent", "kind", "origin", "direction", "weight", "radiance", "contribution"})
      EXPECT_TRUE(node.contains(key)) << key;
    if (node["kind"] == "primary") {
      ++primaries;
      sum += node["contribution"][1].get<double>();
      EXPECT_EQ(node["hit"]["mesh"], "glass_sphere");
    }
    transmitted += node["kind"] == "transmitted";
  }
  EXPECT_EQ(primaries, 4);
  EXPECT_GT(transmitted, 4);
  EXPECT_NEAR(sum, tree["radiance"][1].get<double>(), 1e-5);
  EXPECT_NEAR(sum, image.at(28, 24).g, 1e-4);

  // -q prints nothing.
  const auto quiet = run_luz({"render", whitted(), "--model", "whitted", "--size", "8x6", "-q",
                              "--out", (dir / "q.png").string()});
  EXPECT_EQ(quiet.exit_code, 0);
  EXPECT_EQ(quiet.output, "");
}

// The bench traces what it says: its --spp is validated as luz render's (a square, else the
// stratified grid would trace fewer samples than the header announces).
TEST(WhittedCli, BenchRefusesASampleCountThatIsNotASquare) {
  for (const char* spp : {"3", "0", "8", "4097", "x"}) {
    const auto result = run_luz({"bench", "whitted", "--size", "8x6", "--repeats", "1", "--spp", spp,
                                 "--scenes", "whitted"});
    EXPECT_EQ(result.exit_code, 2) << spp << ": " << result.output;
    EXPECT_TRUE(contains(result.output, "--spp")) << result.output;
    EXPECT_FALSE(contains(result.output, "ratio")) << "nothing benchmarked";
  }
  const auto four = run_luz({"bench", "whitted", "--size", "8x6", "--repeats", "1", "--spp", "4",
                             "--depth", "1", "--scenes", "whitted"});
  ASSERT_EQ(four.exit_code, 0) << four.output;
  EXPECT_TRUE(contains(four.output, "4 spp")) << four.output;
  // At depth 1 every traced ray but the shadow rays is primary: 8 x 6 pixels x 4 samples.
  EXPECT_TRUE(std::regex_search(four.output, std::regex("primary +192 rays"))) << four.output;
}

TEST(WhittedCli, BenchPrintsTheRatioToBareEmbree) {
  const auto result = run_luz({"bench", "whitted", "--size", "64x48", "--repeats", "1", "--scenes", "whitted"});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* part : {"whitted", "ratio", "bare", "primary", "shadow", "reflected", "transmitted"})
    EXPECT_TRUE(contains(result.output, part)) << part << " in " << result.output;
}

}  // namespace
}  // namespace luz
