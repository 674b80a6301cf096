// Image files: EXR keeps linear radiance, PNG is exposed and sRGB-encoded, writes are atomic.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "oiio_images.h"
#include "support.h"

namespace luz {
namespace {

Image gradient() {
  Image image(4, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) image.at(x, y) = Rgb(0.1f * float(x), 0.05f * float(y), 2.5f);
  return image;
}

std::string contents_of(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

size_t files_in(const std::filesystem::path& folder) {
  return size_t(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()));
}

// Every file Luz writes (images, --csv, --ray-tree, the script's dumps) goes through this writer:
// a reader sees the old file or the whole new one, and no temporary is left behind.
TEST(AtomicFile, ReplacesWholeOrLeavesTheOldFileAndNoTemporary) {
  test::ScratchDir dir;
  const std::filesystem::path path = dir / "state.json";
  EXPECT_EQ(io::write_atomically(path, [] { return std::string("{\"old\": 1}\n"); }), "");
  EXPECT_EQ(io::write_atomically(path, [] { return std::string("{\"new\": 2}\n"); }), "");
  EXPECT_EQ(contents_of(path), "{\"new\": 2}\n");
  EXPECT_EQ(files_in(dir.path), 1u);

  // The contents fail halfway (out of memory): the old file stays, the reason is given.
  const std::string failure =
      io::write_atomically(path, []() -> std::string { throw std::runtime_error("no memory left"); });
  EXPECT_EQ(failure, "no memory left");
  EXPECT_EQ(contents_of(path), "{\"new\": 2}\n");
  EXPECT_EQ(files_in(dir.path), 1u);

  // A folder that is not there: refused before the contents are made.
  bool made = false;
  EXPECT_NE(io::write_atomically(dir / "missing" / "x.csv", [&] { made = true; return std::string("a"); }), "");
  EXPECT_FALSE(made);
  EXPECT_EQ(files_in(dir.path), 1u);
}

TEST(ImageIo, ExrKeepsLinearRadianceAndRowOrder) {
  test::ScratchDir dir;
  const Image image = gradient();
  io::write_image(image, dir / "a.exr", 3.0f);  // exposure never touches EXR
  const Image back = io::read_image(dir / "a.exr");
  ASSERT_EQ(back.width, 4);
  ASSERT_EQ(back.height, 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(back.pixels[i][c], image.pixels[i][c]);
}

// Luz writes its files itself and reads them itself (tinyexr, stb_image): each file is read back
// through OpenImageIO too, an implementation independent of both, and all three must agree. Random values (negative, tiny, huge, in every bit pattern deflate
// cannot shrink, so some blocks are stored raw) beside smooth ones, at sizes that leave a partial
// last block of 16 scanlines and a one-pixel-wide picture.
TEST(ImageIo, ExrWrittenByLuzReadsBackBitForBitThroughLuzAndOpenImageIo) {
  test::ScratchDir dir;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> exponent(-30.0f, 30.0f), sign(-1.0f, 1.0f);
  for (const auto& [width, height] : {std::pair{1, 1}, {1, 37}, {123, 45}, {64, 16}}) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        image.at(x, y) = y % 2 == 0 ? Rgb(sign(random) * std::exp2(exponent(random)), float(x) / 7.0f, -float(y))
                                    : Rgb(0.25f * float(x + y), 1e-30f, 3e30f);
    io::write_image(image, dir / "a.exr", 0.0f);
    const test::OiioImage oiio = test::oiio_read(dir / "a.exr");
    const Image back = io::read_image(dir / "a.exr");
    ASSERT_EQ(oiio.width, width);
    ASSERT_EQ(oiio.height, height);
    ASSERT_EQ(oiio.channels, 3);
    ASSERT_EQ(back.width, width);
    ASSERT_EQ(back.height, height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(oiio.values[3 * i + size_t(c)], image.pixels[i][c]) << width << "x" << height << " " << i;
        ASSERT_EQ(back.pixels[i][c], image.pixels[i][c]) << width << "x" << height << " " << i;
      }
  }
}

// Every 8-bit value the encoder wrote comes back: noise (which the Paeth and None filters suit),
// ramps (Sub, Up, Average) and flat rows, over a width that is not a multiple of anything, and
// over a picture whose rows are filtered on several threads.
TEST(ImageIo, PngWrittenByLuzReadsBackValueForValueThroughLuzAndOpenImageIo) {
  test::ScratchDir dir;
  std::mt19937 random(11);
  for (const auto& [width, height] : {std::pair{77, 41}, {641, 480}}) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const float noise = float(random() % 256) / 255.0f;
        image.at(x, y) = 3 * y < height ? Rgb(noise, float(random() % 256) / 255.0f, noise * noise)
                       : 3 * y < 2 * height ? Rgb(float(x) / float(width), float(y) / float(height), 0.5f)
                                            : Rgb(0.3f);
      }
    io::write_image(image, dir / "a.png", 0.0f);
    const test::OiioImage oiio = test::oiio_read(dir / "a.png");
    const Image back = io::read_image(dir / "a.png");
    ASSERT_EQ(oiio.width, width);
    ASSERT_EQ(oiio.height, height);
    ASSERT_EQ(back.width, width);
    ASSERT_EQ(back.height, height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        // The 8-bit code written (SCENES.md: the sRGB curve, rounded) and the ones read back.
        const long written = std::lround(255.0f * srgb_encode(image.pixels[i][c]));
        const long read = std::lround(255.0f * srgb_encode(back.pixels[i][c]));
        ASSERT_EQ(std::lround(255.0f * oiio.values[3 * i + size_t(c)]), written) << width << "x" << height << " " << i;
        ASSERT_EQ(read, written) << width << "x" << height << " pixel " << i << " channel " << c;
      }
  }
}

TEST(ImageIo, PngIsExposedThenSrgbEncoded) {
  test::ScratchDir dir;
  Image image(1, 1, Rgb(0.045f, 0.09f, 1.0f));
  io::write_image(image, dir / "a.png", 1.0f);  // x2: 0.09, 0.18, 2.0 (clamped)
  const Image back = io::read_image(dir / "a.png");  // read_image decodes sRGB again
  EXPECT_NEAR(back.at(0, 0).r, 0.09f, 0.004f);
  EXPECT_NEAR(back.at(0, 0).g, 0.18f, 0.004f);
  EXPECT_FLOAT_EQ(back.at(0, 0).b, 1.0f);
}

// ---- Files written by OpenImageIO, read by Luz and by OpenImageIO ----

// One file of the comparison: its name (the extension picks the format), channels and storage.
struct Written {
  std::string name;
  std::vector<std::string> channels;
  test::Sample sample;
  int tile = 0;
};

constexpr int kWidth = 37, kHeight = 23;  // no multiple of a tile, a JPEG block or a row filter's stride

// Values a file of `sample` can hold exactly: random 8 or 16-bit codes; floats of random sign over
// many magnitudes (halves round them, both readers then see the same halves); positive ones for
// Radiance HDR, which has no sign.
std::vector<float> values_for(const Written& file, std::mt19937& random) {
  std::vector<float> values(size_t(kWidth) * kHeight * file.channels.size());
  std::uniform_real_distribution<float> exponent(-12.0f, 12.0f);
  const bool hdr = file.name.ends_with(".hdr");
  for (float& v : values) {
    if (file.sample == test::Sample::uint8) v = float(random() % 256) / 255.0f;
    else if (file.sample == test::Sample::uint16) v = float(random() % 65536) / 65535.0f;
    else v = (hdr || random() % 4 ? 1.0f : -1.0f) * std::exp2(exponent(random));
  }
  return values;
}

// What Luz must read from what OpenImageIO read: integer files hold sRGB codes (SCENES.md), which
// Luz decodes; floats are radiance as they are. Grey is replicated, alpha dropped.
Rgb expected(const test::OiioImage& o, size_t pixel, test::Sample sample) {
  auto value = [&](int c) {
    const float v = o.values[pixel * size_t(o.channels) + size_t(c)];
    const float max = sample == test::Sample::uint8 ? 255.0f : sample == test::Sample::uint16 ? 65535.0f : 0.0f;
    return max > 0.0f ? srgb_decode(float(std::lround(v * max)) / max) : v;
  };
  return o.channels >= 3 ? Rgb(value(0), value(1), value(2)) : Rgb(value(0));
}

const std::vector<Written>& written_files() {
  using test::Sample;
  static const std::vector<Written> files = {
      {"grey8.png", {"Y"}, Sample::uint8},          {"grey-alpha8.png", {"Y", "A"}, Sample::uint8},
      {"rgb8.png", {"R", "G", "B"}, Sample::uint8}, {"rgba8.png", {"R", "G", "B", "A"}, Sample::uint8},
      {"grey16.png", {"Y"}, Sample::uint16},        {"rgb16.png", {"R", "G", "B"}, Sample::uint16},
      {"rgba16.png", {"R", "G", "B", "A"}, Sample::uint16},
      {"rgb.hdr", {"R", "G", "B"}, Sample::float32},
      {"half.exr", {"R", "G", "B"}, Sample::half}, {"half-rgba.exr", {"R", "G", "B", "A"}, Sample::half},
      {"float.exr", {"R", "G", "B"}, Sample::float32}, {"grey.exr", {"Y"}, Sample::float32},
      {"tiled.exr", {"R", "G", "B"}, Sample::half, 16},
  };
  return files;
}

// PNG of 8 and 16 bits in grey, grey and alpha, RGB and RGBA; Radiance HDR; OpenEXR of half and
// float channels, RGB, RGBA and Y, scanline and tiled: Luz's value of every channel of every pixel is
// the one OpenImageIO's reading makes (bit for bit: the same codes through the same curve, the same floats).
TEST(ImageIo, LuzReadsWhatOpenImageIoReads) {
  test::ScratchDir dir;
  std::mt19937 random(5);
  for (const Written& file : written_files()) {
    test::oiio_write(dir / file.name, kWidth, kHeight, file.channels, file.sample, values_for(file, random), {},
                     file.tile);
    const test::OiioImage oiio = test::oiio_read(dir / file.name);
    ASSERT_EQ(oiio.channels, int(file.channels.size())) << file.name;
    const Image luz = io::read_image(dir / file.name);
    ASSERT_EQ(luz.width, kWidth) << file.name;
    ASSERT_EQ(luz.height, kHeight) << file.name;
    for (size_t i = 0; i < luz.pixels.size(); ++i) {
      const Rgb want = expected(oiio, i, file.sample);
      for (int c = 0; c < 3; ++c) ASSERT_EQ(luz.pixels[i][c], want[c]) << file.name << " pixel " << i << " channel " << c;
    }
  }
}

// JPEG decoders may round their inverse DCT differently (ITU T.81 bounds its error, it does not fix
// its bits): stb_image's codes stay within one of libjpeg's, through OpenImageIO. Full-resolution
// chroma (4:4:4), so that no upsampling filter differs.
TEST(ImageIo, LuzReadsJpegsAsOpenImageIoDoesWithinOneCode) {
  test::ScratchDir dir;
  std::mt19937 random(3);
  for (const std::vector<std::string>& channels : {std::vector<std::string>{"Y"}, {"R", "G", "B"}}) {
    std::vector<float> values(size_t(kWidth) * kHeight * channels.size());
    for (size_t i = 0; i < values.size(); ++i) {  // smooth ramps with a little noise
      const size_t pixel = i / channels.size(), x = pixel % kWidth, y = pixel / kWidth;
      values[i] = std::clamp(float(x + 2 * y + 20 * (i % channels.size())) / 100.0f + float(random() % 16) / 255.0f,
                             0.0f, 1.0f);
    }
    const auto path = dir / (channels.size() == 1 ? "grey.jpg" : "rgb.jpg");
    test::oiio_write(path, kWidth, kHeight, channels, test::Sample::uint8, values,
                     {{"compression", "jpeg:90"}, {"jpeg:subsampling", "4:4:4"}});
    const test::OiioImage oiio = test::oiio_read(path);
    const Image luz = io::read_image(path);
    ASSERT_EQ(luz.width, kWidth);
    ASSERT_EQ(luz.height, kHeight);
    long largest = 0;
    for (size_t i = 0; i < luz.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        const long theirs = std::lround(255.0f * oiio.values[i * channels.size() + (channels.size() == 1 ? 0 : size_t(c))]);
        largest = std::max(largest, std::labs(std::lround(255.0f * srgb_encode(luz.pixels[i][c])) - theirs));
      }
    EXPECT_LE(largest, 1) << path;
  }
}

// A file cut anywhere, or with a byte changed anywhere, is either still a picture of its size (a
// JPEG decoder fills what is missing, as libjpeg does) or a luz::Error that names the file; never a
// crash, a sanitizer report or another exception. PNG and OpenEXR files cut short never pass
// (PNG needs its IEND chunk, OpenEXR its chunks' offsets).
TEST(ImageIo, CutOrDamagedFilesAreRefusedNamingTheFile) {
  test::ScratchDir dir;
  std::mt19937 random(9);
  std::vector<Written> files = {written_files()[2], written_files()[5], written_files()[7], written_files()[8],
                                written_files()[12], {"rgb.jpg", {"R", "G", "B"}, test::Sample::uint8}};
  for (const Written& file : files) {
    test::oiio_write(dir / file.name, kWidth, kHeight, file.channels, file.sample, values_for(file, random), {},
                     file.tile);
    std::ifstream in(dir / file.name, std::ios::binary);
    const std::vector<unsigned char> whole((std::istreambuf_iterator<char>(in)), {});
    const auto broken = dir / ("broken-" + file.name);
    // A cut file that still reads is the whole picture; a damaged header may claim another size.
    auto try_read = [&](const std::vector<unsigned char>& bytes, const std::string& what, bool cut) {
      std::ofstream(broken, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(bytes.data()),
                                                                     std::streamsize(bytes.size()));
      try {
        const Image image = io::read_image(broken);
        if (cut) {
          EXPECT_EQ(image.width, kWidth) << what;
          EXPECT_EQ(image.height, kHeight) << what;
        }
        return true;
      } catch (const Error& e) {
        EXPECT_EQ(e.kind, ErrorKind::bad_value) << what;
        EXPECT_TRUE(std::string(e.what()).starts_with(broken.string() + ": ")) << what << ": " << e.what();
        return false;
      }
    };
    const bool must_fail_when_cut = file.name.ends_with(".png") || file.name.ends_with(".exr");
    for (size_t cut = 0; cut < whole.size(); cut += 1 + cut / 8) {
      const std::string what = file.name + " cut at " + std::to_string(cut);
      const bool read = try_read({whole.begin(), whole.begin() + std::ptrdiff_t(cut)}, what, true);
      if (must_fail_when_cut) {
        EXPECT_FALSE(read) << what;
      }
    }
    for (int k = 0; k < 200; ++k) {
      std::vector<unsigned char> damaged = whole;
      const size_t at = random() % damaged.size();
      damaged[at] = static_cast<unsigned char>(damaged[at] ^ (1 + random() % 255));
      try_read(damaged, file.name + " damaged at " + std::to_string(at), false);
    }
  }
}

TEST(ImageIo, FailedWriteLeavesNoFile) {
  test::ScratchDir dir;
  const auto target = dir / "missing-folder" / "a.png";
  try {
    io::write_image(gradient(), target, 0.0f);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind, ErrorKind::output);
    EXPECT_NE(std::string(e.what()).find("a.png"), std::string::npos);
  }
  EXPECT_FALSE(std::filesystem::exists(target));
}

TEST(ImageIo, WriteReplacesAndLeavesNoTemporary) {
  test::ScratchDir dir;
  io::write_image(gradient(), dir / "a.png", 0.0f);
  io::write_image(Image(2, 2), dir / "a.png", 0.0f);
  EXPECT_EQ(io::read_image(dir / "a.png").width, 2);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path), {}), 1);
}

TEST(ImageIo, UnsupportedOutputIsAUsageError) {
  test::ScratchDir dir;
  EXPECT_FALSE(io::is_supported_output("a.jpg"));
  EXPECT_TRUE(io::is_supported_output("A.PNG"));
  try {
    io::write_image(gradient(), dir / "a.tif", 0.0f);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind, ErrorKind::usage);
  }
}

TEST(ImageIo, DecodeTextureFromPngBytes) {
  test::ScratchDir dir;
  Image image(2, 1);
  image.at(0, 0) = Rgb(1.0f, 0.0f, 0.0f);
  image.at(1, 0) = Rgb(0.2f);
  io::write_image(image, dir / "t.png", 0.0f);
  std::ifstream file(dir / "t.png", std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)), {});
  std::string error;
  const auto texture = io::decode_texture(bytes, "t", error);
  ASSERT_TRUE(texture) << error;
  EXPECT_EQ(texture->width, 2);
  EXPECT_FLOAT_EQ(texture->texel(0, 0).r, 1.0f);
  EXPECT_NEAR(texture->texel(1, 0).g, 0.2f, 0.003f);  // linear again after the sRGB round trip
}

TEST(ImageIo, DecodeTextureRejectsGarbage) {
  std::string error;
  EXPECT_FALSE(io::decode_texture({1, 2, 3, 4, 5}, "junk", error));
  EXPECT_FALSE(error.empty());
}

// A 16-bit RGB PNG, 2 x 1: pixel 0 = (0x1234, 0xffff, 0x0000), pixel 1 = (0x8000, 0x0001, 0xfffe),
// big-endian in the file: its channels decoded through the sRGB curve from value / 65535.
TEST(ImageIo, DecodeTextureReads16BitPngs) {
  const std::vector<unsigned char> png = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
      0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x10, 0x02, 0x00, 0x00, 0x00, 0x2b, 0xd0, 0x34, 0x9e, 0x00, 0x00, 0x00,
      0x15, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x10, 0x32, 0xf9, 0xff, 0x9f, 0x81, 0xa1, 0x81, 0x81, 0x81,
      0xf1, 0xff, 0x3f, 0x00, 0x1c, 0x0d, 0x04, 0xc3, 0xea, 0x92, 0xa5, 0x75, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45,
      0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  std::string error;
  const auto texture = io::decode_texture(png, "16-bit", error);
  ASSERT_TRUE(texture) << error;
  ASSERT_EQ(texture->width, 2);
  const float expected[2][3] = {{0x1234, 0xffff, 0x0000}, {0x8000, 0x0001, 0xfffe}};
  for (int x = 0; x < 2; ++x)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(texture->texel(x, 0)[c], srgb_decode(expected[x][c] / 65535.0f), 1e-6f) << x << " " << c;
}

// glTF embeds PNG and JPEG only: the magic number picks the reader, and bytes that begin like
// one but are not say which format they failed as.
TEST(ImageIo, DecodeTextureNamesTheFormatItFailedAs) {
  std::string error;
  EXPECT_FALSE(io::decode_texture({'B', 'M', 0x3e, 0, 0, 0, 0, 0, 0, 0, 0x3e, 0}, "bitmap", error));
  EXPECT_EQ(error, "not a PNG or JPEG image");
  const std::vector<unsigned char> png_header = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H'};
  EXPECT_FALSE(io::decode_texture(png_header, "cut", error));
  EXPECT_TRUE(error.starts_with("not a readable PNG image")) << error;
  EXPECT_FALSE(io::decode_texture({0xff, 0xd8, 0xff, 0xe0, 0, 16, 'J', 'F', 'I', 'F'}, "cut", error));
  EXPECT_TRUE(error.starts_with("not a readable JPEG image")) << error;
}

TEST(ImageIo, ReadingAMissingFileNamesIt) {
  try {
    io::read_image("/nonexistent/x.png");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind, ErrorKind::file_missing);
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.png"), std::string::npos);
  }
}

}  // namespace
}  // namespace luz
