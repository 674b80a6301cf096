// core/image_compare: the figures of `luz compare` and the viewer's difference view, on images
// whose answers are worked by hand.
#include <cmath>

#include <gtest/gtest.h>

#include "core/image_compare.h"

namespace luz {
namespace {

TEST(ImageCompare, IdenticalImagesDifferByNothing) {
  Image a(8, 4, Rgb(0.3f, 0.2f, 0.1f));
  const ImageComparison c = compare_images(a, a);
  EXPECT_EQ(c.mean_error, Rgb(0.0f));
  EXPECT_EQ(c.rel_rmse, 0.0);
  EXPECT_EQ(c.mean_relative_error, 0.0);
  EXPECT_EQ(c.lit_pixels, 32);
}

TEST(ImageCompare, TenPercentBrighterIsTenPercentRelativeError) {
  Image b(8, 4, Rgb(0.5f)), a(8, 4, Rgb(0.55f));
  b.at(0, 0) = a.at(0, 0) = Rgb(0.0f);  // an unlit pixel: out of the relative error
  const ImageComparison c = compare_images(a, b);
  EXPECT_NEAR(c.mean_relative_error, 0.1, 1e-6);
  EXPECT_EQ(c.lit_pixels, 31);
  EXPECT_NEAR(c.mean_error.g, 0.05 * 31.0 / 32.0, 1e-6);
  // rel-RMSE: (0.05^2 / (0.25 + 0.01)) on 31 of 32 pixels.
  EXPECT_NEAR(c.rel_rmse, std::sqrt(31.0 / 32.0 * 0.0025 / 0.26), 1e-6);
  EXPECT_NEAR(c.relative_difference[1], 0.1f, 1e-6f);
  // 3% off everywhere: the heat map's range is the next step up, 5%.
  EXPECT_EQ(heatmap_range(compare_images(Image(8, 4, Rgb(0.515f)), Image(8, 4, Rgb(0.5f)))), 0.05f);
}

// Too bright here and too dark there do not cancel: the mean is of the errors' sizes.
TEST(ImageCompare, ErrorsOfBothSignsAddUp) {
  Image b(8, 4, Rgb(0.5f)), a(8, 4, Rgb(0.55f));
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y) a.at(x, y) = Rgb(0.45f);
  const ImageComparison c = compare_images(a, b);
  EXPECT_NEAR(c.mean_relative_error, 0.1, 1e-6);
  EXPECT_NEAR(c.mean_error.g, 0.0, 1e-6);  // the signed mean does cancel
  EXPECT_NEAR(c.mean_absolute_error.g, 0.05, 1e-6);
}

// The relative error is of luminance (Rec. 709: Y = 0.2126 R + 0.7152 G + 0.0722 B): blue added
// to a red pixel counts by blue's weight over red's, 0.5 x 0.0722 / 0.2126 = 17%.
TEST(ImageCompare, RelativeErrorIsOfRec709Luminance) {
  EXPECT_FLOAT_EQ(rec709_luminance(Rgb(1.0f, 0.0f, 0.0f)), 0.2126f);
  EXPECT_FLOAT_EQ(rec709_luminance(Rgb(0.0f, 1.0f, 0.0f)), 0.7152f);
  EXPECT_FLOAT_EQ(rec709_luminance(Rgb(0.0f, 0.0f, 1.0f)), 0.0722f);
  const Image red(2, 2, Rgb(1.0f, 0.0f, 0.0f));
  const Image red_and_blue(2, 2, Rgb(1.0f, 0.0f, 0.5f));
  EXPECT_NEAR(compare_images(red_and_blue, red).mean_relative_error, 0.0722 * 0.5 / 0.2126, 1e-6);
}

TEST(ImageCompare, MaskingEmittersLeavesOutTheBrightPixelAndItsNeighbours) {
  Image b(10, 10, Rgb(0.5f)), a(10, 10, Rgb(0.5f));
  b.at(5, 5) = Rgb(40.0f);
  a.at(5, 5) = Rgb(20.0f);  // the emitter is off by half: masked, it does not count
  CompareOptions options;
  options.mask_emitters = true;
  const ImageComparison c = compare_images(a, b, options);
  EXPECT_EQ(c.masked_pixels, 9);
  EXPECT_EQ(c.mean_relative_error, 0.0);
  EXPECT_GT(compare_images(a, b).mean_relative_error, 0.0);
}

TEST(ImageCompare, HeatMapIsBlueDarkerWhiteEqualRedBrighter) {
  EXPECT_GT(diverging_colour(-1.0f).b, diverging_colour(-1.0f).r);
  EXPECT_EQ(diverging_colour(0.0f), Rgb(1.0f));
  EXPECT_GT(diverging_colour(1.0f).r, diverging_colour(1.0f).b);
}

}  // namespace
}  // namespace luz
