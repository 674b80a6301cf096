#include "io/image_io.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cerrno>
#include <cstring>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <random>

#include <dlfcn.h>
#include <signal.h>
#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>

#include "core/error.h"
#include "core/i18n.h"
#include "io/image_encoders.h"
#include "io/image_reader_plugin.h"

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

// A name beside the target, with the same extension.
fs::path temporary_beside(const fs::path& path) {
  std::random_device random;
  return path.parent_path() /
         fmt::format(".{}.tmp{:08x}{}", path.stem().string(), random(), path.extension().string());
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

// No PNG or JPEG holds more than this many bytes of pixels per byte of file: deflate's best
// ratio is 1032:1 (RFC 1951's longest match, 258 bytes, in at most 2 bits), and a JPEG spends at
// least a bit per 8 x 8 block of each component (ITU T.81), 4096:1 with 2x2 chroma subsampling
// of three 8-bit components being out of reach too. A header claiming more is a lie that would
// only cost an allocation and a failed decode.
constexpr int64_t kMaxCompressionRatio = 4096;

// The caps on an image of width x height with `pixel_bytes` bytes a pixel, and for a PNG or
// JPEG of `encoded_bytes` (0: not one) what so many bytes can hold: an empty string when it passes.
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

uint32_t big_endian(std::span<const unsigned char> b, size_t at, int bytes) {
  uint32_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | b[at + size_t(i)];
  return v;
}

// The width and height a PNG's IHDR or a JPEG's frame header (SOFn) claims, read by us before
// OpenImageIO opens the file: its JPEG reader allocates for the claimed size as it opens (2 GB
// for a 140-byte file claiming 62978 x 31234). The JPEG's markers are walked from the start
// (ITU T.81, B.1.1: FF xx, then a 2-byte length for all but SOI, RSTn and TEM); bytes that are
// not a marker where one should be are skipped up to the next FF, as libjpeg resynchronises.
std::optional<std::pair<uint32_t, uint32_t>> claimed_size(std::span<const unsigned char> b) {
  static constexpr unsigned char png[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (b.size() >= 24 && std::equal(std::begin(png), std::end(png), b.begin()))
    return std::pair{big_endian(b, 16, 4), big_endian(b, 20, 4)};
  if (b.size() < 4 || b[0] != 0xff || b[1] != 0xd8) return std::nullopt;
  size_t at = 2;
  while (at + 1 < b.size()) {
    if (b[at] != 0xff) {  // garbage where a marker should be
      ++at;
      continue;
    }
    const unsigned char marker = b[at + 1];
    if (marker == 0xff) {  // a fill byte
      ++at;
      continue;
    }
    if (marker == 0x00 || marker == 0xd8 || marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) {
      at += 2;
      continue;
    }
    if (marker == 0xd9 || marker == 0xda || at + 4 > b.size()) return std::nullopt;  // no frame header first
    const bool frame = marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
    if (frame) return at + 9 <= b.size() ? std::optional{std::pair{big_endian(b, at + 7, 2), big_endian(b, at + 5, 2)}}
                                         : std::nullopt;
    at += 2 + big_endian(b, at + 2, 2);
  }
  return std::nullopt;
}

// The header check before OpenImageIO sees the bytes (the first of the file suffice): one byte a
// pixel at least, of a file of `file_bytes`.
std::string header_problem(std::span<const unsigned char> head, uintmax_t file_bytes) {
  const auto size = claimed_size(head);
  const std::string problem = size ? size_problem(size->first, size->second, 1, file_bytes) : std::string();
  return problem.empty() ? problem : trf("header: {}", problem);
}

// ---- The reader plugin (image_reader_plugin.h) ----
// Beside the program (an installed or copied build), else where this build put it.
std::filesystem::path reader_plugin_path() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path beside = exe.parent_path() / LUZ_IMAGE_READER_NAME;
    if (fs::exists(beside, ec)) return beside;
  }
  return LUZ_IMAGE_READER_PATH;
}

// Opened once, on the first image read, and kept for the life of the process.
const LuzImageReader& image_reader() {
  static std::string failure;
  static const LuzImageReader* reader = [] () -> const LuzImageReader* {
    const fs::path path = reader_plugin_path();
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    const auto entry = module ? reinterpret_cast<LuzImageReaderEntry>(dlsym(module, "luz_image_reader")) : nullptr;
    if (!entry) {
      const char* why = dlerror();  // names the file
      failure = trf("cannot load the image reader: {}", why ? why : path.string() + ": no luz_image_reader");
      return nullptr;
    }
    return entry();
  }();
  if (!reader) throw Error(ErrorKind::file_missing, failure);
  return *reader;
}

// An image opened through the plugin, closed when it goes.
class OpenedImage {
 public:
  OpenedImage(const LuzImageReader& reader, void* handle) : reader_(reader), handle_(handle) {}
  ~OpenedImage() {
    if (handle_) reader_.close(handle_);
  }
  OpenedImage(const OpenedImage&) = delete;
  OpenedImage& operator=(const OpenedImage&) = delete;
  LuzImageHeader header() const {
    LuzImageHeader h;
    reader_.header(handle_, &h);
    return h;
  }
  bool read(void* pixels, std::string& error) const {
    char message[1024] = "";
    const QuietStderr quiet;
    const bool read = reader_.read(handle_, pixels, message, sizeof message) != 0;
    if (!read) error = one_line(message);
    return read;
  }

 private:
  const LuzImageReader& reader_;
  void* handle_;
};

// Reads an opened image into linear RGB: grey is replicated, alpha dropped, 8/16-bit decoded.
// The size comes from the header, which costs nothing to read; it is checked against the caps
// before a byte of pixels is allocated (a 100-byte PNG can claim 65535 x 65535), and for a PNG
// or JPEG of `encoded_bytes` against what so many bytes can hold.
std::optional<Image> read_rgb(const OpenedImage& input, uintmax_t encoded_bytes, std::string& error) {
  const LuzImageHeader spec = input.header();
  if (spec.channels <= 0) {
    error = tr("image has no pixels");
    return std::nullopt;
  }
  error = size_problem(spec.width, spec.height, int64_t(spec.channels) * spec.bytes_per_channel,
                       spec.png_or_jpeg ? encoded_bytes : 0);
  if (!error.empty()) return std::nullopt;
  if (spec.channels > 16) {
    error = trf("{} channels is beyond the limit of 16", spec.channels);
    return std::nullopt;
  }
  const size_t bytes = size_t(spec.bytes_per_channel);
  std::vector<unsigned char> data(size_t(spec.width) * size_t(spec.height) * size_t(spec.channels) * bytes);
  if (!input.read(data.data(), error)) return std::nullopt;
  // Channel k of pixel i as a linear float: the integer formats hold sRGB-encoded values.
  auto value = [&](size_t i, int k) {
    const size_t at = i * size_t(spec.channels) + size_t(k);
    if (bytes == 1) return srgb_decode(float(data[at]) / 255.0f);
    if (bytes == 2) {
      uint16_t v;
      std::memcpy(&v, &data[2 * at], sizeof v);
      return srgb_decode(float(v) / 65535.0f);
    }
    float v;
    std::memcpy(&v, &data[4 * at], sizeof v);
    return v;
  };
  Image image(spec.width, spec.height);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = spec.channels >= 3 ? Rgb(value(i, 0), value(i, 1), value(i, 2)) : Rgb(value(i, 0));
  return image;
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
  const fs::path temporary = temporary_beside(path);
  const TemporaryGuard guard(temporary);
  auto fail = [&](const std::string& why) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    return Error(ErrorKind::output, trf("{}: cannot write: {}", path.string(), why));
  };

  // The temporary is opened first: a folder that cannot be written to fails before the encoding.
  std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
  if (!file) throw fail(std::strerror(errno));
  std::string encoded;
  try {
    encoded = exr ? encode_exr(image) : encode_png(encode_png_pixels(image, exposure), image.width, image.height);
  } catch (const std::exception& e) {  // out of memory
    throw fail(e.what());
  }
  file.write(encoded.data(), std::streamsize(encoded.size()));
  file.close();
  if (!file) throw fail(std::strerror(errno));
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) throw fail(error.message());
}

Image read_image(const fs::path& path) {
  if (!fs::exists(path))
    throw Error(ErrorKind::file_missing, trf("{}: no such file", path.string()));
  std::error_code no_size;
  const uintmax_t file_bytes = fs::file_size(path, no_size);
  {
    std::vector<unsigned char> head(65536);
    std::ifstream file(path, std::ios::binary);
    file.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size()));
    head.resize(size_t(file.gcount()));
    if (const std::string problem = header_problem(head, file_bytes); !problem.empty())
      throw Error(ErrorKind::bad_value, fmt::format("{}: {}", path.string(), problem));
  }
  const LuzImageReader& reader = image_reader();
  char message[1024] = "";
  void* handle = nullptr;
  {
    const QuietStderr quiet;
    handle = reader.open_file(path.c_str(), message, sizeof message);
  }
  if (!handle) throw Error(ErrorKind::bad_value, trf("{}: not an image: {}", path.string(), one_line(message)));
  const OpenedImage input(reader, handle);
  std::string error;
  std::optional<Image> image = read_rgb(input, file_bytes, error);
  if (!image) throw Error(ErrorKind::bad_value, fmt::format("{}: {}", path.string(), error));
  return std::move(*image);
}

std::optional<Texture> decode_texture(const std::vector<unsigned char>& bytes,
                                      const std::string& name, std::string& error) {
  // glTF embeds PNG or JPEG only (glTF 2.0, "Images"): the magic number picks the one reader,
  // which reads the bytes through a memory proxy. Anything else is refused before OpenImageIO
  // sees it; left to itself, OpenImageIO would try each of its readers in turn on bytes its
  // first choice refused (hundreds of milliseconds for nothing).
  auto starts_with = [&bytes](std::initializer_list<unsigned char> magic) {
    return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
  };
  const char* format = starts_with({0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}) ? "png"
                       : starts_with({0xff, 0xd8, 0xff})                           ? "jpeg"
                                                                                   : nullptr;
  if (!format) {
    error = tr("not a PNG or JPEG image");
    return std::nullopt;
  }
  error = header_problem(bytes, bytes.size());
  if (!error.empty()) return std::nullopt;
  const LuzImageReader& reader = image_reader();
  char message[1024] = "";
  void* handle = nullptr;
  {
    const QuietStderr quiet;
    handle = reader.open_memory(bytes.data(), bytes.size(), format, message, sizeof message);
  }
  if (!handle) {
    error = trf("not a readable {} image{}", format == std::string("png") ? "PNG" : "JPEG",
                message[0] ? ": " + one_line(message) : std::string());
    return std::nullopt;
  }
  const OpenedImage input(reader, handle);
  std::optional<Image> image = read_rgb(input, bytes.size(), error);
  if (!image) return std::nullopt;
  Texture texture;
  texture.name = name;
  texture.width = image->width;
  texture.height = image->height;
  texture.texels = std::move(image->pixels);
  return texture;
}

}  // namespace luz::io
