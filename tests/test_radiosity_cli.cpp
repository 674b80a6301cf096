// `luz render --model radiosity` as a user calls it: its flags, their usage errors (exit 2),
// the residual history in CSV, and `luz bench radiosity`'s table.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "support.h"

namespace luz {
namespace {

using test::run_luz;

std::string cornell() { return (test::scene_dir() / "cornell_box.gltf").string(); }
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

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

}  // namespace
}  // namespace luz
