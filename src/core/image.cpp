#include "core/image.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/std_compat.h"

namespace luz {

// IEC 61966-2-1 transfer curve.
float srgb_encode(float linear) {
  if (!(linear > 0.0f)) return 0.0f;
  if (linear >= 1.0f) return 1.0f;
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

namespace {

uint8_t code_of(float linear) { return uint8_t(std::lround(255.0f * srgb_encode(linear))); }

// The codes of (0, 1) by table. Positive floats are ordered as their bits are, so the bits with
// the low 15 cut off number buckets of floats, each spanning a factor 1 + 2^-8 of linear values.
// The code grows by at most 255 x f'(x) x = 255 x 1.055 / 2.4 x^(1/2.4) <= 112 per unit of
// ln x (12.92 x 255 x <= 10.4 on the linear part): less than half a code over a bucket, so a
// bucket holds at most one code's start, and a value's code is its bucket's first code or the
// next one.
constexpr int kBucketShift = 15;
constexpr uint32_t kOne = 0x3F800000;  // the bits of 1.0f

struct SrgbCodes {
  std::array<float, 256> start{};  // start[k]: the least float whose code is k
  std::array<uint8_t, (kOne >> kBucketShift) + 1> bucket{};  // the code of each bucket's least float

  SrgbCodes() {
    // Each code's start by bisection on the floats' bits; code_of never decreases (pow is
    // monotonic), which the test checks float by float around every start.
    for (int k = 1; k < 256; ++k) {
      uint32_t below = 0, at = kOne;  // code_of(below) < k <= code_of(at)
      while (at - below > 1) {
        const uint32_t middle = below + (at - below) / 2;
        (code_of(bit_cast<float>(middle)) >= k ? at : below) = middle;
      }
      start[size_t(k)] = bit_cast<float>(at);
    }
    for (uint32_t b = 0; b < bucket.size(); ++b) {
      const float least = bit_cast<float>(b << kBucketShift);
      bucket[b] = uint8_t(std::upper_bound(start.begin() + 1, start.end(), least) - start.begin() - 1);
    }
  }

  // The code of `linear`: its bucket's first code, or the next one from its start on.
  uint8_t operator()(float linear) const {
    if (!(linear > 0.0f)) return 0;
    if (linear >= 1.0f) return 255;
    const uint8_t code = bucket[bit_cast<uint32_t>(linear) >> kBucketShift];
    return code < 255 && linear >= start[size_t(code) + 1] ? uint8_t(code + 1) : code;
  }
};

const SrgbCodes& srgb_codes() {
  static const SrgbCodes codes;
  return codes;
}

}  // namespace

uint8_t srgb_byte(float linear) { return srgb_codes()(linear); }

void srgb_bytes(std::span<const Rgb> pixels, float scale, std::span<uint8_t> out) {
  const SrgbCodes& codes = srgb_codes();
  for (size_t i = 0; i < pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) out[3 * i + size_t(c)] = codes(pixels[i][c] * scale);
}

}  // namespace luz
