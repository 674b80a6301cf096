#include "core/image_compare.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace luz {

float rec709_luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

ImageComparison compare_images(const Image& a, const Image& reference, const CompareOptions& options) {
  ImageComparison result;
  const size_t n = reference.pixels.size();
  result.lit.assign(n, 0);
  result.relative_difference.assign(n, 0.0f);
  if (n == 0 || a.pixels.size() != n) return result;

  double mean_y = 0.0;
  for (const Rgb& c : reference.pixels) mean_y += double(rec709_luminance(c));
  mean_y /= double(n);
  const double lit_threshold = 0.01 * mean_y;

  std::vector<unsigned char> masked(n, 0);
  if (options.mask_emitters) {
    std::vector<float> lit_y;
    for (const Rgb& c : reference.pixels)
      if (double(rec709_luminance(c)) > lit_threshold) lit_y.push_back(rec709_luminance(c));
    if (!lit_y.empty()) {
      std::nth_element(lit_y.begin(), lit_y.begin() + std::ptrdiff_t(lit_y.size() / 2), lit_y.end());
      const float emitter = 10.0f * lit_y[lit_y.size() / 2];
      const int w = reference.width, h = reference.height;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          if (rec709_luminance(reference.at(x, y)) <= emitter) continue;
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int u = x + dx, v = y + dy;
              if (u >= 0 && v >= 0 && u < w && v < h) masked[size_t(v) * size_t(w) + size_t(u)] = 1;
            }
        }
    }
  }

  glm::dvec3 sum_error(0.0), sum_absolute(0.0);
  double sum_rel_squared = 0.0, sum_relative = 0.0;
  size_t counted = 0;
  for (size_t i = 0; i < n; ++i) {
    if (masked[i]) {
      ++result.masked_pixels;
      continue;
    }
    ++counted;
    const glm::dvec3 A(a.pixels[i]), B(reference.pixels[i]);
    const glm::dvec3 d = A - B;
    sum_error += d;
    sum_absolute += glm::abs(d);
    sum_rel_squared += glm::dot(d * d / (B * B + 0.01), glm::dvec3(1.0)) / 3.0;
    const double yb = double(rec709_luminance(reference.pixels[i]));
    if (yb > lit_threshold && yb > 0.0) {
      const double relative = (double(rec709_luminance(a.pixels[i])) - yb) / yb;
      result.lit[i] = 1;
      result.relative_difference[i] = float(relative);
      sum_relative += std::abs(relative);
      ++result.lit_pixels;
    }
  }
  if (counted > 0) {
    result.mean_error = Rgb(sum_error / double(counted));
    result.mean_absolute_error = Rgb(sum_absolute / double(counted));
    result.rel_rmse = std::sqrt(sum_rel_squared / double(counted));
  }
  if (result.lit_pixels > 0) result.mean_relative_error = sum_relative / double(result.lit_pixels);
  return result;
}

Rgb diverging_colour(float t) {
  // White at 0, toward a saturated blue (t = -1) or red (t = +1), interpolated in sRGB-encoded
  // values (what the eye compares), then decoded to linear.
  t = std::clamp(t, -1.0f, 1.0f);
  const Rgb white(1.0f), blue(0.23f, 0.30f, 0.75f), red(0.71f, 0.02f, 0.15f);
  const Rgb encoded = t < 0.0f ? glm::mix(white, blue, -t) : glm::mix(white, red, t);
  return Rgb(srgb_decode(encoded.r), srgb_decode(encoded.g), srgb_decode(encoded.b));
}

Image relative_difference_heatmap(const ImageComparison& comparison, int width, int height, float range) {
  Image heatmap(width, height, Rgb(srgb_decode(0.5f)));
  if (comparison.lit.size() != heatmap.pixels.size() || !(range > 0.0f)) return heatmap;
  for (size_t i = 0; i < heatmap.pixels.size(); ++i)
    if (comparison.lit[i]) heatmap.pixels[i] = diverging_colour(comparison.relative_difference[i] / range);
  return heatmap;
}

float heatmap_range(const ImageComparison& comparison) {
  std::vector<float> magnitudes;
  for (size_t i = 0; i < comparison.lit.size(); ++i)
    if (comparison.lit[i]) magnitudes.push_back(std::abs(comparison.relative_difference[i]));
  if (magnitudes.empty()) return 1.0f;
  const size_t k = std::min(magnitudes.size() - 1, size_t(0.95 * double(magnitudes.size())));
  std::nth_element(magnitudes.begin(), magnitudes.begin() + std::ptrdiff_t(k), magnitudes.end());
  for (float range : {0.01f, 0.02f, 0.05f, 0.1f, 0.2f, 0.5f})
    if (magnitudes[k] <= range) return range;
  return 1.0f;
}

}  // namespace luz
