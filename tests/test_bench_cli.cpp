// `luz bench local` as a user runs it: a row per scene, shading and effect, each row's figures
// consistent with each other (fps from the median, the ratio from the two medians), and bad input
// refused before any table is printed, as `luz bench whitted` refuses a bad --scenes too. Timings
// themselves are never asserted.
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support.h"

namespace luz {
namespace {

using test::run_luz;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The whitespace-separated cells of the lines that start with `scene`, bars left out.
std::vector<std::vector<std::string>> rows_of(const std::string& output, const std::string& scene) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind(scene + " ", 0) != 0) continue;
    std::istringstream words(line);
    std::vector<std::string> cells;
    for (std::string word; words >> word;)
      if (word != "|") cells.push_back(word);
    rows.push_back(cells);
  }
  return rows;
}

TEST(BenchLocalCli, PrintsARowPerShadingAndEffectWithItsRatioToTheBareTriangles) {
  const auto result = run_luz({"bench", "local", "--scenes", "cornell_box", "--shadings", "flat,phong",
                               "--effects", "none,shadows", "--frames", "3", "--size", "640x360"});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "luz bench local: 640x360, 3 frames a row")) << result.output;
  const auto rows = rows_of(result.output, "cornell_box");
  ASSERT_EQ(rows.size(), 4u) << result.output;
  const char* const expected[4][2] = {{"flat", "none"}, {"flat", "shadows"}, {"phong", "none"}, {"phong", "shadows"}};
  for (size_t r = 0; r < rows.size(); ++r) {
    const auto& row = rows[r];
    ASSERT_EQ(row.size(), 9u) << result.output;  // scene shading effect best median fps | bare best median | ratio
    EXPECT_EQ(row[1], expected[r][0]);
    EXPECT_EQ(row[2], expected[r][1]);
    const double best = std::stod(row[3]), median = std::stod(row[4]), fps = std::stod(row[5]);
    const double bare_best = std::stod(row[6]), bare_median = std::stod(row[7]), ratio = std::stod(row[8]);
    EXPECT_LE(best, median + 1e-9) << result.output;
    EXPECT_LE(bare_best, bare_median + 1e-9) << result.output;
    // The figures are printed to 0.1: each derived one within what that rounding allows.
    if (median > 0.05) {
      EXPECT_GE(fps, 1000.0 / (median + 0.05) - 0.05) << result.output;
      EXPECT_LE(fps, 1000.0 / (median - 0.05) + 0.05) << result.output;
    }
    if (bare_median > 0.05) {
      EXPECT_GE(ratio, (median - 0.05) / (bare_median + 0.05) - 0.05) << result.output;
      EXPECT_LE(ratio, (median + 0.05) / (bare_median - 0.05) + 0.05) << result.output;
    }
  }
  // One bare limit per scene, in every row.
  for (const auto& row : rows) EXPECT_EQ(row[7], rows[0][7]) << result.output;
}

TEST(BenchLocalCli, RefusesBadInputBeforeItPrintsATable) {
  const std::vector<std::vector<std::string>> usage = {
      {"--shadings", "toon"}, {"--effects", "bloom"}, {"--frames", "0"}, {"--size", "wide"},
      {"--scenes", "no_such_scene"}};
  for (const auto& flag : usage) {
    std::vector<std::string> args = {"bench", "local", "--frames", "1", "--size", "32x18"};
    args.insert(args.end(), flag.begin(), flag.end());
    const auto result = run_luz(args);
    EXPECT_EQ(result.exit_code, 2) << flag[0] << " " << flag[1] << ": " << result.output;
    EXPECT_TRUE(contains(result.output, flag[0])) << result.output;
    EXPECT_FALSE(contains(result.output, "luz bench local:")) << "nothing benchmarked: " << result.output;
  }
  // An unknown scene name lists the shipped ones; a path that is not there is bad input (exit 1)
  // naming it. A bad scene after a good one still stops the bench before its first row.
  const auto unknown = run_luz({"bench", "local", "--scenes", "cornell_box,no_such_scene", "--frames", "1"});
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_TRUE(contains(unknown.output, "no_such_scene") && contains(unknown.output, "cornell_box, cornell_spheres"))
      << unknown.output;
  EXPECT_TRUE(rows_of(unknown.output, "cornell_box").empty()) << unknown.output;
  test::ScratchDir dir;
  const std::string missing = (dir / "missing.gltf").string();
  const auto absent = run_luz({"bench", "local", "--scenes", missing, "--frames", "1"});
  EXPECT_EQ(absent.exit_code, 1) << absent.output;
  EXPECT_TRUE(contains(absent.output, "missing.gltf")) << absent.output;
}

TEST(BenchWhittedCli, RefusesAnUnknownSceneBeforeItPrintsATable) {
  const auto result = run_luz({"bench", "whitted", "--scenes", "whitted,no_such_scene", "--size", "8x6",
                               "--repeats", "1"});
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_TRUE(contains(result.output, "no_such_scene")) << result.output;
  EXPECT_FALSE(contains(result.output, "luz bench whitted:")) << "nothing benchmarked: " << result.output;
}

}  // namespace
}  // namespace luz
