#pragma once
// A float RGB image of linear radiance, row 0 at the top.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/color.h"

namespace luz {

// Allocates without writing: a vector of it sized n leaves its n elements as the memory held
// them (a construction with a value is the standard one). A renderer that writes every pixel of
// a picture from many threads then neither pays for clearing it first nor has one thread touch
// all of a fresh picture's pages.
template <typename T>
struct UnclearedAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = UnclearedAllocator<U>;
  };
  using std::allocator<T>::allocator;
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;  // default-initialised: nothing written for plain values
  }
};

// The pixels of a picture or a texture, row by row.
using Pixels = std::vector<Rgb, UnclearedAllocator<Rgb>>;

struct Image {
  int width = 0;
  int height = 0;
  Pixels pixels;

  // Tells the constructor to leave the pixels unwritten: the caller writes every one.
  struct Uncleared {};

  Image() = default;
  Image(int w, int h, Rgb fill = Rgb(0.0f)) : width(w), height(h), pixels(size_t(w) * h, fill) {}
  Image(int w, int h, Uncleared) : width(w), height(h), pixels(size_t(w) * h) {}

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
