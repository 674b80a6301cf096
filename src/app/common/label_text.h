#pragma once
// Text drawn into an Image without any GL: a TrueType font rasterised by stb_truetype (Debian's
// libstb), for the labels of `luz render`'s side-by-side panes and any caption a handout needs.
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "core/image.h"

namespace luz::app {

// UTF-8 -> code points; a malformed byte becomes U+FFFD.
std::u32string decode_utf8(std::string_view text);

class LabelFont {
public:
  // DejaVu Sans (Debian's fonts-dejavu-core): Latin-1, Greek and the maths signs the formulas use.
  static std::filesystem::path default_file();

  // Throws luz::Error (file_missing / bad_value) naming the font file.
  explicit LabelFont(const std::filesystem::path& file = default_file());
  ~LabelFont();
  LabelFont(LabelFont&&) noexcept;

  bool has_glyph(char32_t code_point) const;

  struct Extent {
    int width = 0;   // pixels from the pen's start to the end of the last advance
    int ascent = 0;  // pixels above the baseline, and below it
    int descent = 0;
  };
  Extent measure(std::string_view utf8, float pixel_height) const;

  // Draws `utf8` with its top-left corner at (x, y), blending `colour` over the image by each
  // pixel's coverage; what falls outside the image is clipped.
  void draw(Image& image, int x, int y, std::string_view utf8, float pixel_height, Rgb colour) const;

private:
  struct Face;
  std::unique_ptr<Face> face_;
};

}  // namespace luz::app
