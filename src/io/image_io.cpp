#include "io/image_io.h"

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstring>
#include <cstdint>
#include <fstream>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "core/error.h"
#include "core/i18n.h"
#include "io/atomic_file.h"
#include "io/image_decoders.h"
#include "io/image_encoders.h"

namespace luz::io {
namespace fs = std::filesystem;
using i18n::tr;
using i18n::trf;

namespace {

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// 8-bit sRGB of SCENES.md "Image output".
std::vector<uint8_t> encode_png_pixels(const Image& image, float exposure) {
  const float scale = std::exp2(exposure);
  std::vector<uint8_t> bytes(image.pixels.size() * 3);
  srgb_bytes(image.pixels, scale, bytes);
  return bytes;
}

// The whole file: the decoders read the header's claimed size from these bytes, then the pixels.
std::vector<unsigned char> read_file(const fs::path& path) {
  std::error_code size_error;
  const uintmax_t size = fs::file_size(path, size_error);
  std::ifstream file(path, std::ios::binary);
  if (size_error || !file)
    throw Error(ErrorKind::file_missing, trf("{}: cannot be read: {}", path.string(),
                                             size_error ? size_error.message() : std::strerror(errno)));
  std::vector<unsigned char> bytes(static_cast<size_t>(size));
  file.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  if (size_t(file.gcount()) != bytes.size())
    throw Error(ErrorKind::file_missing, trf("{}: cannot be read: {}", path.string(), std::strerror(errno)));
  return bytes;
}

}  // namespace

bool is_supported_output(const fs::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".png" || ext == ".exr";
}

bool is_png_output(const fs::path& path) { return lower_extension(path) == ".png"; }

void write_image(const Image& image, const fs::path& path, float exposure) {
  if (!is_supported_output(path))
    throw Error(ErrorKind::usage, trf("{}: output must be .png or .exr", path.string()));
  const bool exr = lower_extension(path) == ".exr";
  // The last guard for every renderer: a NaN or infinite radiance is a bug upstream, and a file
  // that hides it (PNG clamps it to black or white) would only move the surprise elsewhere.
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const Rgb& c = image.pixels[i];
    if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b))
      throw Error(ErrorKind::output,
                  trf("{}: not written: pixel ({}, {}) is not finite ({}, {}, {})", path.string(),
                      i % size_t(std::max(image.width, 1)), i / size_t(std::max(image.width, 1)),
                      c.r, c.g, c.b));
  }
  const std::string failure = write_atomically(path, [&] {
    return exr ? encode_exr(image) : encode_png(encode_png_pixels(image, exposure), image.width, image.height);
  });
  if (!failure.empty()) throw Error(ErrorKind::output, trf("{}: cannot write: {}", path.string(), failure));
}

Image read_image(const fs::path& path) {
  if (!fs::exists(path))
    throw Error(ErrorKind::file_missing, trf("{}: no such file", path.string()));
  const std::vector<unsigned char> bytes = read_file(path);
  const std::optional<ImageFormat> format = image_format(bytes);
  if (!format)
    throw Error(ErrorKind::bad_value,
                trf("{}: not an image: {}", path.string(), tr("Luz reads PNG, JPEG, Radiance HDR and OpenEXR")));
  std::string error;
  std::optional<Image> image = decode_image(bytes, *format, error);
  if (!image) throw Error(ErrorKind::bad_value, fmt::format("{}: {}", path.string(), error));
  return std::move(*image);
}

std::optional<Texture> decode_texture(const std::vector<unsigned char>& bytes,
                                      const std::string& name, std::string& error) {
  // glTF embeds PNG or JPEG only (glTF 2.0, "Images"): anything else is refused by its magic number.
  const std::optional<ImageFormat> format = image_format(bytes);
  if (format != ImageFormat::png && format != ImageFormat::jpeg) {
    error = tr("not a PNG or JPEG image");
    return std::nullopt;
  }
  std::optional<Image> image = decode_image(bytes, *format, error);
  if (!image) return std::nullopt;
  Texture texture;
  texture.name = name;
  texture.width = image->width;
  texture.height = image->height;
  texture.texels = std::move(image->pixels);
  return texture;
}

}  // namespace luz::io
