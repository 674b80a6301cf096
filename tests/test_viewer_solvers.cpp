// Slide 36's window in a real window: tests/viewer/solvers.txt is played on
// scenes/cornell_box.gltf by the `viewer_solvers_script` CTest fixture (Xvfb, Mesa's software GL);
// these tests check the curves it dumped and the plots it drew. Skipped only when xvfb-run is
// missing.
//
// Tolerances: the residuals of Jacobi and Gauss-Seidel never rise from one sweep to the next
// (the system is diagonally dominant, both converge monotonically; 1e-12 relative for rounding);
// "the plot changes": more than 1% of the pixels inside the plots' rectangle move by more than 8
// codes between 20 rows and 1200 rows (the frames, grids and labels stay: only the curves can);
// the window's curves against `luz solvers`'s CSV for the same scene, patches and hemicube: equal
// to the CSV's 9 significant digits (5e-9 relative): the same solvers on the same form factors,
// whose hemicubes both GL contexts (the window's, OSMesa's) rasterise alike.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "io/image_io.h"
#include "support.h"
#include "viewer_support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;

const fs::path run_dir = LUZ_VIEWER_RUN_DIR;  // where the fixture played the script

using test::json_of;

class ViewerSolvers : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
  static fs::path file(const std::string& name) { return run_dir / name; }
};

// The error of a curve's last sample with at most `rows` rows used.
double error_at(const nlohmann::json& curve, size_t rows) {
  double error = 1.0;
  for (const auto& sample : curve)
    if (sample["rows"].get<size_t>() <= rows) error = sample["error"].get<double>();
  return error;
}

TEST_F(ViewerSolvers, AllFourMethodsRunSideBySide) {
  const nlohmann::json start = json_of(file("start.json")), early = json_of(file("early.json")),
                       later = json_of(file("later.json"));
  EXPECT_EQ(start["phase"], "ready");
  EXPECT_EQ(start["rows"], 0);  // opened paused: nothing stepped before `wait-solver-rows`
  EXPECT_EQ(early["rows"], 20);  // `wait-solver-rows 20` pauses at exactly 20, never a step past
  EXPECT_FALSE(early["running"].get<bool>());
  EXPECT_EQ(later["phase"], "ready");
  EXPECT_FALSE(later["running"].get<bool>());
  EXPECT_GT(later["patches"].get<int>(), 300);
  EXPECT_LT(later["patches"].get<int>(), 500);  // about the window's 400
  for (const char* method : {"jacobi", "gauss-seidel", "southwell", "shooting"}) {
    SCOPED_TRACE(method);
    ASSERT_TRUE(later["curves"].contains(method));
    EXPECT_GE(later["curves"][method].back()["rows"].get<size_t>(), 1200u);
  }
}

TEST_F(ViewerSolvers, ShootingShowsAUsablePictureFirst) {
  const nlohmann::json later = json_of(file("later.json"));
  const size_t n = later["patches"].get<size_t>();
  const nlohmann::json& curves = later["curves"];
  // One sweep's worth of rows: Jacobi has just shown its first iterate, the shooting has shot n times.
  const double jacobi = error_at(curves["jacobi"], n), shooting = error_at(curves["shooting"], n);
  EXPECT_LT(shooting, jacobi) << "after " << n << " rows";
}

// What the window plots is what `luz solvers` computes headless for the same settings (its
// defaults are the window's: about 400 patches, hemicube 64): every sample of every curve, at
// the same number of rows, with the same residual and error.
TEST_F(ViewerSolvers, TheCurvesAreLuzSolverssForTheSameSettings) {
  const nlohmann::json later = json_of(file("later.json"));
  const size_t n = later["patches"].get<size_t>();
  test::ScratchDir dir;
  const fs::path csv = dir / "curves.csv";
  const auto result = test::run_luz({"solvers", (test::scene_dir() / "cornell_box.gltf").string(), "--iterations", "4",
                                     "--csv", csv.string(), "-q"});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::map<std::pair<std::string, size_t>, std::pair<double, double>> headless;  // (method, rows) -> residual, error
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string method, iteration, rows, seconds, residual, error;
    std::getline(fields, method, ',');
    std::getline(fields, iteration, ',');
    std::getline(fields, rows, ',');
    std::getline(fields, seconds, ',');
    std::getline(fields, residual, ',');
    std::getline(fields, error, ',');
    headless[{method, std::stoul(rows)}] = {std::stod(residual), std::stod(error)};
  }
  for (const char* method : {"jacobi", "gauss-seidel", "southwell", "shooting"}) {
    SCOPED_TRACE(method);
    const nlohmann::json& curve = later["curves"][method];
    ASSERT_GE(curve.size(), 3u);
    for (const auto& sample : curve) {
      const size_t rows = sample["rows"];
      if (rows > 4 * n) continue;  // past the CSV's four sweeps
      const auto found = headless.find({method, rows});
      ASSERT_NE(found, headless.end()) << "no headless sample at " << rows << " rows";
      const double residual = sample["residual"], error = sample["error"];
      EXPECT_NEAR(residual, found->second.first, 5e-9 * found->second.first) << rows << " rows";
      EXPECT_NEAR(error, found->second.second, 5e-9 * found->second.second) << rows << " rows";
    }
  }
}

TEST_F(ViewerSolvers, JacobiAndGaussSeidelResidualsNeverRise) {
  const nlohmann::json later = json_of(file("later.json"));
  for (const char* method : {"jacobi", "gauss-seidel"}) {
    SCOPED_TRACE(method);
    const nlohmann::json& curve = later["curves"][method];
    ASSERT_GE(curve.size(), 3u);
    for (size_t i = 1; i < curve.size(); ++i) {
      const double before = curve[i - 1]["residual"], after = curve[i]["residual"];
      EXPECT_LE(after, before * (1.0 + 1e-12)) << "sweep " << i;
    }
  }
}

TEST_F(ViewerSolvers, ThePlotsGrowAsTheyRun) {
  const nlohmann::json later = json_of(file("later.json"));
  const auto& r = later["plot"];
  const float x0 = r[0], y0 = r[1], x1 = r[2], y1 = r[3];
  ASSERT_GT(x1 - x0, 100.0f);
  ASSERT_GT(y1 - y0, 100.0f);
  const Image early = io::read_image(file("early-panel.png")), late = io::read_image(file("later-panel.png"));
  ASSERT_EQ(early.width, late.width);
  ASSERT_GE(early.width, int(x1));
  ASSERT_GE(early.height, int(y1));
  size_t moved = 0, total = 0;
  for (int y = int(y0); y < int(y1); ++y)
    for (int x = int(x0); x < int(x1); ++x, ++total)
      for (int c = 0; c < 3; ++c)
        if (std::abs(255.0f * (srgb_encode(early.at(x, y)[c]) - srgb_encode(late.at(x, y)[c]))) > 8.0f) {
          ++moved;
          break;
        }
  EXPECT_GT(double(moved) / double(total), 0.01);
}

TEST_F(ViewerSolvers, AboveTheLimitItRefusesAndSaysWhy) {
  const nlohmann::json refused = json_of(file("refused.json"));
  EXPECT_EQ(refused["phase"], "refused");
  EXPECT_GT(refused["patches"].get<int>(), 5000);
  EXPECT_NE(refused["message"].get<std::string>().find("at most 5000"), std::string::npos);
  EXPECT_TRUE(refused["curves"].empty());
}

}  // namespace
}  // namespace luz
