// Image files: EXR keeps linear radiance, PNG is exposed and sRGB-encoded, writes are atomic.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <utility>

#include <gtest/gtest.h>

#include "core/error.h"
#include "io/image_io.h"
#include "support.h"

namespace luz {
namespace {

Image gradient() {
  Image image(4, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) image.at(x, y) = Rgb(0.1f * float(x), 0.05f * float(y), 2.5f);
  return image;
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

// Luz writes its files itself and reads them through OpenImageIO: two implementations of each
// format that must agree. Random values (negative, tiny, huge, in every bit pattern deflate
// cannot shrink, so some blocks are stored raw) beside smooth ones, at sizes that leave a partial
// last block of 16 scanlines and a one-pixel-wide picture.
TEST(ImageIo, ExrWrittenByLuzReadsBackBitForBitThroughOpenImageIo) {
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
    const Image back = io::read_image(dir / "a.exr");
    ASSERT_EQ(back.width, width);
    ASSERT_EQ(back.height, height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(back.pixels[i][c], image.pixels[i][c]) << width << "x" << height << " " << i;
  }
}

// Every 8-bit value the encoder wrote comes back: noise (which the Paeth and None filters suit),
// ramps (Sub, Up, Average) and flat rows, over a width that is not a multiple of anything, and
// over a picture whose rows are filtered on several threads.
TEST(ImageIo, PngWrittenByLuzReadsBackValueForValueThroughOpenImageIo) {
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
    const Image back = io::read_image(dir / "a.png");
    ASSERT_EQ(back.width, width);
    ASSERT_EQ(back.height, height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        // The 8-bit code written (SCENES.md: the sRGB curve, rounded) and the one read back.
        const long written = std::lround(255.0f * srgb_encode(image.pixels[i][c]));
        const long read = std::lround(255.0f * srgb_encode(back.pixels[i][c]));
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
