#pragma once
// A float RGB image of linear radiance, row 0 at the top.
#include <cstdint>
#include <span>
#include <vector>

#include "core/color.h"

namespace luz {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<Rgb> pixels;

  Image() = default;
  Image(int w, int h, Rgb fill = Rgb(0.0f)) : width(w), height(h), pixels(size_t(w) * h, fill) {}

  Rgb& at(int x, int y) { return pixels[size_t(y) * width + x]; }
  const Rgb& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

// PNG encoding of SCENES.md: radiance x 2^exposure, then the sRGB transfer curve, clamped.
float srgb_encode(float linear);
float srgb_decode(float encoded);
// The 8-bit code PNG stores: lround(255 srgb_encode(linear)), read from a table of the values
// where each code starts instead of computed with pow (a 1024x1024 picture has 3 million values).
uint8_t srgb_byte(float linear);
// The same for every channel of `pixels` x `scale`, into out[3 i + c] (out.size() = 3 x pixels).
void srgb_bytes(std::span<const Rgb> pixels, float scale, std::span<uint8_t> out);

}  // namespace luz
