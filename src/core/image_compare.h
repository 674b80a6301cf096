#pragma once
// Two pictures of the same view compared: a model's against a reference (the path tracer's), as
// `luz compare` prints it and the viewer's difference view shows it. No GL here.
//
//   mean error (per channel)     mean of A - B: the bias
//   mean absolute error          mean of |A - B| per channel
//   rel-RMSE                     sqrt(mean over pixels and channels of (A - B)^2 / (B^2 + eps)),
//                                eps = 0.01 (so black reference pixels do not dominate)
//   mean relative error          mean of |Y(A) - Y(B)| / Y(B) over the lit pixels, Y the
//                                luminance (Rec. 709): a pixel is lit when Y(B) > 1% of the
//                                reference's mean luminance
#include <vector>

#include "core/color.h"
#include "core/image.h"

namespace luz {

float rec709_luminance(const Rgb& c);  // Rec. 709: 0.2126 R + 0.7152 G + 0.0722 B

struct CompareOptions {
  // Leave out the emitters: pixels whose reference luminance exceeds 10x the median of the lit
  // pixels (an emitter seen directly is orders brighter than what it lights), and their
  // neighbours (the partly covered pixels at its edge).
  bool mask_emitters = false;
};

struct ImageComparison {
  Rgb mean_error{0.0f};
  Rgb mean_absolute_error{0.0f};
  double rel_rmse = 0.0;
  double mean_relative_error = 0.0;  // over lit pixels (0 when none)
  int lit_pixels = 0;
  int masked_pixels = 0;             // emitter pixels left out of every figure
  // Per pixel: 1 where it counts in the relative error, 0 elsewhere (unlit or masked).
  std::vector<unsigned char> lit;
  // Per pixel: (Y(A) - Y(B)) / Y(B) where lit, 0 elsewhere.
  std::vector<float> relative_difference;
};

// `a` and `reference` must have the same size (the caller says which file is wrong).
ImageComparison compare_images(const Image& a, const Image& reference, const CompareOptions& options = {});

// The signed relative difference as colours: blue where A is darker than the reference, white
// where equal, red where brighter, saturated at +-range; unlit pixels grey. Linear RGB, so that
// a PNG written from it shows those colours.
Image relative_difference_heatmap(const ImageComparison& comparison, int width, int height, float range);

// The heat maps' scale unless one is asked for: +-50%, the same in the window's difference view,
// `luz compare` and the handouts, so that two heat maps side by side mean the same colours.
inline constexpr float kHeatmapRange = 0.5f;

// A range fitted to one comparison: the smallest of 1, 2, 5, 10, 20, 50, 100 % that holds 95% of the
// lit pixels' relative differences.
float heatmap_range(const ImageComparison& comparison);

// The diverging colour map itself, t in [-1, 1] (linear RGB).
Rgb diverging_colour(float t);

}  // namespace luz
