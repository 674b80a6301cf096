// `luz render --model path` and `luz compare` as a user runs them: flags, exit codes (2 usage,
// 1 bad input), the mean and --error-out images, determinism for a seed, compare's figures and
// heat map.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/image.h"
#include "io/image_io.h"
#include "support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;
using test::run_luz;

std::string cornell() { return (test::scene_dir() / "cornell_box.gltf").string(); }
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(PathCli, HelpListsThePathFlagsAndCompare) {
  const auto help = run_luz({"render", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag : {"path", "--seed", "--time", "--error-out", "--spp", "--depth"})
    EXPECT_TRUE(contains(help.output, flag)) << flag;
  const auto compare = run_luz({"compare", "--help"});
  EXPECT_EQ(compare.exit_code, 0);
  for (const char* flag : {"--heatmap", "--mask-emitters"}) EXPECT_TRUE(contains(compare.output, flag)) << flag;
}

// The path tracer's rows come after the Whitted tracer's flags whose --spp and --depth they share
// and before --time, which it shares with radiosity, whose flags follow.
TEST(PathCli, HelpListsThePathFlagsBesideTheTracers) {
  const auto help = run_luz({"render", "--help"});
  ASSERT_EQ(help.exit_code, 0);
  size_t before = 0;
  for (const char* flag : {"--spp", "--ray-tree", "--seed", "--error-out", "--time", "--shots", "--csv"}) {
    const size_t at = help.output.find(std::string("  ") + flag + " ");
    ASSERT_NE(at, std::string::npos) << flag;
    EXPECT_GT(at, before) << flag << " is out of order:\n" << help.output;
    before = at;
  }
}

TEST(PathCli, UsageErrorsNameTheFlag) {
  test::ScratchDir dir;
  const std::string out = (dir / "x.exr").string();
  const auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"render", cornell(), "--size", "8x6", "--out", out};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_luz(args);
  };
  for (const std::vector<std::string>& flag : std::vector<std::vector<std::string>>{
           {"--seed", "3"}, {"--time", "1"}, {"--error-out", (dir / "e.exr").string()}}) {
    std::vector<std::string> args = {"--model", "whitted"};
    args.insert(args.end(), flag.begin(), flag.end());
    const auto result = run(args);
    EXPECT_EQ(result.exit_code, 2) << flag[0];
    EXPECT_TRUE(contains(result.output, flag[0]) && contains(result.output, "path")) << result.output;
  }
  // Whitted's own flags other than --spp and --depth are not the path tracer's.
  const auto fresnel = run({"--model", "path", "--fresnel"});
  EXPECT_EQ(fresnel.exit_code, 2);
  EXPECT_TRUE(contains(fresnel.output, "--fresnel")) << fresnel.output;
  EXPECT_EQ(run({"--model", "path", "--error-out", (dir / "e.png").string()}).exit_code, 2);
  EXPECT_EQ(run({"--model", "path", "--spp", "0"}).exit_code, 2);
  EXPECT_EQ(run({"--model", "path", "--time", "-1"}).exit_code, 2);
  EXPECT_EQ(run({"--model", "whitted", "--spp", "3"}).exit_code, 2);  // Whitted still needs a square
  EXPECT_TRUE(fs::is_empty(dir.path));
}

TEST(PathCli, RendersTheMeanAndTheStandardError) {
  test::ScratchDir dir;
  const fs::path out = dir / "p.exr", error = dir / "e.exr";
  // A number of samples that is not a square: the path tracer takes any.
  const auto result = run_luz({"render", cornell(), "--model", "path", "--size", "40x30", "--spp", "5",
                               "--depth", "4", "--out", out.string(), "--error-out", error.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* part : {"5 spp", "depth 4", "samples/s", "e.exr"})
    EXPECT_TRUE(contains(result.output, part)) << part << " in " << result.output;
  EXPECT_FALSE(contains(result.output, "path [")) << "no progress bar when stderr is not a terminal";
  const Image mean = io::read_image(out), se = io::read_image(error);
  ASSERT_EQ(mean.width, 40);
  ASSERT_EQ(se.width, 40);
  ASSERT_EQ(se.height, 30);
  double lit = 0.0, noise = 0.0;
  for (size_t i = 0; i < mean.pixels.size(); ++i) {
    EXPECT_TRUE(is_finite(mean.pixels[i]));
    EXPECT_GE(se.pixels[i].g, 0.0f);
    lit += mean.pixels[i].g;
    noise += se.pixels[i].g;
  }
  EXPECT_GT(lit, 0.0);
  EXPECT_GT(noise, 0.0);  // 5 samples of a Cornell box are noisy, and the error image says so
}

TEST(PathCli, SameSeedSameFileAndMoreTimeLessNoise) {
  test::ScratchDir dir;
  const auto render = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = {"render", cornell(), "--model", "path", "--size", "24x18", "-q",
                                     "--out", (dir / (name + ".exr")).string(),
                                     "--error-out", (dir / (name + "_e.exr")).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    EXPECT_EQ(run_luz(args).exit_code, 0);
    return std::pair{io::read_image(dir / (name + ".exr")), io::read_image(dir / (name + "_e.exr"))};
  };
  const auto a = render("a", {"--spp", "4", "--seed", "9"});
  const auto b = render("b", {"--spp", "4", "--seed", "9"});
  const auto c = render("c", {"--spp", "4", "--seed", "10"});
  EXPECT_EQ(a.first.pixels, b.first.pixels);
  EXPECT_NE(a.first.pixels, c.first.pixels);
  // --time with --spp as the cap: passes until either is reached; 64 samples in 60 s here.
  const auto timed = render("t", {"--spp", "64", "--time", "60"});
  // A time shorter than one pass still renders one.
  const auto instant = render("i", {"--time", "0.001"});
  double lit = 0.0;
  for (const Rgb& pixel : instant.first.pixels) lit += pixel.g;
  EXPECT_GT(lit, 0.0);
  double noise_a = 0.0, noise_t = 0.0;
  for (size_t i = 0; i < a.second.pixels.size(); ++i) {
    noise_a += a.second.pixels[i].g;
    noise_t += timed.second.pixels[i].g;
  }
  EXPECT_LT(noise_t, 0.5 * noise_a);  // 16x the samples: about a quarter of the error
}

TEST(CompareCli, PrintsTheFiguresAndWritesAHeatMap) {
  test::ScratchDir dir;
  Image reference(20, 10, Rgb(0.5f)), brighter(20, 10, Rgb(0.55f));
  reference.at(3, 3) = Rgb(50.0f);  // an emitter
  brighter.at(3, 3) = Rgb(50.0f);
  io::write_image(reference, dir / "b.exr", 0.0f);
  io::write_image(brighter, dir / "a.exr", 0.0f);
  const auto result = run_luz({"compare", (dir / "a.exr").string(), (dir / "b.exr").string(),
                               "--heatmap", (dir / "h.png").string(), "--mask-emitters"});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* part : {"mean error", "R +0.05", "rel-RMSE", "mean relative error over lit pixels",
                           "10.00%", "emitter pixels left out: 9", "h.png"})
    EXPECT_TRUE(contains(result.output, part)) << part << " in " << result.output;
  const Image heatmap = io::read_image(dir / "h.png");
  EXPECT_EQ(heatmap.width, 20);
  EXPECT_GT(heatmap.height, 10);  // the legend below the picture
  // A brighter than B everywhere: red (more red than blue) in the picture's lit part.
  EXPECT_GT(heatmap.at(15, 8).r, heatmap.at(15, 8).b);
}

TEST(CompareCli, BadInputNamesTheFile) {
  test::ScratchDir dir;
  io::write_image(Image(20, 10, Rgb(0.5f)), dir / "a.exr", 0.0f);
  io::write_image(Image(21, 10, Rgb(0.5f)), dir / "b.exr", 0.0f);
  const auto sizes = run_luz({"compare", (dir / "a.exr").string(), (dir / "b.exr").string()});
  EXPECT_EQ(sizes.exit_code, 1);
  EXPECT_TRUE(contains(sizes.output, "a.exr") && contains(sizes.output, "20x10")) << sizes.output;
  const auto text = run_luz({"compare", (dir / "a.exr").string(), cornell()});
  EXPECT_EQ(text.exit_code, 1);
  EXPECT_TRUE(contains(text.output, "cornell_box.gltf") && contains(text.output, "not an image")) << text.output;
  const auto missing = run_luz({"compare", (dir / "nothing.exr").string(), (dir / "a.exr").string()});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_TRUE(contains(missing.output, "nothing.exr")) << missing.output;
  EXPECT_EQ(run_luz({"compare", (dir / "a.exr").string()}).exit_code, 2);  // B missing: usage
  EXPECT_EQ(run_luz({"compare", (dir / "a.exr").string(), (dir / "a.exr").string(), "--heatmap",
                     (dir / "h.exr").string()}).exit_code, 2);
}

}  // namespace
}  // namespace luz
