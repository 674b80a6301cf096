#include "io/image_decoders.h"

#include <algorithm>
#include <initializer_list>

#include "core/i18n.h"
#include "io/image_io.h"

namespace luz::io {
using i18n::tr;
using i18n::trf;

namespace {

// No PNG or JPEG holds more than this many bytes of pixels per byte of file: deflate's best
// ratio is 1032:1 (RFC 1951's longest match, 258 bytes, in at most 2 bits), and a JPEG spends at
// least a bit per 8 x 8 block of each component (ITU T.81), 4096:1 with 2x2 chroma subsampling
// of three 8-bit components being out of reach too. A header claiming more is a lie that would
// only cost an allocation and a failed decode.
constexpr int64_t kMaxCompressionRatio = 4096;

bool starts_with(std::span<const unsigned char> bytes, std::initializer_list<unsigned char> magic) {
  return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
}

bool starts_with(std::span<const unsigned char> bytes, std::string_view magic) {
  return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
}

}  // namespace

// The signatures of ISO/IEC 15948 (PNG), ITU T.81's SOI followed by a marker (JPEG), the
// Radiance program's header line (stb_image reads both of its spellings) and OpenEXR's magic
// number 20000630, little-endian.
std::optional<ImageFormat> image_format(std::span<const unsigned char> bytes) {
  if (starts_with(bytes, {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'})) return ImageFormat::png;
  if (starts_with(bytes, {0xff, 0xd8, 0xff})) return ImageFormat::jpeg;
  if (starts_with(bytes, "#?RADIANCE\n") || starts_with(bytes, "#?RGBE\n")) return ImageFormat::hdr;
  if (starts_with(bytes, {0x76, 0x2f, 0x31, 0x01})) return ImageFormat::exr;
  return std::nullopt;
}

const char* format_label(ImageFormat format) {
  switch (format) {
    case ImageFormat::png: return "PNG";
    case ImageFormat::jpeg: return "JPEG";
    case ImageFormat::hdr: return "Radiance HDR";
    case ImageFormat::exr: return "OpenEXR";
  }
  return "";
}

std::optional<Image> decode_image(std::span<const unsigned char> bytes, ImageFormat format, std::string& error) {
  return format == ImageFormat::exr ? decode_exr(bytes, error) : decode_with_stb(bytes, format, error);
}

std::string size_problem(int64_t width, int64_t height, int64_t pixel_bytes, uintmax_t encoded_bytes) {
  if (width <= 0 || height <= 0) return tr("image has no pixels");
  if (width > kMaxImageSide || height > kMaxImageSide || width * height > kMaxImagePixels)
    return trf("{} x {} pixels is beyond the limit of {} per side and {} in all", width, height, kMaxImageSide,
               kMaxImagePixels);
  if (encoded_bytes > 0 && width * height * pixel_bytes / kMaxCompressionRatio > int64_t(encoded_bytes))
    return trf("{} x {} pixels cannot come from {} bytes (more than {}:1; the file is cut or its header lies)", width,
               height, encoded_bytes, kMaxCompressionRatio);
  return {};
}

std::string unreadable(ImageFormat format, const std::string& why) {
  return trf("not a readable {} image: {}", format_label(format), why);
}

}  // namespace luz::io
