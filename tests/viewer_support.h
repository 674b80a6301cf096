#pragma once
// What the scripted-viewer tests share: a CTest fixture played a script under Xvfb into a run
// folder; these helpers read its screenshots (as the 8-bit codes the PNG holds) and JSON dumps.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace luz::test {

// An 8-bit sRGB picture, as the PNG holds it.
struct Codes {
  int width = 0, height = 0;
  std::vector<int> values;  // r, g, b per pixel, row 0 at the top
  int at(int x, int y, int c) const { return values[(size_t(y) * size_t(width) + size_t(x)) * 3 + size_t(c)]; }
  std::string size() const { return std::to_string(width) + "x" + std::to_string(height); }
};

Codes codes(const std::filesystem::path& png);
nlohmann::json json_of(const std::filesystem::path& file);

// The share of values that differ by more than `by` codes.
double share_moved(const Codes& a, const Codes& b, int by);

// The same picture from two GL contexts (the window's and OSMesa's): mean difference <= 0.5
// code and 99.5% of the values within 2 codes.
void expect_same_picture(const Codes& a, const Codes& b);

// A trace's rays as the viewer dumped them (`dump-trace`) against those `luz render` printed for
// the same picture ("rays: N primary, N shadow, N reflected, N transmitted"): equal, kind for kind.
void expect_rays_of_render(const nlohmann::json& trace, const std::string& render_output);

// For a fixture's SetUp: skips the test when xvfb-run is missing (setup.sh installs it), fails
// it when the scripted run in `run_dir` did not finish (see the CTest test `script_test`).
void require_scripted_run(const std::filesystem::path& run_dir, const std::string& script_test);

}  // namespace luz::test
