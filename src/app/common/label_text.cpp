#include "app/common/label_text.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <vector>

#include <fmt/format.h>
#include <stb_truetype.h>

#include "app/common/i18n.h"
#include "core/error.h"

namespace luz::app {
namespace fs = std::filesystem;

std::u32string decode_utf8(std::string_view text) {
  std::u32string out;
  for (size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const int length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xe ? 3 : (lead >> 3) == 0x1e ? 4 : 0;
    char32_t code = length == 1 ? lead : length == 2 ? lead & 0x1f : length == 3 ? lead & 0x0f : lead & 0x07;
    bool valid = length > 0 && i + size_t(length) <= text.size();
    for (int k = 1; valid && k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + size_t(k)]);
      valid = (next >> 6) == 0x2;
      code = code << 6 | (next & 0x3f);
    }
    out.push_back(valid ? code : U'\uFFFD');
    i += valid ? size_t(length) : 1;
  }
  return out;
}

struct LabelFont::Face {
  std::vector<unsigned char> bytes;  // stb_truetype reads the font in place
  stbtt_fontinfo info{};
};

fs::path LabelFont::default_file() { return "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"; }

LabelFont::LabelFont(const fs::path& file) : face_(std::make_unique<Face>()) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw Error(ErrorKind::file_missing,
                trf("{}: the label font cannot be read (Debian: fonts-dejavu-core)", file.string()));
  face_->bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  const int offset = stbtt_GetFontOffsetForIndex(face_->bytes.data(), 0);
  if (offset < 0 || !stbtt_InitFont(&face_->info, face_->bytes.data(), offset))
    throw Error(ErrorKind::bad_value, trf("{}: not a TrueType font", file.string()));
}

LabelFont::~LabelFont() = default;
LabelFont::LabelFont(LabelFont&&) noexcept = default;

bool LabelFont::has_glyph(char32_t code_point) const {
  return stbtt_FindGlyphIndex(&face_->info, int(code_point)) != 0;
}

LabelFont::Extent LabelFont::measure(std::string_view utf8, float pixel_height) const {
  const float scale = stbtt_ScaleForPixelHeight(&face_->info, pixel_height);
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&face_->info, &ascent, &descent, &gap);
  float pen = 0.0f;
  const std::u32string text = decode_utf8(utf8);
  for (size_t i = 0; i < text.size(); ++i) {
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&face_->info, int(text[i]), &advance, &bearing);
    pen += scale * float(advance);
    if (i + 1 < text.size()) pen += scale * float(stbtt_GetCodepointKernAdvance(&face_->info, int(text[i]), int(text[i + 1])));
  }
  return {int(std::ceil(pen)), int(std::ceil(scale * float(ascent))), int(std::ceil(-scale * float(descent)))};
}

void LabelFont::draw(Image& image, int x, int y, std::string_view utf8, float pixel_height, Rgb colour) const {
  const float scale = stbtt_ScaleForPixelHeight(&face_->info, pixel_height);
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&face_->info, &ascent, &descent, &gap);
  const int baseline = y + int(std::ceil(scale * float(ascent)));
  float pen = float(x);
  const std::u32string text = decode_utf8(utf8);
  std::vector<unsigned char> coverage;
  for (size_t i = 0; i < text.size(); ++i) {
    const int code = int(text[i]);
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    const float shift = pen - std::floor(pen);  // the sub-pixel start keeps the spacing even
    stbtt_GetCodepointBitmapBoxSubpixel(&face_->info, code, scale, scale, shift, 0.0f, &x0, &y0, &x1, &y1);
    const int w = x1 - x0, h = y1 - y0;
    if (w > 0 && h > 0) {
      coverage.assign(size_t(w) * size_t(h), 0);
      stbtt_MakeCodepointBitmapSubpixel(&face_->info, coverage.data(), w, h, w, scale, scale, shift, 0.0f, code);
      const int left = int(std::floor(pen)) + x0, top = baseline + y0;
      for (int row = 0; row < h; ++row)
        for (int column = 0; column < w; ++column) {
          const int px = left + column, py = top + row;
          if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
          const float a = float(coverage[size_t(row) * size_t(w) + size_t(column)]) / 255.0f;
          Rgb& pixel = image.at(px, py);
          pixel = pixel * (1.0f - a) + colour * a;
        }
    }
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&face_->info, code, &advance, &bearing);
    pen += scale * float(advance);
    if (i + 1 < text.size()) pen += scale * float(stbtt_GetCodepointKernAdvance(&face_->info, code, int(text[i + 1])));
  }
}

}  // namespace luz::app
