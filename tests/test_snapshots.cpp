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

// Small pictures at each camera's aspect ratio; update_goldens.sh uses the same sizes.
std::string size_of(const std::string& scene) { return scene == "cornell_box" ? "120x120" : "160x120"; }

// Renders through the command to EXR (linear radiance, for properties) or PNG (for goldens).
Image render(const test::ScratchDir& dir, const std::string& scene, const std::string& model,
             const std::string& extension, std::vector<std::string> extra = {}) {
  const fs::path out = dir / (scene + "-" + model + extension);
  std::vector<std::string> args = {"render", (test::scene_dir() / (scene + ".gltf")).string(),
                                   "--model", model, "--size", size_of(scene), "-q", "--out", out.string()};
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

std::string snapshot_name(const testing::TestParamInfo<std::tuple<const char*, const char*>>& param) {
  return std::string(std::get<0>(param.param)) + "_" + std::get<1>(param.param);
}

class Snapshot : public testing::TestWithParam<std::tuple<const char*, const char*>> {};

TEST_P(Snapshot, MatchesItsGolden) {
  const auto [scene, model] = GetParam();
  test::ScratchDir dir;
  const Image image = render(dir, scene, model, ".png");
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
                         snapshot_name);

// ---- Radiosity -----------------------------------------------------------------------------
// Coarse meshes and small hemicubes keep each solve under two seconds on llvmpipe; the same
// flags are in update_goldens.sh (keep them in step).
std::vector<std::string> radiosity_flags(const std::string& scene) {
  if (scene == "cornell_box") return {"--patch-size", "0.1", "--hemicube-res", "64"};
  if (scene == "whitted") return {"--patch-size", "0.25", "--hemicube-res", "64", "--converge", "0.02"};
  return {"--patch-size", "0.1", "--hemicube-res", "64"};
}

class RadiositySnapshot : public testing::TestWithParam<const char*> {};

TEST_P(RadiositySnapshot, MatchesItsGolden) {
  const std::string scene = GetParam();
  test::ScratchDir dir;
  const Image image = render(dir, scene, "radiosity", ".png", radiosity_flags(scene));
  const fs::path golden_path = test::test_data_dir() / "golden" / (scene + "-radiosity.png");
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

INSTANTIATE_TEST_SUITE_P(ShippedScenes, RadiositySnapshot, testing::ValuesIn(kScenes));

float red_over_green(const Rgb& c) { return c.r / c.g; }

TEST(CornellBoxRadiosity, ColourBleedsAndTheCeilingIsLitIndirectly) {
  test::ScratchDir dir;
  const Image image = render(dir, "cornell_box", "radiosity", ".exr", radiosity_flags("cornell_box"));
  const Image local = render(dir, "cornell_box", "gouraud", ".exr");
  const Rgb left = mean_colour(image, 0.03f, 0.3f, 0.15f, 0.7f);
  const Rgb right = mean_colour(image, 0.85f, 0.3f, 0.97f, 0.7f);
  EXPECT_GT(left.r, 3.0f * left.g);
  EXPECT_GT(right.g, 2.0f * right.r);
  EXPECT_GT(mean_colour(image, 0.45f, 0.12f, 0.55f, 0.15f).r, 10.0f) << "the lamp shows its Le";
  // The white back wall takes a red tint beside the red wall and a green one beside the green.
  const Rgb back_left = mean_colour(image, 0.23f, 0.25f, 0.27f, 0.4f);
  const Rgb back_right = mean_colour(image, 0.73f, 0.25f, 0.77f, 0.4f);
  EXPECT_GT(red_over_green(back_left), 1.2f * red_over_green(back_right));
  // The lamp faces down: the ceiling has only indirect light, several times the local models'
  // ambient stand-in (Ia ka = 0.02 x 0.73).
  const Rgb ceiling = mean_colour(image, 0.25f, 0.03f, 0.38f, 0.1f);
  const Rgb ceiling_local = mean_colour(local, 0.25f, 0.03f, 0.38f, 0.1f);
  EXPECT_GT(ceiling.g, 2.0f * ceiling_local.g);
  // The floor in front of the blocks, lit directly: within a factor of 1.5 of the local model
  // (same units; radiosity adds the interreflections and the lamp's true extent).
  const Rgb floor = mean_colour(image, 0.45f, 0.9f, 0.55f, 0.97f);
  const Rgb floor_local = mean_colour(local, 0.45f, 0.9f, 0.55f, 0.97f);
  EXPECT_GT(floor.g, floor_local.g / 1.5f);
  EXPECT_LT(floor.g, floor_local.g * 1.5f);
}

TEST(PhongSpheresRadiosity, DiffuseFallsWithKdAcrossTheColumns) {
  test::ScratchDir dir;
  const Image image = render(dir, "phong_spheres", "radiosity", ".exr", radiosity_flags("phong_spheres"));
  float previous = 1e30f;
  for (int column = 0; column < 5; ++column) {  // kd = (1 - ks) x base, ks rising to the right
    const float x0 = 0.1f + 0.1675f * float(column) + 0.03f;
    const float brightest = [&] {
      float best = 0.0f;
      for (int y = 0; y < image.height; ++y)
        for (int x = int(x0 * float(image.width)); x < int((x0 + 0.08f) * float(image.width)); ++x)
          best = std::max(best, image.at(x, y).r);
      return best;
    }();
    EXPECT_LT(brightest, previous) << "column " << column;
    previous = brightest;
  }
}

TEST(WhittedRadiosity, BoardLitAndShadowedUnderTheSky) {
  test::ScratchDir dir;
  const Image image = render(dir, "whitted", "radiosity", ".exr", radiosity_flags("whitted"));
  for (int x = 0; x < image.width; ++x) EXPECT_NEAR(image.at(x, 0).b, 0.8f, 1e-5f) << "the sky";
  int red = 0, yellow = 0;
  for (int y = int(0.85f * float(image.height)); y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Rgb p = image.at(x, y);
      red += p.r > 3.0f * p.g && p.r > 3.0f * p.b;
      yellow += p.g > 0.5f * p.r && p.r > 3.0f * p.b;
    }
  EXPECT_GT(red, image.width / 4);
  EXPECT_GT(yellow, image.width / 4);
}

// Properties: what a class sees in each plate, in every model.

TEST(CornellBox, RedWallOnTheLeftGreenOnTheRightLightOnTheCeiling) {
  test::ScratchDir dir;
  for (const char* model : kModels) {
    const Image image = render(dir, "cornell_box", model, ".exr");
    const Rgb left = mean_colour(image, 0.03f, 0.3f, 0.15f, 0.7f);
    const Rgb right = mean_colour(image, 0.85f, 0.3f, 0.97f, 0.7f);
    EXPECT_GT(left.r, 3.0f * left.g) << model;
    EXPECT_GT(left.r, 3.0f * left.b) << model;
    EXPECT_GT(right.g, 2.0f * right.r) << model;
    EXPECT_GT(right.g, 2.0f * right.b) << model;
    // The lamp, just below the ceiling in the middle, shows its own radiance: the brightest
    // thing in the picture.
    EXPECT_GT(mean_colour(image, 0.45f, 0.12f, 0.55f, 0.15f).r, 10.0f) << model;
    EXPECT_GT(max_luminance(image), 10.0f) << model;
  }
}

TEST(PhongSpheres, HighlightsGrowWithKsAcrossTheColumns) {
  test::ScratchDir dir;
  const Image lit = render(dir, "phong_spheres", "phong", ".exr");
  const Image matte = render(dir, "phong_spheres", "phong", ".exr", {"--no-specular"});
  // The specular share of the brightest pixel in each column of spheres, ks rising left to right.
  float previous = -1.0f;
  for (int column = 0; column < 5; ++column) {
    const float x0 = 0.1f + 0.1675f * float(column), x1 = x0 + 0.135f;
    float lit_max = 0.0f, matte_max = 0.0f;
    for (int y = 0; y < lit.height; ++y)
      for (int x = int(x0 * float(lit.width)); x < int(x1 * float(lit.width)); ++x) {
        lit_max = std::max(lit_max, lit.at(x, y).g);
        matte_max = std::max(matte_max, matte.at(x, y).g);
      }
    const float specular = lit_max - matte_max;
    if (column == 0) EXPECT_NEAR(specular, 0.0f, 1e-4f) << "ks = 0: no highlight";
    else EXPECT_GT(specular, previous) << "column " << column;
    previous = specular;
  }
}

TEST(Whitted, SkyAboveCheckerboardBelow) {
  test::ScratchDir dir;
  for (const char* model : kModels) {
    const Image image = render(dir, "whitted", model, ".exr");
    const Rgb sky(0.2f, 0.35f, 0.8f);  // scene.extras.background
    for (int x = 0; x < image.width; ++x) {
      EXPECT_NEAR(image.at(x, 0).r, sky.r, 1e-5f);
      EXPECT_NEAR(image.at(x, 0).b, sky.b, 1e-5f);
    }
    int red = 0, yellow = 0;
    for (int y = int(0.85f * float(image.height)); y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const Rgb p = image.at(x, y);
        red += p.r > 3.0f * p.g && p.r > 3.0f * p.b;
        yellow += p.g > 0.5f * p.r && p.r > 3.0f * p.b;
      }
    EXPECT_GT(red, image.width / 4) << model;
    EXPECT_GT(yellow, image.width / 4) << model;
  }
}

}  // namespace
}  // namespace luz
