// Where the samples go (raytracing/sampling.h): the pixel's strata, the points on an emitter,
// and Whitted's adaptive subdivision, each against what its distribution or its arithmetic must
// give whatever the scene.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/image.h"
#include "raytracing/sampling.h"

namespace luz::rt {
namespace {

// n x n jittered samples: one in each stratum, and over many pixels their mean is the pixel's
// centre (samples stuck at the strata's corners would pull it to (n - 1) / 2n).
TEST(StratifiedSamples, OnePerStratumAndCentredOnAverage) {
  std::vector<glm::vec2> samples;
  glm::dvec2 sum(0.0);
  int count = 0;
  for (int pixel = 0; pixel < 500; ++pixel) {
    Random random(pixel, 3, -1);
    stratified_pixel_samples(16, random, samples);
    ASSERT_EQ(samples.size(), 16u);
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        const glm::vec2 s = samples[size_t(4 * j + i)];
        EXPECT_GE(s.x, float(i) / 4.0f);
        EXPECT_LT(s.x, float(i + 1) / 4.0f);
        EXPECT_GE(s.y, float(j) / 4.0f);
        EXPECT_LT(s.y, float(j + 1) / 4.0f);
        sum += glm::dvec2(s);
        ++count;
      }
  }
  // 8000 samples of standard deviation 1/(4 sqrt(12)) about their strata's centres: the mean's
  // is 0.0008; 0.005 is six of those.
  EXPECT_NEAR(sum.x / count, 0.5, 0.005);
  EXPECT_NEAR(sum.y / count, 0.5, 0.005);
}

// Shirley's map spreads the points uniformly over the triangle: their mean is the centroid, and
// a quarter of them fall in each of the four triangles the edges' midpoints cut it into.
TEST(TriangleSamples, UniformOverTheTriangle) {
  const glm::vec3 p0(0, 0, 0), p1(2, 0, 0), p2(0, 1, 0);
  std::vector<glm::vec3> points;
  glm::dvec3 sum(0.0);
  int corner0 = 0, count = 0;
  for (int draw = 0; draw < 500; ++draw) {
    Random random(draw, 7, 0);
    triangle_samples(p0, p1, p2, 9, random, points);
    ASSERT_EQ(points.size(), 9u);
    for (const glm::vec3& p : points) {
      const float b1 = p.x / 2.0f, b2 = p.y, b0 = 1.0f - b1 - b2;
      EXPECT_GE(std::min({b0, b1, b2}), -1e-6f) << "outside the triangle";
      corner0 += b0 > 0.5f;  // the quarter at p0
      sum += glm::dvec3(p);
      ++count;
    }
  }
  const glm::dvec3 centroid = glm::dvec3(p0 + p1 + p2) / 3.0;
  EXPECT_NEAR(sum.x / count, centroid.x, 0.01);
  EXPECT_NEAR(sum.y / count, centroid.y, 0.01);
  EXPECT_NEAR(double(corner0) / count, 0.25, 0.02);
}

// On a bilinear radiance (x y / 4 in red, x y / 8 in green) each square's corner average is its
// exact mean, so the adaptive pixel, subdivided to any depth, is the pixel's exact mean: a square
// given the wrong corner values would be off. Every square's corners differ here (threshold 0),
// so each level splits them all, and each split traces five new points.
TEST(AdaptivePixel, ExactOnABilinearRadianceAtEveryDepth) {
  int traced = 0;
  const auto f = [&traced](float x, float y) {
    ++traced;
    return Rgb(x * y / 4.0f, x * y / 8.0f, 0.0f);
  };
  for (const float x0 : {0.0f, 1.0f}) {  // the pixels [0, 1]^2 and [1, 2]^2
    const float x1 = x0 + 1.0f;
    const Rgb corners[4] = {f(x0, x0), f(x1, x0), f(x0, x1), f(x1, x1)};
    const float half = (x1 * x1 - x0 * x0) / 2.0f;  // the integral of x over [x0, x1]
    const float mean = half * half / 4.0f;
    for (int levels = 0; levels <= 3; ++levels) {
      traced = 0;
      const Rgb pixel = adaptive_pixel(x0, x0, corners, levels, 0.0f, f);
      EXPECT_NEAR(pixel.r, mean, 1e-6f) << "pixel at " << x0 << ", levels " << levels;
      EXPECT_NEAR(pixel.g, mean / 2.0f, 1e-6f) << "pixel at " << x0 << ", levels " << levels;
      EXPECT_EQ(traced, 5 * ((1 << (2 * levels)) - 1) / 3) << "5 (4^L - 1) / 3 points";
    }
  }
}

// The same subdivision written the plain way, each square's corners traced where they lie
// rather than handed down from its parent: adaptive_pixel must agree with it square for square,
// also where the refinement stops at different depths side by side (an edge through the pixel).
Rgb subdivided(float x, float y, float size, int levels, float threshold,
               const std::function<Rgb(float, float)>& f) {
  const Rgb c[4] = {f(x, y), f(x + size, y), f(x, y + size), f(x + size, y + size)};
  bool differ = false;
  for (int k = 0; k < 3; ++k) {
    float lo = 1.0f, hi = 0.0f;
    for (const Rgb& v : c) {
      lo = std::min(lo, srgb_encode(v[k]));
      hi = std::max(hi, srgb_encode(v[k]));
    }
    differ |= hi - lo > threshold;
  }
  if (levels == 0 || !differ) return 0.25f * (c[0] + c[1] + c[2] + c[3]);
  const float h = size / 2.0f;
  return 0.25f * (subdivided(x, y, h, levels - 1, threshold, f) + subdivided(x + h, y, h, levels - 1, threshold, f) +
                  subdivided(x, y + h, h, levels - 1, threshold, f) +
                  subdivided(x + h, y + h, h, levels - 1, threshold, f));
}

TEST(AdaptivePixel, AgreesWithTheSubdivisionTracedSquareBySquare) {
  // A bright disc on a dark blue ground, its edge crossing the 4 x 4 pixels at every angle.
  const auto f = [](float x, float y) {
    const float dx = x - 2.1f, dy = y - 1.9f;
    return dx * dx + dy * dy < 1.7f * 1.7f ? Rgb(1.0f, 0.2f, 0.0f) : Rgb(0.0f, 0.0f, 0.3f);
  };
  int refined = 0;
  for (int py = 0; py < 4; ++py)
    for (int px = 0; px < 4; ++px) {
      const float x = float(px), y = float(py);
      const Rgb corners[4] = {f(x, y), f(x + 1, y), f(x, y + 1), f(x + 1, y + 1)};
      const Rgb pixel = adaptive_pixel(x, y, corners, 4, 0.1f, f);
      const Rgb expected = subdivided(x, y, 1.0f, 4, 0.1f, f);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(pixel[c], expected[c], 1e-6f) << px << ", " << py;
      refined += pixel != 0.25f * (corners[0] + corners[1] + corners[2] + corners[3]);
    }
  EXPECT_GE(refined, 4);  // the edge's pixels were refined, not their corners averaged
}

}  // namespace
}  // namespace luz::rt
