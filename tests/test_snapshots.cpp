// Snapshot tests: every shipped scene in every local model, rendered by `luz render` as a user
// would, checked by properties a teacher relies on and against a golden image.
//
// Golden tolerance, in 8-bit sRGB codes of the PNG: mean absolute difference <= 1 code and at
// most 0.5% of the pixels off by more than 16 codes (rasterisation may move a silhouette by a
// pixel between Mesa versions; shading may not change). Goldens are rewritten only by
// `cmake --build build --target update-goldens`.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/image.h"
#include "io/image_io.h"
#include "support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScenes[] = {"cornell_box", "phong_spheres", "whitted"};
constexpr const char* kModels[] = {"flat", "gouraud", "phong"};

Image render(const test::ScratchDir& dir, const std::string& scene, const std::string& model,
             std::vector<std::string> extra = {}) {
  const fs::path out = dir / (scene + "-" + model + ".png");
  std::vector<std::string> args = {"render", (test::scene_dir() / (scene + ".gltf")).string(),
                                   "--model", model, "--size", "160x120", "-q", "--out", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto result = test::run_luz(args);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output, "") << "a shipped scene renders without a warning";
  return io::read_image(out);
}

// The mean colour of a rectangle given in fractions of the image.
Rgb mean_colour(const Image& image, float x0, float y0, float x1, float y1) {
  Rgb sum(0.0f);
  int n = 0;
  for (int y = int(y0 * float(image.height)); y < int(y1 * float(image.height)); ++y)
    for (int x = int(x0 * float(image.width)); x < int(x1 * float(image.width)); ++x, ++n)
      sum += image.at(x, y);
  return sum / float(n);
}

float max_luminance(const Image& image) {
  float best = 0.0f;
  for (const Rgb& p : image.pixels) best = std::max(best, 0.2126f * p.r + 0.7152f * p.g + 0.0722f * p.b);
  return best;
}

class Snapshot : public testing::TestWithParam<std::tuple<const char*, const char*>> {};

TEST_P(Snapshot, MatchesItsGolden) {
  const auto [scene, model] = GetParam();
  test::ScratchDir dir;
  const Image image = render(dir, scene, model);
  const fs::path golden_path = test::test_data_dir() / "golden" / (std::string(scene) + "-" + model + ".png");
  ASSERT_TRUE(fs::exists(golden_path)) << golden_path << " is missing: run the update-goldens target";
  const Image golden = io::read_image(golden_path);
  ASSERT_EQ(image.width, golden.width);
  ASSERT_EQ(image.height, golden.height);
  double total = 0.0;
  int far_off = 0;
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float codes = 255.0f * std::abs(srgb_encode(image.pixels[i][c]) - srgb_encode(golden.pixels[i][c]));
      total += codes;
      far_off += codes > 16.0f;
    }
  const double channels = 3.0 * double(image.pixels.size());
  EXPECT_LE(total / channels, 1.0) << "mean difference in 8-bit codes";
  EXPECT_LE(double(far_off) / channels, 0.005) << "share of values off by more than 16 codes";
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, Snapshot,
                         testing::Combine(testing::ValuesIn(kScenes), testing::ValuesIn(kModels)),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param)) + "_" + std::get<1>(info.param);
                         });

}  // namespace
}  // namespace luz
