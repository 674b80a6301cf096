// OpenEXR through tinyexr: its version and header are parsed first, the data window refused
// against the caps, then the pixels of the single part decoded, half channels as floats.
#include <tinyexr.h>

#include <algorithm>
#include <array>
#include <cstring>

#include "core/i18n.h"
#include "io/image_decoders.h"

namespace luz::io {
using i18n::tr;
using i18n::trf;

namespace {

constexpr int kMaxChannels = 16;

// tinyexr's header and image, freed when they go.
struct ExrHeader {
  EXRHeader header;
  ExrHeader() { InitEXRHeader(&header); }
  ~ExrHeader() { FreeEXRHeader(&header); }
  ExrHeader(const ExrHeader&) = delete;
  ExrHeader& operator=(const ExrHeader&) = delete;
};

// Freed only once loaded: when LoadEXRImageFromMemory fails, tinyexr 1.0.1 has freed what it
// allocated already, and leaves the dangling pointers in the image.
struct ExrImage {
  EXRImage image;
  bool loaded = false;
  ExrImage() { InitEXRImage(&image); }
  ~ExrImage() {
    if (loaded) FreeEXRImage(&image);
  }
  ExrImage(const ExrImage&) = delete;
  ExrImage& operator=(const ExrImage&) = delete;
};

// tinyexr's message for a failure (allocated by it, freed here) on one line, or its error code.
std::string failure(const char* message, int code) {
  std::string text = message ? std::string(message) : trf("error {}", code);
  if (message) FreeEXRErrorMessage(message);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

// The channels that make the picture: R, G and B; else Y (luminance); else a file's only channel.
std::optional<std::array<int, 3>> rgb_channels(const EXRHeader& header) {
  int r = -1, g = -1, b = -1, y = -1;
  for (int c = 0; c < header.num_channels; ++c) {
    const char* name = header.channels[c].name;
    if (std::strcmp(name, "R") == 0) r = c;
    if (std::strcmp(name, "G") == 0) g = c;
    if (std::strcmp(name, "B") == 0) b = c;
    if (std::strcmp(name, "Y") == 0) y = c;
  }
  if (r >= 0 && g >= 0 && b >= 0) return std::array{r, g, b};
  if (y >= 0) return std::array{y, y, y};
  if (header.num_channels == 1) return std::array{0, 0, 0};
  return std::nullopt;
}

// Channel c's value at index `at` of its plane: floats (half is asked for as float), or the
// unsigned integers a uint channel holds, taken as numbers.
float value(const EXRHeader& header, unsigned char* const* planes, int c, size_t at) {
  if (header.requested_pixel_types[c] == TINYEXR_PIXELTYPE_UINT)
    return float(reinterpret_cast<const unsigned int*>(planes[c])[at]);
  return reinterpret_cast<const float*>(planes[c])[at];
}

// The decoded planes into `image`: whole planes for a scanline file; for a tiled one the tiles of
// its first level, each tile_size_x wide in memory, those of the right and bottom edges cut by
// the data window.
void copy_pixels(const EXRHeader& header, const EXRImage& exr, const std::array<int, 3>& rgb, Image& image) {
  auto pixel = [&](unsigned char* const* planes, size_t at) {
    return Rgb(value(header, planes, rgb[0], at), value(header, planes, rgb[1], at), value(header, planes, rgb[2], at));
  };
  if (!header.tiled) {
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = pixel(exr.images, i);
    return;
  }
  for (int t = 0; t < exr.num_tiles; ++t) {
    const EXRTile& tile = exr.tiles[t];
    for (int j = 0; j < header.tile_size_y; ++j)
      for (int i = 0; i < header.tile_size_x; ++i) {
        const int x = tile.offset_x * header.tile_size_x + i, y = tile.offset_y * header.tile_size_y + j;
        if (x < image.width && y < image.height)
          image.at(x, y) = pixel(tile.images, size_t(i) + size_t(j) * size_t(header.tile_size_x));
      }
  }
}

}  // namespace

std::optional<Image> decode_exr(std::span<const unsigned char> bytes, std::string& error) {
  EXRVersion version;
  if (const int code = ParseEXRVersionFromMemory(&version, bytes.data(), bytes.size()); code != TINYEXR_SUCCESS) {
    error = unreadable(ImageFormat::exr, trf("no version field (error {})", code));
    return std::nullopt;
  }
  if (version.multipart || version.non_image) {
    error = unreadable(ImageFormat::exr, tr("multi-part and deep files are not read"));
    return std::nullopt;
  }
  ExrHeader header;
  const char* message = nullptr;
  if (const int code = ParseEXRHeaderFromMemory(&header.header, &version, bytes.data(), bytes.size(), &message);
      code != TINYEXR_SUCCESS) {
    error = unreadable(ImageFormat::exr, failure(message, code));
    return std::nullopt;
  }
  const EXRBox2i& window = header.header.data_window;
  const int64_t width = int64_t(window.max_x) - window.min_x + 1, height = int64_t(window.max_y) - window.min_y + 1;
  if (const std::string problem = size_problem(width, height, 4 * int64_t(header.header.num_channels), 0);
      !problem.empty()) {
    error = trf("header: {}", problem);
    return std::nullopt;
  }
  if (header.header.num_channels > kMaxChannels) {
    error = trf("{} channels is beyond the limit of {}", header.header.num_channels, kMaxChannels);
    return std::nullopt;
  }
  const std::optional<std::array<int, 3>> rgb = rgb_channels(header.header);
  if (!rgb) {
    error = unreadable(ImageFormat::exr, tr("no R, G and B channels, no Y channel"));
    return std::nullopt;
  }
  for (int c = 0; c < header.header.num_channels; ++c)
    if (header.header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF)
      header.header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;

  ExrImage exr;
  if (const int code = LoadEXRImageFromMemory(&exr.image, &header.header, bytes.data(), bytes.size(), &message);
      code != TINYEXR_SUCCESS) {
    error = unreadable(ImageFormat::exr, failure(message, code));
    return std::nullopt;
  }
  exr.loaded = true;
  if (exr.image.width != width || exr.image.height != height) {
    error = unreadable(ImageFormat::exr, tr("the header and the pixels disagree"));
    return std::nullopt;
  }
  Image image(static_cast<int>(width), static_cast<int>(height));
  copy_pixels(header.header, exr.image, *rgb, image);
  return image;
}

}  // namespace luz::io
