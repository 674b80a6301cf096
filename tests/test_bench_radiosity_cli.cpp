// `luz bench radiosity` as a user runs it: one table row per patch count asked for, each row's
// numbers consistent with each other, and bad values refused (usage: exit 2; a missing scene:
// exit 1 naming it). Timings themselves are never asserted.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support.h"

namespace luz {
namespace {

using test::run_luz;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The cells of the table's data rows: "| rays | 1024 | 310 | ... |" lines whose second cell is a
// number.
std::vector<std::vector<std::string>> table_rows(const std::string& output) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    const size_t second = line.find("| ", 1);
    if (line.size() < 3 || line[0] != '|' || second == std::string::npos || second + 2 >= line.size() ||
        !std::isdigit(static_cast<unsigned char>(line[second + 2])))
      continue;
    std::vector<std::string> cells;
    std::istringstream parts(line.substr(1));
    std::string cell;
    while (std::getline(parts, cell, '|')) {
      const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
      if (a != std::string::npos) cells.push_back(cell.substr(a, b - a + 1));
    }
    rows.push_back(cells);
  }
  return rows;
}

TEST(BenchRadiosityCli, PrintsOneRowPerPatchCount) {
  const auto result = run_luz({"bench", "radiosity", "--patches", "60", "240", "--hemicube-res", "64",
                               "--seconds", "20"});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* part : {"cornell_box", "hemicube 64", "shots/s", "draw ms", "update ms"})
    EXPECT_TRUE(contains(result.output, part)) << part << " in " << result.output;
  // One row per patch count for each form-factor method, rays first, then the hemicube.
  const auto rows = table_rows(result.output);
  ASSERT_EQ(rows.size(), 4u) << result.output;
  // The criterion the header states: "until unshot < C of the emitted power".
  const size_t at = result.output.find("until unshot < ");
  ASSERT_NE(at, std::string::npos) << result.output;
  const double criterion = std::stod(result.output.substr(at + 15));
  const size_t targets[2] = {60, 240};
  for (size_t k = 0; k < rows.size(); ++k) {
    const auto& row = rows[k];
    ASSERT_EQ(row.size(), 10u) << result.output;
    EXPECT_EQ(row[0], k < 2 ? "rays" : "hemicube");
    // The mesh is subdivided to about the patch count asked for (square patches on walls whose
    // sides are not multiples of the patch size: within a factor of 2).
    const double patches = std::stod(row[1]);
    EXPECT_GT(patches, 0.5 * double(targets[k % 2])) << row[1];
    EXPECT_LT(patches, 2.0 * double(targets[k % 2])) << row[1];
    EXPECT_GT(std::stoi(row[2]), 0) << "shots";
    // Converged within the 20 s cap: the time is given, and what is left unshot (in percent,
    // rounded to two decimals) is not above the criterion.
    EXPECT_TRUE(row[8].ends_with(" s")) << row[8];
    EXPECT_LE(std::stod(row[9]), 100.0 * criterion) << row[9];
  }
}

TEST(BenchRadiosityCli, BadValuesAreRefused) {
  for (const std::vector<std::string>& flag : std::vector<std::vector<std::string>>{
           {"--hemicube-res", "3"}, {"--seconds", "0"}, {"--patches", "many"}, {"--bogus"}}) {
    std::vector<std::string> args = {"bench", "radiosity"};
    args.insert(args.end(), flag.begin(), flag.end());
    const auto result = run_luz(args);
    EXPECT_EQ(result.exit_code, 2) << flag[0] << ": " << result.output;
    EXPECT_FALSE(contains(result.output, "shots/s")) << "nothing benchmarked";
  }
  const auto missing = run_luz({"bench", "radiosity", "--scene", "no_such_scene.gltf"});
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_TRUE(contains(missing.output, "no_such_scene.gltf")) << missing.output;
}

}  // namespace
}  // namespace luz
