// Image files: EXR keeps linear radiance, PNG is exposed and sRGB-encoded, writes are atomic.
#include <cmath>
#include <filesystem>
#include <fstream>

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
