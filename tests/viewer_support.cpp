#include "viewer_support.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>

#include "core/image.h"
#include "io/image_io.h"

namespace luz::test {

Codes codes(const std::filesystem::path& png) {
  const Image image = io::read_image(png);  // decoded to linear; encode back to the codes
  Codes out{image.width, image.height, {}};
  out.values.reserve(image.pixels.size() * 3);
  for (const Rgb& p : image.pixels)
    for (int c = 0; c < 3; ++c) out.values.push_back(int(std::lround(255.0f * srgb_encode(p[c]))));
  return out;
}

nlohmann::json json_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

double share_moved(const Codes& a, const Codes& b, int by) {
  EXPECT_EQ(a.values.size(), b.values.size());
  size_t moved = 0;
  for (size_t i = 0; i < a.values.size() && i < b.values.size(); ++i) moved += std::abs(a.values[i] - b.values[i]) > by;
  return double(moved) / double(a.values.size());
}

void expect_same_picture(const Codes& a, const Codes& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  double total = 0;
  size_t within = 0;
  for (size_t i = 0; i < a.values.size(); ++i) {
    const int difference = std::abs(a.values[i] - b.values[i]);
    total += difference;
    within += difference <= 2;
  }
  const double n = double(a.values.size());
  EXPECT_LE(total / n, 0.5) << "mean difference in 8-bit codes";
  EXPECT_GE(double(within) / n, 0.995) << "share of values within 2 codes";
}

void expect_rays_of_render(const nlohmann::json& trace, const std::string& render_output) {
  std::smatch rays;
  ASSERT_TRUE(std::regex_search(render_output, rays,
                                std::regex(R"(rays: (\d+) primary, (\d+) shadow, (\d+) reflected, (\d+) transmitted)")))
      << render_output;
  const char* kinds[] = {"primary", "shadow", "reflected", "transmitted"};
  for (size_t k = 0; k < 4; ++k)
    EXPECT_EQ(trace["rays"][kinds[k]].get<long>(), std::stol(rays[k + 1])) << kinds[k] << " rays; " << render_output;
}

void require_scripted_run(const std::filesystem::path& run_dir, const std::string& script_test) {
  if (std::filesystem::exists(run_dir / "done")) return;
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "xvfb-run is missing: the viewer cannot be run headless";
  FAIL() << "the scripted viewer did not finish in " << run_dir << " (see the " << script_test << " test)";
}

}  // namespace luz::test
