#include "io/image_io.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstring>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <random>

#include <signal.h>
#include <fcntl.h>
#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include "core/error.h"
#include "core/i18n.h"

namespace luz::io {
namespace fs = std::filesystem;
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
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      bytes[3 * i + c] = uint8_t(std::lround(255.0f * srgb_encode(image.pixels[i][c] * scale)));
  return bytes;
}

// A name beside the target, with the same extension so OpenImageIO picks the same format.
fs::path temporary_beside(const fs::path& path) {
  std::random_device random;
  const std::string stem = "." + path.stem().string() + fmt::format(".tmp{:08x}", random());
  return path.parent_path() / (stem + path.extension().string());
}

// While the temporary file exists, SIGINT and SIGTERM remove it before the process ends as it
// would have (the previous disposition is restored and the signal raised again). The handler
// only calls async-signal-safe functions (unlink, sigaction, raise) on a fixed buffer.
char g_temporary[4096];
struct sigaction g_previous_int, g_previous_term;

extern "C" void remove_temporary_and_reraise(int signal_number) {
  unlink(g_temporary);
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
  raise(signal_number);
}

class TemporaryGuard {
 public:
  explicit TemporaryGuard(const fs::path& temporary) {
    const std::string name = temporary.string();
    armed_ = name.size() < sizeof g_temporary;
    if (!armed_) return;
    std::memcpy(g_temporary, name.c_str(), name.size() + 1);
    struct sigaction action {};
    action.sa_handler = remove_temporary_and_reraise;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &g_previous_int);
    sigaction(SIGTERM, &action, &g_previous_term);
  }
  ~TemporaryGuard() {
    if (!armed_) return;
    sigaction(SIGINT, &g_previous_int, nullptr);
    sigaction(SIGTERM, &g_previous_term, nullptr);
  }
  TemporaryGuard(const TemporaryGuard&) = delete;
  TemporaryGuard& operator=(const TemporaryGuard&) = delete;

 private:
  bool armed_ = false;
};

// libpng's default error handler, which OpenImageIO's PNG reader keeps, prints "libpng error:
// ..." on stderr before OpenImageIO reports the same problem to us; Luz prints its own one-line
// message instead, so stderr is pointed at /dev/null while an image is decoded.
class QuietStderr {
 public:
  QuietStderr() {
    std::fflush(stderr);
    saved_ = dup(STDERR_FILENO);
    const int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved_ >= 0 && null >= 0) dup2(null, STDERR_FILENO);
    if (null >= 0) close(null);
  }
  ~QuietStderr() {
    if (saved_ < 0) return;
    dup2(saved_, STDERR_FILENO);
    close(saved_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_ = -1;
};

// OpenImageIO's messages can span lines ("PNG read error: ...\nPNG library error"): one line.
std::string one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (size_t at; (at = text.find('\n')) != std::string::npos;) text.replace(at, 1, "; ");
  return text;
}

// OpenImageIO keeps 8/16-bit files in their encoded values; everything Luz computes is linear.
bool is_integer_format(const OIIO::ImageSpec& spec) {
  return spec.format == OIIO::TypeDesc::UINT8 || spec.format == OIIO::TypeDesc::UINT16;
}

// Reads an opened input into linear RGB: grey is replicated, alpha dropped, 8/16-bit decoded.
// The size comes from the header, which costs nothing to read; it is checked against the caps
// before a byte of pixels is allocated (a 100-byte PNG can claim 65535 x 65535).
std::optional<Image> read_rgb(OIIO::ImageInput& input, std::string& error) {
  const OIIO::ImageSpec& spec = input.spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
    error = "image has no pixels";
    return std::nullopt;
  }
  if (spec.width > kMaxImageSide || spec.height > kMaxImageSide ||
      int64_t(spec.width) * spec.height > kMaxImagePixels) {
    error = trf("{} x {} pixels is beyond the limit of {} per side and {} in all", spec.width,
                        spec.height, kMaxImageSide, kMaxImagePixels);
    return std::nullopt;
  }
  if (spec.nchannels > 16) {
    error = trf("{} channels is beyond the limit of 16", spec.nchannels);
    return std::nullopt;
  }
  std::vector<float> data(size_t(spec.width) * spec.height * spec.nchannels);
  bool read = false;
  {
    const QuietStderr quiet;
    read = input.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data());
  }
  if (!read) {
    error = one_line(input.geterror());
    return std::nullopt;
  }
  const bool decode = is_integer_format(spec);
  Image image(spec.width, spec.height);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const float* p = &data[i * spec.nchannels];
    Rgb c = spec.nchannels >= 3 ? Rgb(p[0], p[1], p[2]) : Rgb(p[0]);
    if (decode) c = Rgb(srgb_decode(c.r), srgb_decode(c.g), srgb_decode(c.b));
    image.pixels[i] = c;
  }
  return image;
}

}  // namespace

bool is_supported_output(const fs::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".png" || ext == ".exr";
}

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
  const fs::path temporary = temporary_beside(path);
  const TemporaryGuard guard(temporary);
  auto fail = [&](const std::string& why) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    return Error(ErrorKind::output, trf("{}: cannot write: {}", path.string(), why));
  };

  auto output = OIIO::ImageOutput::create(temporary.string());
  if (!output) throw fail(OIIO::geterror());
  OIIO::ImageSpec spec(image.width, image.height, 3,
                       exr ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (exr) spec.attribute("compression", "zip");
  if (!output->open(temporary.string(), spec)) throw fail(output->geterror());
  bool written = false;
  if (exr) {
    written = output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
  } else {
    const std::vector<uint8_t> bytes = encode_png_pixels(image, exposure);
    written = output->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  }
  if (!written || !output->close()) throw fail(output->geterror());
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) throw fail(error.message());
}

Image read_image(const fs::path& path) {
  if (!fs::exists(path))
    throw Error(ErrorKind::file_missing, trf("{}: no such file", path.string()));
  std::unique_ptr<OIIO::ImageInput> input;
  {
    const QuietStderr quiet;
    input = OIIO::ImageInput::open(path.string());
  }
  if (!input)
    throw Error(ErrorKind::bad_value,
                trf("{}: not an image: {}", path.string(), one_line(OIIO::geterror())));
  std::string error;
  std::optional<Image> image = read_rgb(*input, error);
  if (!image) throw Error(ErrorKind::bad_value, fmt::format("{}: {}", path.string(), error));
  return std::move(*image);
}

std::optional<Texture> decode_texture(const std::vector<unsigned char>& bytes,
                                      const std::string& name, std::string& error) {
  // OpenImageIO picks a reader by the file name; a memory proxy carries the bytes. The
  // extension only chooses which reader tries first: each one checks the magic number.
  const bool png = bytes.size() >= 4 && bytes[0] == 0x89 && bytes[1] == 'P';
  const std::string pseudo_name = png ? "texture.png" : "texture.jpg";
  OIIO::Filesystem::IOMemReader proxy(const_cast<unsigned char*>(bytes.data()), bytes.size());
  std::unique_ptr<OIIO::ImageInput> input;
  {
    const QuietStderr quiet;
    input = OIIO::ImageInput::open(pseudo_name, nullptr, &proxy);
  }
  if (!input) {
    error = "not a PNG or JPEG image";
    (void)OIIO::geterror();  // clear OpenImageIO's pending message
    return std::nullopt;
  }
  std::optional<Image> image = read_rgb(*input, error);
  if (!image) return std::nullopt;
  Texture texture;
  texture.name = name;
  texture.width = image->width;
  texture.height = image->height;
  texture.texels = std::move(image->pixels);
  return texture;
}

}  // namespace luz::io
