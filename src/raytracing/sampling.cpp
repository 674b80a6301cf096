#include "raytracing/sampling.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/image.h"

namespace luz::rt {

uint64_t branch_seed(uint64_t parent, RayKind branch) {
  // One more SplitMix64 step of the parent's seed, told apart by the branch: the reflected and
  // the transmitted child of one hit get unrelated streams, and so do a child and its parent.
  uint64_t seed = parent ^ (uint64_t(branch) << 56);
  return splitmix(seed);
}

Random::Random(int x, int y, int sample) : state_(sample_seed(x, y, sample)) {}

float Random::next() {
  return float(splitmix(state_) >> 40) * 0x1.0p-24f;  // 24 random bits: exact in a float, < 1
}

bool is_square(int spp) {
  if (spp < 1) return false;
  const int n = int(std::lround(std::sqrt(double(spp))));
  return n * n == spp;
}

void stratified_pixel_samples(int spp, Random& random, std::vector<glm::vec2>& samples) {
  samples.clear();
  if (spp <= 1) {
    samples.emplace_back(0.5f);
    return;
  }
  const int n = std::max(1, int(std::lround(std::sqrt(double(spp)))));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float jx = random.next(), jy = random.next();
      samples.emplace_back((float(i) + jx) / float(n), (float(j) + jy) / float(n));
    }
}

void triangle_samples(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, int count,
                      Random& random, std::vector<glm::vec3>& points) {
  points.clear();
  if (count <= 1) {
    points.push_back((p0 + p1 + p2) / 3.0f);
    return;
  }
  // A random permutation pairs the u-strata with the v-strata (Fisher-Yates). Its buffer is kept
  // per thread: this runs for every hit and every emissive triangle.
  thread_local std::vector<int> permutation;
  permutation.resize(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) permutation[size_t(i)] = i;
  for (int i = count - 1; i > 0; --i) {
    const int j = std::min(i, int(random.next() * float(i + 1)));
    std::swap(permutation[size_t(i)], permutation[size_t(j)]);
  }
  for (int i = 0; i < count; ++i) {
    const float u = (float(i) + random.next()) / float(count);
    const float v = (float(permutation[size_t(i)]) + random.next()) / float(count);
    const float s = std::sqrt(u);
    const float b0 = 1.0f - s, b1 = v * s;
    points.push_back(b0 * p0 + b1 * p1 + (1.0f - b0 - b1) * p2);
  }
}

namespace {

bool corners_differ(const Rgb corners[4], float threshold) {
  for (int c = 0; c < 3; ++c) {
    float lo = 1.0f, hi = 0.0f;
    for (int k = 0; k < 4; ++k) {
      const float e = srgb_encode(corners[k][c]);
      lo = std::min(lo, e);
      hi = std::max(hi, e);
    }
    if (hi - lo > threshold) return true;
  }
  return false;
}

Rgb subdivide(float x, float y, float size, const Rgb corners[4], int levels, float threshold,
              const std::function<Rgb(float, float)>& radiance) {
  if (levels <= 0 || !corners_differ(corners, threshold))
    return 0.25f * (corners[0] + corners[1] + corners[2] + corners[3]);
  const float h = 0.5f * size;
  // The five new points: edge midpoints and the centre.
  const Rgb top = radiance(x + h, y), left = radiance(x, y + h), centre = radiance(x + h, y + h);
  const Rgb right = radiance(x + size, y + h), bottom = radiance(x + h, y + size);
  const Rgb q0[4] = {corners[0], top, left, centre};
  const Rgb q1[4] = {top, corners[1], centre, right};
  const Rgb q2[4] = {left, centre, corners[2], bottom};
  const Rgb q3[4] = {centre, right, bottom, corners[3]};
  return 0.25f * (subdivide(x, y, h, q0, levels - 1, threshold, radiance) +
                  subdivide(x + h, y, h, q1, levels - 1, threshold, radiance) +
                  subdivide(x, y + h, h, q2, levels - 1, threshold, radiance) +
                  subdivide(x + h, y + h, h, q3, levels - 1, threshold, radiance));
}

}  // namespace

Rgb adaptive_pixel(float x, float y, const Rgb corners[4], int levels, float threshold,
                   const std::function<Rgb(float, float)>& radiance) {
  return subdivide(x, y, 1.0f, corners, levels, threshold, radiance);
}

}  // namespace luz::rt
