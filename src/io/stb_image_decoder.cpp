// PNG, JPEG and Radiance HDR through stb_image.
//
// stb_image's implementation is compiled here, for these three formats and from memory only:
// static, so that its symbols stay in this file (libstb, which ImGui brings along for
// stb_truetype, exports its own), and instrumented with the rest of Luz under the sanitizers and
// the fuzzer. Its failure reason is thread-local (STBI_THREAD_LOCAL under C++11). Its memory
// comes zeroed: a JPEG scan may name a Huffman table no DHT segment defined, which stb_image 2.27
// then reads as it found it in memory (a fuzzed file: an index past the table's end); zeroed, such
// a table decodes every code as symbol 0, within its arrays.
#include <cstdlib>
#define STBI_MALLOC(size) std::calloc(1, size)
#define STBI_REALLOC(pointer, size) std::realloc(pointer, size)
#define STBI_FREE(pointer) std::free(pointer)
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_HDR
#define STBI_NO_STDIO
#include <stb_image.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string_view>

#include <libdeflate.h>

#include "core/i18n.h"
#include "io/image_decoders.h"
#include "io/jpeg_segments.h"

namespace luz::io {
using i18n::tr;
using i18n::trf;

namespace {

struct StbFree {
  void operator()(void* pixels) const { stbi_image_free(pixels); }
};
using StbPixels = std::unique_ptr<void, StbFree>;

// The linear value of each 8-bit sRGB code: a table, since a large texture has tens of millions.
const std::array<float, 256>& srgb_codes() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (size_t code = 0; code < t.size(); ++code) t[code] = srgb_decode(float(code) / 255.0f);
    return t;
  }();
  return table;
}

// Channel k of pixel i as a linear float: the integer formats hold sRGB-encoded values.
float channel(const void* pixels, int channel_bytes, size_t at) {
  if (channel_bytes == 1) return srgb_codes()[static_cast<const unsigned char*>(pixels)[at]];
  if (channel_bytes == 2) return srgb_decode(float(static_cast<const uint16_t*>(pixels)[at]) / 65535.0f);
  return static_cast<const float*>(pixels)[at];
}

// Every pixel in the format the header promised: floats for HDR, 16-bit values for a 16-bit PNG,
// bytes for the rest; null when the decoder fails.
void* load(std::span<const unsigned char> bytes, int channel_bytes, int& width, int& height, int& channels) {
  const int length = int(bytes.size());
  if (channel_bytes == 4) return stbi_loadf_from_memory(bytes.data(), length, &width, &height, &channels, 0);
  if (channel_bytes == 2) return stbi_load_16_from_memory(bytes.data(), length, &width, &height, &channels, 0);
  return stbi_load_from_memory(bytes.data(), length, &width, &height, &channels, 0);
}

uint32_t big_endian(std::span<const unsigned char> bytes, size_t at) {
  return uint32_t(bytes[at]) << 24 | uint32_t(bytes[at + 1]) << 16 | uint32_t(bytes[at + 2]) << 8 | bytes[at + 3];
}

// The size a PNG's IHDR claims (ISO/IEC 15948, 11.2.2: the first chunk; width and height at bytes
// 16 and 20), for the message when stb_image refuses a header: it refuses more than 2^30 bytes of
// pixels without saying what size it read. A JPEG's is its frame header's (jpeg_segments.h).
std::optional<std::pair<int64_t, int64_t>> png_claimed_size(std::span<const unsigned char> bytes) {
  if (bytes.size() < 24 || std::string_view(reinterpret_cast<const char*>(bytes.data()) + 12, 4) != "IHDR")
    return std::nullopt;
  return std::pair{int64_t(big_endian(bytes, 16)), int64_t(big_endian(bytes, 20))};
}

// stb_image checks neither a PNG chunk's CRC-32 (ISO/IEC 15948, 5.3: over the chunk's type and
// data) nor whether the file reaches its IEND chunk, which libpng does: a damaged byte would
// otherwise become a wrong texel, a cut file a black band. Walks the chunks, each length
// checked against the bytes that remain.
std::string png_chunk_problem(std::span<const unsigned char> bytes) {
  for (size_t at = 8; at + 12 <= bytes.size();) {
    const size_t length = big_endian(bytes, at);
    if (length > bytes.size() - at - 12) return tr("the file is cut short");
    const std::string_view type(reinterpret_cast<const char*>(bytes.data()) + at + 4, 4);
    if (libdeflate_crc32(0, bytes.data() + at + 4, length + 4) != big_endian(bytes, at + 8 + length))
      return trf("chunk {} fails its CRC check", type);
    if (type == "IEND") return {};
    at += 12 + length;
  }
  return tr("the file is cut short");
}

// stb_image 2.27 decodes a Radiance scanline's run-length code (Ward, "Real Pixels", Graphics
// Gems II: per channel, a byte n > 128 then one value for a run of n - 128, else n values as they
// are) in a loop that only ends when the scanline is full: a count of 0 never fills it, and past
// the end of the bytes its reader returns zeros, so a cut or damaged file made it loop for ever;
// a cut file without run-length code it fills with black. This walks the pixels as stb_image
// will, on bytes whose header `stbi_info` read (`width` x `height`, within the caps), and names a
// cut or such a count; any other fault is left to stb_image to report.
std::string radiance_problem(std::span<const unsigned char> bytes, int width, int height) {
  // The pixels follow the resolution line, which follows the header's first empty line.
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  const size_t empty_line = text.find("\n\n");
  const size_t resolution_end = empty_line == std::string_view::npos ? text.npos : text.find('\n', empty_line + 2);
  if (resolution_end == std::string_view::npos) return tr("the file is cut short");
  const size_t flat_bytes = 4 * size_t(width) * size_t(height);  // RGBE, 4 bytes a pixel
  if (width < 8 || width >= 32768)  // too narrow or too wide for run-length code: flat scanlines
    return resolution_end + 1 + flat_bytes > bytes.size() ? tr("the file is cut short") : std::string();
  size_t at = resolution_end + 1;
  auto next = [&]() -> int { return at < bytes.size() ? bytes[at++] : (++at, 0); };
  for (int row = 0; row < height; ++row) {
    const size_t row_start = at;
    const int c1 = next(), c2 = next(), high = next();
    if (c1 != 2 || c2 != 2 || (high & 0x80) != 0)  // not run-length encoded: all pixels read flat from here
      return row_start + flat_bytes > bytes.size() ? tr("the file is cut short") : std::string();
    if (((high << 8) | next()) != width) return {};  // stb_image refuses the scanline
    for (int channel = 0; channel < 4; ++channel)
      for (int filled = 0; filled < width;) {
        const int count = next();
        if (count == 0) return at > bytes.size() ? tr("the file is cut short") : tr("a run of no pixels in a scanline");
        const int pixels = count > 128 ? count - 128 : count;
        if (pixels > width - filled) return {};  // stb_image refuses the run
        at += count > 128 ? 1 : size_t(count);
        filled += pixels;
      }
  }
  return at > bytes.size() ? tr("the file is cut short") : std::string();
}

}  // namespace

std::optional<Image> decode_with_stb(std::span<const unsigned char> bytes, ImageFormat format, std::string& error) {
  if (bytes.size() > size_t(std::numeric_limits<int>::max())) {  // stb_image counts bytes in an int
    error = unreadable(format, tr("larger than 2 GB"));
    return std::nullopt;
  }
  // The size the header claims, for the message when stb_image refuses the header.
  std::optional<std::pair<int64_t, int64_t>> claimed = format == ImageFormat::png ? png_claimed_size(bytes) : std::nullopt;
  if (format == ImageFormat::jpeg) {  // before stbi_info, which builds the tables before the frame header
    const JpegSegments segments = walk_jpeg_segments(bytes);
    if (!segments.huffman_problem.empty()) {
      error = unreadable(format, segments.huffman_problem);
      return std::nullopt;
    }
    // T.81 lets a frame header leave the height to a DNL segment after the first scan (B.2.5).
    if (segments.size && segments.size->second == 0) {
      error = unreadable(format, tr("its height comes after the first scan (a DNL segment), which Luz does not read"));
      return std::nullopt;
    }
    claimed = segments.size;
  }
  // The size the header claims, read without decoding (stb_image stops before it allocates).
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels)) {
    const std::string problem = claimed ? size_problem(claimed->first, claimed->second, 1, 0) : std::string();
    error = problem.empty() ? unreadable(format, tr("its header is cut or damaged")) : trf("header: {}", problem);
    return std::nullopt;
  }
  const bool hdr = format == ImageFormat::hdr;
  const int channel_bytes = hdr ? 4 : stbi_is_16_bit_from_memory(bytes.data(), int(bytes.size())) ? 2 : 1;
  if (const std::string size = size_problem(width, height, int64_t(channels) * channel_bytes, hdr ? 0 : bytes.size());
      !size.empty()) {
    error = trf("header: {}", size);
    return std::nullopt;
  }

  const std::string problem = hdr                           ? radiance_problem(bytes, width, height)
                              : format == ImageFormat::png ? png_chunk_problem(bytes)
                                                           : std::string();
  if (!problem.empty()) {
    error = unreadable(format, problem);
    return std::nullopt;
  }
  int read_width = 0, read_height = 0, read_channels = 0;
  const StbPixels pixels(load(bytes, channel_bytes, read_width, read_height, read_channels));
  if (!pixels) {
    const char* why = stbi_failure_reason();
    error = unreadable(format, why ? why : tr("the decoder gave no reason"));
    return std::nullopt;
  }
  if (read_width != width || read_height != height || read_channels < 1) {  // it reads the same header again
    error = unreadable(format, tr("the header and the pixels disagree"));
    return std::nullopt;
  }
  Image image(width, height);
  const size_t stride = size_t(read_channels);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const size_t at = i * stride;
    image.pixels[i] = read_channels >= 3 ? Rgb(channel(pixels.get(), channel_bytes, at),
                                               channel(pixels.get(), channel_bytes, at + 1),
                                               channel(pixels.get(), channel_bytes, at + 2))
                                         : Rgb(channel(pixels.get(), channel_bytes, at));
  }
  return image;
}

}  // namespace luz::io
