// Snapshot tests: every shipped scene in every local model, rendered by `luz render` as a user
// would, checked by properties a teacher relies on and against a golden image.
//
// Golden tolerance, in 8-bit sRGB codes of the PNG: mean absolute difference <= 1 code and at
// most 0.5% of the pixels off by more than 16 codes (rasterisation may move a silhouette by a
// pixel between Mesa versions; shading may not change). Goldens are rewritten only by
// `cmake --build build --target update-goldens`.
#include <array>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include <glm/mat4x4.hpp>

#include "core/image.h"
#include "io/gltf_loader.h"
#include "io/image_io.h"
#include "support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScenes[] = {"cornell_box", "phong_spheres", "whitted", "local_effects"};
constexpr const char* kModels[] = {"flat", "gouraud", "phong"};

// Small pictures at each camera's aspect ratio; update_goldens.sh uses the same sizes.
std::string size_of(const std::string& scene) {
  return scene == "cornell_box" || scene == "cornell_spheres" ? "120x120" : "160x120";
}

// Every switch of slide 19 on, as the local_effects golden and the README's picture have them.
const std::vector<std::string> kEffectFlags = {"--shadows", "--transparency", "--reflection-map", "--fog", "linear",
                                               "--fog-near", "6", "--fog-far", "24"};

// Renders through the command to EXR (linear radiance, for properties) or PNG (for goldens).
Image render(const test::ScratchDir& dir, const std::string& scene, const std::string& model,
             const std::string& extension, std::vector<std::string> extra = {}) {
  static int count = 0;  // each render its own file: a test may render one model several ways
  const fs::path out = dir / (scene + "-" + model + "-" + std::to_string(count++) + extension);
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

void expect_golden(const Image& image, const std::string& name) {
  const fs::path golden_path = test::test_data_dir() / "golden" / (name + ".png");
  ASSERT_TRUE(fs::exists(golden_path)) << golden_path << " is missing: run the update-goldens target";
  const Image golden = io::read_image(golden_path);
  ASSERT_EQ(image.width, golden.width) << name;
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

TEST_P(Snapshot, MatchesItsGolden) {
  const auto [scene, model] = GetParam();
  test::ScratchDir dir;
  expect_golden(render(dir, scene, model, ".png"), std::string(scene) + "-" + model);
}

// The plate with every effect of slide 19 on, in each model.
class EffectsSnapshot : public testing::TestWithParam<const char*> {};

TEST_P(EffectsSnapshot, MatchesItsGolden) {
  const char* model = GetParam();
  test::ScratchDir dir;
  expect_golden(render(dir, "local_effects", model, ".png", kEffectFlags),
                std::string("local_effects-") + model + "-effects");
}

INSTANTIATE_TEST_SUITE_P(LocalEffects, EffectsSnapshot, testing::ValuesIn(kModels));

INSTANTIATE_TEST_SUITE_P(ShippedScenes, Snapshot,
                         testing::Combine(testing::ValuesIn(kScenes), testing::ValuesIn(kModels)),
                         snapshot_name);

// The Whitted tracer (default settings: depth 5, 1 sample per pixel, centroid area lights) is
// deterministic, so the same golden tolerance holds; update_goldens.sh renders the same list.
constexpr const char* kTracedScenes[] = {"whitted", "cornell_box", "cornell_spheres"};
constexpr const char* kTracedModels[] = {"whitted"};
INSTANTIATE_TEST_SUITE_P(Traced, Snapshot,
                         testing::Combine(testing::ValuesIn(kTracedScenes), testing::ValuesIn(kTracedModels)),
                         snapshot_name);

// ---- Radiosity -----------------------------------------------------------------------------
// Coarse meshes and small hemicubes keep each solve under two seconds on llvmpipe; the same
// flags are in update_goldens.sh (keep them in step).
std::vector<std::string> radiosity_flags(const std::string& scene) {
  if (scene == "cornell_box") return {"--patch-size", "0.1", "--hemicube-res", "64"};
  if (scene == "whitted") return {"--patch-size", "0.25", "--hemicube-res", "64", "--converge", "0.02"};
  if (scene == "cornell_spheres") return {"--patch-size", "0.12", "--hemicube-res", "64", "--converge", "0.02"};
  return {"--patch-size", "0.1", "--hemicube-res", "64"};
}

class RadiositySnapshot : public testing::TestWithParam<const char*> {};

TEST_P(RadiositySnapshot, MatchesItsGolden) {
  const std::string scene = GetParam();
  test::ScratchDir dir;
  expect_golden(render(dir, scene, "radiosity", ".png", radiosity_flags(scene)), scene + "-radiosity");
}

// The slide-19 plate is for the local models (its spheres alone make some 17k patches):
// radiosity's snapshots are the lecture scenes.
constexpr const char* kRadiosityScenes[] = {"cornell_box", "phong_spheres", "whitted", "cornell_spheres"};
INSTANTIATE_TEST_SUITE_P(ShippedScenes, RadiositySnapshot, testing::ValuesIn(kRadiosityScenes));

// ---- Hybrid (slides 41-43) -------------------------------------------------------------------
// The radiosity solve with radiosity_flags(), then the tracer at its defaults; deterministic
// (seeded hemicube rotations, seeded samples), so the golden tolerance above holds.
class HybridSnapshot : public testing::TestWithParam<const char*> {};

TEST_P(HybridSnapshot, MatchesItsGolden) {
  const std::string scene = GetParam();
  test::ScratchDir dir;
  expect_golden(render(dir, scene, "hybrid", ".png", radiosity_flags(scene)), scene + "-hybrid");
}

constexpr const char* kHybridScenes[] = {"cornell_spheres"};
INSTANTIATE_TEST_SUITE_P(ShippedScenes, HybridSnapshot, testing::ValuesIn(kHybridScenes));

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

// Whitted's tracer: what slide 23's picture shows.

int count(const Image& image, float x0, float y0, float x1, float y1, bool (*is)(const Rgb&)) {
  int n = 0;
  for (int y = int(y0 * float(image.height)); y < int(y1 * float(image.height)); ++y)
    for (int x = int(x0 * float(image.width)); x < int(x1 * float(image.width)); ++x) n += is(image.at(x, y));
  return n;
}
// The checker's red and yellow, also when seen through glass (where the sky's reflection adds
// a little blue), and the sky.
bool reddish(const Rgb& p) { return p.r > 2.0f * p.g && p.r > 1.5f * p.b; }
bool yellowish(const Rgb& p) { return p.g > 0.7f * p.r && p.r > 1.5f * p.b; }
bool sky_blue(const Rgb& p) { return p.b > 1.5f * p.r && p.b > p.g; }

TEST(WhittedModel, MirrorReflectsTheCheckerboardAndGlassShowsItUpsideDown) {
  test::ScratchDir dir;
  const Image traced = render(dir, "whitted", "whitted", ".exr");
  const Image local = render(dir, "whitted", "phong", ".exr");
  // Mirror sphere (right): the checkerboard in its lower half, the sky in its upper half.
  const float mx0 = 0.55f, mx1 = 0.67f;
  EXPECT_GT(count(traced, mx0, 0.50f, mx1, 0.60f, reddish), 30);
  EXPECT_GT(count(traced, mx0, 0.50f, mx1, 0.60f, yellowish), 30);
  EXPECT_GT(count(traced, mx0, 0.36f, mx1, 0.44f, sky_blue), 60);
  // Glass sphere (left) refracts like a lens: the checkerboard upside down in its upper half,
  // the sky in its lower half.
  const float gx0 = 0.30f, gx1 = 0.45f;
  EXPECT_GT(count(traced, gx0, 0.22f, gx1, 0.32f, reddish), 30);
  EXPECT_GT(count(traced, gx0, 0.22f, gx1, 0.32f, yellowish), 30);
  EXPECT_GT(count(traced, gx0, 0.40f, gx1, 0.50f, sky_blue), 150);
  // The local model shows none of it: there the spheres are their own dull colours (boxes
  // inside both silhouettes).
  for (auto is : {reddish, yellowish, sky_blue}) {
    EXPECT_EQ(count(local, 0.56f, 0.40f, 0.66f, 0.58f, is), 0);
    EXPECT_EQ(count(local, 0.31f, 0.26f, 0.40f, 0.46f, is), 0);
  }
}

TEST(WhittedModel, CornellBlocksCastShadowsOnTheFloor) {
  test::ScratchDir dir;
  const Image shadows = render(dir, "cornell_box", "whitted", ".exr");
  const Image none = render(dir, "cornell_box", "whitted", ".exr", {"--no-shadows"});
  // The floor beside the short block (in front, right) and left of the tall one, in shadow.
  for (const auto& [x0, y0, x1, y1] : {std::array{0.50f, 0.92f, 0.64f, 0.96f},
                                       std::array{0.15f, 0.70f, 0.25f, 0.77f}}) {
    EXPECT_LT(mean_colour(shadows, x0, y0, x1, y1).r, 0.3f * mean_colour(none, x0, y0, x1, y1).r)
        << x0 << "," << y0;
  }
  // The open floor in front on the left sees the whole lamp: the same with or without shadows.
  const Rgb open = mean_colour(shadows, 0.10f, 0.92f, 0.35f, 0.96f);
  EXPECT_NEAR(open.r, mean_colour(none, 0.10f, 0.92f, 0.35f, 0.96f).r, 1e-6f);
  EXPECT_GT(open.r, 5.0f * mean_colour(shadows, 0.50f, 0.92f, 0.64f, 0.96f).r);
}

// ---- Slide 19 on the plate: each switch on and off, in every model ------------------------------
// Where a world point of local_effects.gltf lands in the picture (the scene camera, 160x120).
struct PlatePixels {
  Scene scene = io::load_gltf(test::scene_dir() / "local_effects.gltf").scene;
  glm::ivec2 pixel(const Image& image, glm::vec3 P) const {
    const Camera& camera = scene.cameras.front();
    const glm::vec4 clip = camera.projection(float(image.width) / float(image.height), scene.bounds()) * camera.view() *
                           glm::vec4(P, 1.0f);
    const int x = int((clip.x / clip.w * 0.5f + 0.5f) * float(image.width));
    const int y = int((0.5f - clip.y / clip.w * 0.5f) * float(image.height));
    return {std::clamp(x, 0, image.width - 1), std::clamp(y, 0, image.height - 1)};
  }
  Rgb at(const Image& image, glm::vec3 P) const {
    const glm::ivec2 p = pixel(image, P);
    return image.at(p.x, p.y);
  }
};

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

class EffectSwitch : public testing::TestWithParam<const char*> {};

TEST_P(EffectSwitch, ShadowsDarkenTheFloorBehindTheBoxAndNothingElse) {
  test::ScratchDir dir;
  const PlatePixels plate;
  const Image off = render(dir, "local_effects", GetParam(), ".exr");
  const Image on = render(dir, "local_effects", GetParam(), ".exr", {"--shadows"});
  // Left of the box, where the key spot's shadow shows beside it (the box hides the rest).
  const glm::vec3 beside_box(-3.15f, 0.0f, -1.65f), open_floor(0.8f, 0.0f, 0.8f), box_top(-2.6f, 0.7f, -1.6f);
  EXPECT_LT(luminance(plate.at(on, beside_box)), 0.7f * luminance(plate.at(off, beside_box)));
  EXPECT_NEAR(luminance(plate.at(on, open_floor)), luminance(plate.at(off, open_floor)), 1e-4f)
      << "the lit floor keeps its light (no acne)";
  EXPECT_NEAR(luminance(plate.at(on, box_top)), luminance(plate.at(off, box_top)), 1e-4f)
      << "the box's top is lit by every light (no acne)";
}

TEST_P(EffectSwitch, FogTakesTheFarPillarsTowardTheFogColour) {
  test::ScratchDir dir;
  const PlatePixels plate;
  const Rgb fog(0.25f, 0.27f, 0.3f);  // LocalOptions' default fog colour
  const Image off = render(dir, "local_effects", GetParam(), ".exr");
  const Image on = render(dir, "local_effects", GetParam(), ".exr", {"--fog", "linear", "--fog-near", "6", "--fog-far", "24"});
  const glm::vec3 far_pillar(-3.0f, 1.5f, -12.8f), near_floor(0.0f, 0.0f, 2.0f);  // 18.9 m and 4.7 m away
  const float f = (24.0f - 18.9f) / 18.0f;
  EXPECT_LT(glm::length(plate.at(on, far_pillar) - fog), 1.5f * f * glm::length(plate.at(off, far_pillar) - fog));
  EXPECT_EQ(plate.at(on, near_floor), plate.at(off, near_floor)) << "nearer than --fog-near: untouched";
  EXPECT_EQ(on.at(on.width / 2, 0), fog) << "the sky is all fog";
}

TEST_P(EffectSwitch, TransparencyShowsTheRedBoxThroughThePane) {
  test::ScratchDir dir;
  const PlatePixels plate;
  const Image off = render(dir, "local_effects", GetParam(), ".exr");
  const Image on = render(dir, "local_effects", GetParam(), ".exr", {"--transparency"});
  const glm::vec3 red_box_front(-0.4f, 0.35f, -1.75f);
  const Rgb seen_off = plate.at(off, red_box_front), seen_on = plate.at(on, red_box_front);
  const glm::ivec2 p = plate.pixel(on, red_box_front);
  EXPECT_GT(seen_on.r, seen_off.r + 0.02f) << "through the pane, the red box, pixel " << p.x << ", " << p.y;
  EXPECT_GT(seen_on.r, 1.5f * seen_on.g);
  EXPECT_LT(seen_off.r, 1.5f * seen_off.b) << "the opaque pane is bluish grey";
}

TEST_P(EffectSwitch, ReflectionMapShowsTheFloorInTheMirrorBall) {
  test::ScratchDir dir;
  const PlatePixels plate;
  const Image off = render(dir, "local_effects", GetParam(), ".exr");
  const Image on = render(dir, "local_effects", GetParam(), ".exr", {"--reflection-map"});
  const glm::vec3 lower_ball(2.6f, 0.5f - 0.3f, -1.6f + 0.4f);  // its normal looks down and forward
  EXPECT_GT(luminance(plate.at(on, lower_ball)), luminance(plate.at(off, lower_ball)) + 0.03f);
  const glm::vec3 open_floor(0.8f, 0.0f, 0.8f);
  EXPECT_EQ(plate.at(on, open_floor), plate.at(off, open_floor)) << "kr = 0 there";
}

INSTANTIATE_TEST_SUITE_P(LocalEffects, EffectSwitch, testing::ValuesIn(kModels));

}  // namespace
}  // namespace luz
