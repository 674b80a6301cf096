// Core formulas worked by hand: sRGB, attenuation, spot cones, the roughness mapping, cameras.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "core/camera.h"
#include "core/exposure.h"
#include "core/image.h"
#include "core/light.h"
#include "core/material.h"
#include "core/scene.h"
#include "core/std_compat.h"

namespace luz {
namespace {

TEST(Srgb, KnownPointsOfTheCurve) {
  EXPECT_FLOAT_EQ(srgb_encode(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgb_encode(1.0f), 1.0f);
  EXPECT_NEAR(srgb_encode(0.18f), 0.4613f, 1e-4f);  // middle grey
  EXPECT_NEAR(srgb_encode(0.002f), 12.92f * 0.002f, 1e-7f);  // linear toe
  EXPECT_FLOAT_EQ(srgb_encode(std::nanf("")), 0.0f);
  for (float x : {0.001f, 0.01f, 0.2f, 0.5f, 0.9f}) EXPECT_NEAR(srgb_decode(srgb_encode(x)), x, 1e-5f);
}

// The PNG byte from the table is the rounded curve itself, on every float where a code starts
// (each start's neighbourhood, found from the inverse curve) and on a dense sweep of (0, 1).
TEST(Srgb, ByteIsTheRoundedCurve) {
  const auto expected = [](float x) { return long(std::lround(255.0f * srgb_encode(x))); };
  size_t checked = 0;
  for (int k = 1; k < 256; ++k) {
    // The linear value where code k starts, then the 200 floats on each side of it.
    float x = srgb_decode((float(k) - 0.5f) / 255.0f);
    for (int i = 0; i < 200; ++i) x = std::nextafter(x, 0.0f);
    for (int i = 0; i < 400; ++i, x = std::nextafter(x, 2.0f), ++checked)
      ASSERT_EQ(long(srgb_byte(x)), expected(x)) << "x = " << x << " near the start of code " << k;
  }
  for (uint32_t bits = 1; bits < 0x3F800000u; bits += 997, ++checked) {
    const float x = bit_cast<float>(bits);
    ASSERT_EQ(long(srgb_byte(x)), expected(x)) << "x = " << x;
  }
  EXPECT_GT(checked, 1000000u);
  EXPECT_EQ(srgb_byte(0.0f), 0);
  EXPECT_EQ(srgb_byte(-1.0f), 0);
  EXPECT_EQ(srgb_byte(std::nanf("")), 0);
  EXPECT_EQ(srgb_byte(1.0f), 255);
  EXPECT_EQ(srgb_byte(1e30f), 255);
  EXPECT_EQ(srgb_byte(0.18f), 118);  // middle grey: 255 x 0.4613 = 117.6
}

TEST(Attenuation, PhysicalIsInverseSquare) {
  Attenuation physical;
  EXPECT_FLOAT_EQ(physical.factor(2.0f), 0.25f);
}

TEST(Attenuation, ClassroomForm) {
  Attenuation classroom{true, {1.0f, 0.5f, 0.25f}};
  EXPECT_FLOAT_EQ(classroom.factor(2.0f), 1.0f / (1.0f + 1.0f + 1.0f));
}

TEST(Light, SmoothSpotConeFollowsKhrLightsPunctual) {
  Light spot;
  spot.type = LightType::spot;
  spot.direction = {0, 0, -1};
  spot.inner_cone = 0.2f;
  spot.outer_cone = 0.4f;
  EXPECT_FLOAT_EQ(spot.spot_factor({0, 0, -1}), 1.0f);
  const float angle = 0.3f;  // between the cones: ((cos a - cos o) / (cos i - cos o))^2
  const float t = (std::cos(angle) - std::cos(0.4f)) / (std::cos(0.2f) - std::cos(0.4f));
  EXPECT_NEAR(spot.spot_factor({std::sin(angle), 0, -std::cos(angle)}), t * t, 1e-5f);
  EXPECT_FLOAT_EQ(spot.spot_factor({std::sin(0.5f), 0, -std::cos(0.5f)}), 0.0f);
}

TEST(Light, WarnSpotIsCosineToThePInsideTheOuterCone) {
  Light spot;
  spot.type = LightType::spot;
  spot.direction = {0, -1, 0};
  spot.outer_cone = 1.0f;
  spot.warn_exponent = 8.0f;
  const float angle = 0.5f;
  EXPECT_NEAR(spot.spot_factor({std::sin(angle), -std::cos(angle), 0}), std::pow(std::cos(angle), 8.0f), 1e-6f);
  EXPECT_FLOAT_EQ(spot.spot_factor({std::sin(1.2f), -std::cos(1.2f), 0}), 0.0f);
}

TEST(Material, ShininessFromRoughness) {
  EXPECT_FLOAT_EQ(shininess_from_roughness(0.5f), 2.0f / 0.0625f - 2.0f);  // 30
  EXPECT_FLOAT_EQ(shininess_from_roughness(1.0f), 1.0f);                 // 0 clamped up to 1
  EXPECT_FLOAT_EQ(shininess_from_roughness(0.0f), 10000.0f);
  EXPECT_FLOAT_EQ(shininess_from_roughness(0.05f), 10000.0f);            // 319998 clamped
}

TEST(Camera, LooksDownMinusZOfItsNode) {
  Camera camera;
  camera.to_world = glm::rotate(glm::translate(glm::mat4(1.0f), {1, 2, 3}), glm::radians(90.0f), {0, 1, 0});
  EXPECT_NEAR(camera.position().x, 1.0f, 1e-6f);
  EXPECT_NEAR(camera.forward().x, -1.0f, 1e-6f);  // -Z turned 90 degrees about +Y is -X
  const glm::vec4 eye = camera.view() * glm::vec4(camera.position(), 1.0f);
  EXPECT_NEAR(glm::length(glm::vec3(eye)), 0.0f, 1e-5f);
}

TEST(Camera, FramingSeesTheWholeBoundingBox) {
  Bounds bounds;
  bounds.grow({-1, -1, -1});
  bounds.grow({1, 1, 1});
  const Camera camera = Camera::framing(bounds);
  const glm::mat4 clip = camera.projection(1.0f, bounds) * camera.view();
  for (float x : {-1.0f, 1.0f})
    for (float y : {-1.0f, 1.0f})
      for (float z : {-1.0f, 1.0f}) {
        const glm::vec4 p = clip * glm::vec4(x, y, z, 1.0f);
        EXPECT_LE(std::abs(p.x / p.w), 1.0f);
        EXPECT_LE(std::abs(p.y / p.w), 1.0f);
        EXPECT_GT(p.w, 0.0f);
      }
}

TEST(Camera, FramingSeesAFlatWideSceneFromAbove) {
  // A ground plane 10 m wide and 0.1 m tall: seen from 45 degrees above the horizon (less the
  // little height it has: 45 x (1 - 2 x 0.01) = 44.1), not edge-on, and still all in view. A box
  // as tall as it is wide is framed from +Z as before.
  Bounds ground;
  ground.grow({-5, 0, -5});
  ground.grow({5, 0.1f, 5});
  const Camera camera = Camera::framing(ground);
  EXPECT_NEAR(camera.forward().y, -std::sin(glm::radians(44.1f)), 1e-4f);
  EXPECT_NEAR(camera.forward().x, 0.0f, 1e-6f);
  const glm::mat4 clip = camera.projection(1.0f, ground) * camera.view();
  for (float x : {-5.0f, 5.0f})
    for (float y : {0.0f, 0.1f})
      for (float z : {-5.0f, 5.0f}) {
        const glm::vec4 p = clip * glm::vec4(x, y, z, 1.0f);
        EXPECT_LE(std::abs(p.x / p.w), 1.0f);
        EXPECT_LE(std::abs(p.y / p.w), 1.0f);
        EXPECT_GT(p.w, 0.0f);
      }
  Bounds box;
  box.grow({-1, -1, -1});
  box.grow({1, 1, 1});
  EXPECT_NEAR(Camera::framing(box).forward().z, -1.0f, 1e-6f);
  EXPECT_FLOAT_EQ(Camera::framing_elevation(box), 0.0f);
}

// One rule for every model: a mesh shows its material's kd texture when the texture exists and
// the mesh has TEXCOORD_0 to place it by.
TEST(Scene, AMeshShowsItsTextureOnlyWithTextureCoordinates) {
  Scene scene;
  scene.textures.resize(2);
  Mesh mapped, unmapped;
  mapped.uvs = {{0, 0}, {1, 0}, {0, 1}};
  Material material;
  EXPECT_EQ(scene.shown_texture(mapped, material), -1) << "no texture";
  material.kd_texture = 1;
  EXPECT_EQ(scene.shown_texture(mapped, material), 1);
  EXPECT_EQ(scene.shown_texture(unmapped, material), -1) << "no TEXCOORD_0";
  material.kd_texture = 2;
  EXPECT_EQ(scene.shown_texture(mapped, material), -1) << "no such texture";
}

TEST(Scene, AreaLightsAreTheEmissiveTriangles) {
  Scene scene;
  scene.materials = {Material{}, Material{}};
  scene.materials[1].emission = Rgb(2.0f);
  Mesh quad;  // 2 x 1 m in the plane y = 1, facing down
  quad.positions = {{0, 1, 0}, {2, 1, 0}, {2, 1, 1}, {0, 1, 1}};
  quad.normals.assign(4, {0, -1, 0});
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.material = 1;
  Mesh plain = quad;
  plain.material = 0;
  scene.meshes = {plain, quad};
  scene.find_area_lights();
  ASSERT_EQ(scene.area_lights.size(), 2u);
  EXPECT_EQ(scene.area_lights[0].mesh, 1);
  EXPECT_FLOAT_EQ(scene.area_lights[0].area + scene.area_lights[1].area, 2.0f);
  EXPECT_NEAR(scene.area_lights[0].normal.y, -1.0f, 1e-6f);  // counter-clockwise seen from below
  EXPECT_EQ(scene.area_lights[1].radiance, Rgb(2.0f));
}

TEST(Scene, FindCameraByNameOrIndex) {
  Scene scene;
  scene.cameras.resize(2);
  scene.cameras[0].name = "front";
  scene.cameras[1].name = "top";
  EXPECT_EQ(scene.find_camera("top"), 1);
  EXPECT_EQ(scene.find_camera("0"), 0);
  EXPECT_EQ(scene.find_camera("2"), -1);
  EXPECT_EQ(scene.find_camera("side"), -1);
  EXPECT_EQ(scene.find_camera("1x"), -1);
}

}  // namespace
// ---- The exposure fitted to a picture (core/exposure.h) ------------------------------------------

// An image of one grey luminance y (R = G = B, so Rec. 709's Y is y) in its first `lit` pixels and
// black after them.
Image grey_picture(float y, int lit, int black = 0) {
  Image image(lit + black, 1);
  for (int x = 0; x < lit + black; ++x) image.at(x, 0) = Rgb(x < lit ? y : 0.0f);
  return image;
}

TEST(Exposure, AUniformPictureIsShownAsMiddleGrey) {
  // log2(0.18 / 0.045) = 2 exactly; log2(0.18 / 0.72) = -2.
  EXPECT_FLOAT_EQ(*fitted_exposure(picture_key(grey_picture(0.045f, 10))), 2.0f);
  EXPECT_FLOAT_EQ(*fitted_exposure(picture_key(grey_picture(0.72f, 10))), -2.0f);
  EXPECT_NEAR(picture_key(grey_picture(0.72f, 10)).log_average, 0.72, 1e-6);
}

TEST(Exposure, TheKeyIsTheLogAverageNotTheMean) {
  // Half at 0.01 and half at 1: the log-average is 0.1 (the arithmetic mean, 0.505, would give
  // -1.5 EV), so the fit is log2(1.8) = 0.848 -> 0.8.
  Image image = grey_picture(0.01f, 4);
  for (int x = 0; x < 2; ++x) image.at(x, 0) = Rgb(1.0f);
  EXPECT_NEAR(picture_key(image).log_average, 0.1, 1e-6);
  EXPECT_FLOAT_EQ(*fitted_exposure(picture_key(image)), 0.8f);
}

TEST(Exposure, LuminanceWeighsTheChannelsAsRec709) {
  Image green(1, 1);
  green.at(0, 0) = Rgb(0.0f, 0.18f / 0.7152f, 0.0f);  // Y = 0.18: shown as it is
  EXPECT_FLOAT_EQ(*fitted_exposure(picture_key(green)), 0.0f);
}

TEST(Exposure, OnlyLitPixelsCount) {
  // Black pixels (a background, a shadow) and broken ones have no say.
  Image image = grey_picture(0.045f, 3, 5);
  image.at(5, 0) = Rgb(std::numeric_limits<float>::quiet_NaN());
  image.at(6, 0) = Rgb(std::numeric_limits<float>::infinity());
  image.at(7, 0) = Rgb(-1.0f);
  EXPECT_EQ(picture_key(image).lit, 3u);
  EXPECT_FLOAT_EQ(*fitted_exposure(picture_key(image)), 2.0f);
  EXPECT_FALSE(fitted_exposure(picture_key(grey_picture(0.5f, 0, 4))).has_value());
}

TEST(Exposure, ABigPictureIsReadOnAGridOfAbout65536Pixels) {
  // 1024 x 1024: every 4th pixel of every 4th row. The left half at 0.01, the right at 1: the
  // grid reads as many of each, so the key is still their log-average, 0.1.
  Image big(1024, 1024);
  for (int y = 0; y < 1024; ++y)
    for (int x = 0; x < 1024; ++x) big.at(x, y) = Rgb(x < 512 ? 0.01f : 1.0f);
  const PictureKey key = picture_key(big);
  EXPECT_EQ(key.lit, 65536u);
  EXPECT_NEAR(key.log_average, 0.1, 1e-6);
  // Up to 2^16 pixels, every one is read.
  EXPECT_EQ(picture_key(grey_picture(0.5f, 65536)).lit, 65536u);
  EXPECT_EQ(picture_key(Image(300, 200, Rgb(0.5f))).lit, 60000u);
}

TEST(Exposure, APictureWithAlmostNoLightStopsAtSixteenEvAndSaysSo) {
  // Radiance 1e-10 calls for log2(0.18 / 1e-10) = +30.7 EV: rounding noise shown as white blobs.
  // The fit stops at +16 EV and the note says why; 0.045 (+2 EV) is an ordinary fit.
  const PictureKey faint = picture_key(grey_picture(1e-10f, 10));
  EXPECT_FLOAT_EQ(*fitted_exposure(faint), kMaxFittedExposure);
  EXPECT_TRUE(almost_no_light(faint));
  EXPECT_NE(almost_no_light_note(faint).find("+30.7 EV"), std::string::npos) << almost_no_light_note(faint);
  const PictureKey ordinary = picture_key(grey_picture(0.045f, 10));
  EXPECT_FALSE(almost_no_light(ordinary));
  EXPECT_FLOAT_EQ(*fitted_exposure(ordinary), 2.0f);
  // Just inside the bound: 0.18 / 2^16 is fitted, not bounded.
  EXPECT_FALSE(almost_no_light(picture_key(grey_picture(0.18f / 65536.0f, 10))));
}

TEST(Exposure, TheFitIsRoundedToATenthOfAnEv) {
  // log2(0.18 / 0.1) = 0.848
  const float fitted = *fitted_exposure(picture_key(grey_picture(0.1f, 1)));
  EXPECT_FLOAT_EQ(fitted, 0.8f);
  EXPECT_FALSE(std::signbit(*fitted_exposure(picture_key(grey_picture(0.18f, 1)))));  // +0, not -0
}

TEST(Exposure, APictureFarOffItsExposureIsNamedOverOrUnder) {
  // A Blender lamp read as W/sr: radiance 175 everywhere, fitted log2(0.18 / 175) = -9.9 EV.
  const Image bright = grey_picture(175.0f, 8, 2);
  const std::string over = exposure_problem(bright, 0.0f, "hint");
  EXPECT_EQ(over, "at +0 EV the picture is over-exposed: 100% of its lit pixels are white, and its mid-tones "
                  "call for -9.9 EV (hint)");
  EXPECT_EQ(exposure_problem(bright, -9.9f), "");
  // Within kExposureTolerance (4 EV) of the fit: nothing to say.
  EXPECT_EQ(exposure_problem(bright, -9.9f + 3.9f), "");
  EXPECT_NE(exposure_problem(bright, -9.9f + 4.1f), "");
  // Radiance 1e-4 at +0 EV shows as black (below the 8-bit code 0.5 of the sRGB curve) and calls
  // for log2(0.18 / 1e-4) = +10.8 EV. No hint: it is about lights too bright.
  EXPECT_EQ(exposure_problem(grey_picture(1e-4f, 4), 0.0f, "hint"),
            "at +0 EV the picture is under-exposed: 100% of its lit pixels are black, and its mid-tones call "
            "for +10.8 EV");
  EXPECT_NE(exposure_problem(grey_picture(0.045f, 4), 2.0f - 4.1f), "");
  EXPECT_EQ(exposure_problem(grey_picture(0.045f, 4), 2.0f - 3.9f), "");
  EXPECT_EQ(exposure_problem(grey_picture(0.0f, 4), 0.0f), "");  // nothing lit
}

TEST(Exposure, TheSharesCountWhiteAndBlackPixels) {
  // Three of four lit pixels clip at +0 EV (a channel >= 1), the fourth does not.
  Image image = grey_picture(300.0f, 4);
  image.at(3, 0) = Rgb(0.5f);
  EXPECT_NE(exposure_problem(image, 0.0f).find("75% of its lit pixels are white"), std::string::npos);
  Image dark = grey_picture(1e-5f, 4);
  dark.at(0, 0) = Rgb(1e-2f);
  EXPECT_NE(exposure_problem(dark, 0.0f).find("75% of its lit pixels are black"), std::string::npos);
}

TEST(Exposure, ThePhotometricHintIsForBlendersLights) {
  Scene scene;
  scene.generator = "Khronos glTF Blender I/O v3.4.50";
  EXPECT_EQ(photometric_hint(scene), "");  // no light
  scene.lights.push_back(Light{});
  EXPECT_EQ(photometric_hint(scene),
            "Khronos glTF Blender I/O v3.4.50 writes lights in candela: in its Lighting Mode \"Standard\" 683 "
            "times the W/sr Luz reads, in \"Raw\" its point and spot lights 4 pi times; \"Unitless\" writes W/sr");
  scene.default_lights = true;  // Luz's own: in its units
  EXPECT_EQ(photometric_hint(scene), "");
  scene.default_lights = false;
  scene.generator = "Khronos glTF Blender I/O";
  EXPECT_NE(photometric_hint(scene), "");
  scene.generator = "glTF-Transform v3";
  EXPECT_EQ(photometric_hint(scene), "");
}

}  // namespace luz
