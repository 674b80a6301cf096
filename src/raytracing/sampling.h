#pragma once
// Where the samples go (slide 27, aliasing and supersampling; soft shadows of area lights).
// Every random number comes from a generator seeded by the pixel and the sample, never from
// shared state, so a picture is bitwise the same however the threads are scheduled.
//
// The ray tree's random numbers. The light samples of a hit (points on the area lights) are
// drawn from a generator of the ray's own, seeded by where the ray sits in its sample's ray tree:
// the primary ray by the pixel and the sample (sample_seed), a reflected or transmitted ray by
// its parent's seed and the branch it takes (branch_seed). No ray's numbers depend on how many
// its parent or its siblings drew, so the order in which the rays are traced does not matter:
// slide 26's recursion (depth first) and the wavefront renderer (generation by generation) draw
// the same numbers for the same ray, and render the same picture.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/color.h"
#include "raytracing/ray.h"

namespace luz::rt {

// A small counter-based generator (SplitMix64, Steele et al. 2014): seeded by a hash of the
// pixel and the sample index, it gives the same sequence on any thread.
class Random {
public:
  Random() = default;
  explicit Random(uint64_t seed) : state_(seed) {}
  Random(int x, int y, int sample);  // Random(sample_seed(x, y, sample))
  float next();  // uniform in [0, 1)

private:
  uint64_t state_ = 0;
};

// One step of SplitMix64: advances `state` and returns its next 64 random bits.
inline uint64_t splitmix(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// The seed of the ray tree of sample `sample` of pixel (x, y): its primary ray's. Inline: a
// tile computes one per sample, in a loop the compiler unrolls.
inline uint64_t sample_seed(int x, int y, int sample) {
  uint64_t seed = (uint64_t(uint32_t(x)) << 32) ^ uint64_t(uint32_t(y));
  seed = splitmix(seed) ^ uint64_t(uint32_t(sample));
  return splitmix(seed);
}
// The seed of the reflected or transmitted ray (`branch`) spawned at the hit of the ray whose
// seed is `parent`.
uint64_t branch_seed(uint64_t parent, RayKind branch);

// Stratified pixel sampling: n x n jittered positions in the unit square, n = sqrt(spp); a single
// sample sits at the centre (0.5, 0.5), where the rasteriser samples too.
void stratified_pixel_samples(int spp, Random& random, std::vector<glm::vec2>& samples);

// True when spp is a perfect square (1, 4, 9, ...).
bool is_square(int spp);

// Points on triangle (p0, p1, p2) for an area light, with equal area each. One sample is the
// centroid (SCENES.md's cheapest setting). N samples are N-rooks (Shirley 1991): strata of width
// 1/N in each coordinate of the unit square, paired by a random permutation, mapped onto the
// triangle by Shirley's area-preserving map (b0 = 1 - sqrt(u), b1 = v sqrt(u)), so every
// sample stands for area A/N.
void triangle_samples(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, int count,
                      Random& random, std::vector<glm::vec3>& points);

// Whitted's adaptive supersampling (Whitted 1980, section 4): radiance at the four corners of a
// pixel; where they differ by more than `threshold` (after sRGB encoding, so the test follows
// what the eye sees) the square is split in four and each quarter is sampled the same way, at
// most `levels` times. The pixel is the area-weighted mean of its squares' corner averages.
// `radiance(x, y)` gives the radiance through image point (x, y) (pixel units, y down);
// `corners` are the pixel's four corner radiances, (x, y), (x+1, y), (x, y+1), (x+1, y+1).
Rgb adaptive_pixel(float x, float y, const Rgb corners[4], int levels, float threshold,
                   const std::function<Rgb(float, float)>& radiance);

}  // namespace luz::rt
