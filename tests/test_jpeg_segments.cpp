// The walk over a JPEG's segments that Luz makes before stb_image reads a file (the frame
// header's size, the Huffman tables): held to stb_image's own reading of the frame header
// (stbi_info, compiled here a second time) on real files, and to markers that only look like
// markers inside another segment's data.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#include <stb_image.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/image_io.h"
#include "io/jpeg_segments.h"
#include "oiio_images.h"
#include "support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;

std::vector<unsigned char> bytes_of(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

struct StbSize {
  bool read = false;
  int width = 0, height = 0;
};
StbSize stb_size(const std::vector<unsigned char>& bytes) {
  StbSize size;
  int channels = 0;
  size.read = stbi_info_from_memory(bytes.data(), int(bytes.size()), &size.width, &size.height, &channels) != 0;
  return size;
}

// A picture of width x height with some detail, written by OpenImageIO (libjpeg) with `attributes`.
std::vector<unsigned char> written_jpeg(const fs::path& path, int width, int height,
                                        const std::vector<std::pair<std::string, std::string>>& attributes) {
  std::vector<float> values(size_t(width) * size_t(height) * 3);
  for (size_t i = 0; i < values.size(); ++i) values[i] = float((i * 37) % 101) / 100.0f;
  test::oiio_write(path, width, height, {"R", "G", "B"}, test::Sample::uint8, values, attributes);
  return bytes_of(path);
}

// Files from elsewhere: baseline and progressive (a DHT before each scan, after the frame header),
// EXIF blocks holding a whole thumbnail JPEG in APP1, comments; and libjpeg's own through
// OpenImageIO. The walk finds the size stb_image reads, and no table it would overrun.
TEST(JpegSegments, FindTheSizeStbImageReadsInRealFiles) {
  std::vector<fs::path> files;
  const fs::path models = "/usr/share/assimp/models";  // Debian's assimp-testmodels, installed by setup.sh
  if (fs::exists(models))
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(models)) {
      std::string extension = entry.path().extension().string();
      for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
      if (entry.is_regular_file() && (extension == ".jpg" || extension == ".jpeg")) files.push_back(entry.path());
    }
  test::ScratchDir dir;
  written_jpeg(dir / "baseline.jpg", 37, 23, {{"compression", "jpeg:90"}});
  written_jpeg(dir / "progressive.jpg", 300, 7, {{"compression", "jpeg:75"}, {"jpeg:progressive", "1"}});
  written_jpeg(dir / "full_chroma.jpg", 5, 640, {{"compression", "jpeg:95"}, {"jpeg:subsampling", "4:4:4"}});
  for (const char* name : {"baseline.jpg", "progressive.jpg", "full_chroma.jpg"}) files.push_back(dir / name);

  for (const fs::path& file : files) {
    const std::vector<unsigned char> bytes = bytes_of(file);
    const io::JpegSegments segments = io::walk_jpeg_segments(bytes);
    const StbSize stb = stb_size(bytes);
    ASSERT_TRUE(stb.read) << file;
    ASSERT_TRUE(segments.size) << file;
    EXPECT_EQ(segments.size->first, stb.width) << file;
    EXPECT_EQ(segments.size->second, stb.height) << file;
    EXPECT_EQ(segments.huffman_problem, "") << file;
  }
  const auto expected = [&](const char* name, int width, int height) {
    const io::JpegSegments segments = io::walk_jpeg_segments(bytes_of(dir / name));
    ASSERT_TRUE(segments.size) << name;
    EXPECT_EQ(*segments.size, (std::pair<int64_t, int64_t>{width, height})) << name;
  };
  expected("progressive.jpg", 300, 7);
  expected("full_chroma.jpg", 5, 640);
}

// A COM segment (a comment, T.81 B.2.4.5) whose text holds the bytes of a frame header claiming
// 61440 x 61440 pixels and of a Huffman table of 510 codes. They are the comment's data: the file
// is the picture it was, and reads as it did.
std::vector<unsigned char> comment_with_fake_markers() {
  std::vector<unsigned char> text = {0xff, 0xc0, 0x00, 0x11, 0x08, 0xf0, 0x00, 0xf0, 0x00, 0x03,
                                     0x01, 0x11, 0x00, 0x02, 0x11, 0x01, 0x03, 0x11, 0x01,  // SOF0, 3 components
                                     0xff, 0xc4, 0x00, 0x13, 0x00, 0xff, 0xff};  // DHT: 255 + 255 codes
  text.resize(text.size() + 14, 0);
  const size_t length = text.size() + 2;
  std::vector<unsigned char> segment = {0xff, 0xfe, static_cast<unsigned char>(length >> 8),
                                        static_cast<unsigned char>(length & 0xff)};
  segment.insert(segment.end(), text.begin(), text.end());
  return segment;
}

TEST(JpegSegments, MarkersInsideASegmentsDataAreData) {
  test::ScratchDir dir;
  const std::vector<unsigned char> plain = written_jpeg(dir / "plain.jpg", 37, 23, {{"compression", "jpeg:90"}});
  std::vector<unsigned char> commented = plain;
  const std::vector<unsigned char> comment = comment_with_fake_markers();
  commented.insert(commented.begin() + 2, comment.begin(), comment.end());  // right after SOI

  const io::JpegSegments segments = io::walk_jpeg_segments(commented);
  ASSERT_TRUE(segments.size);
  EXPECT_EQ(*segments.size, (std::pair<int64_t, int64_t>{37, 23}));
  EXPECT_EQ(segments.huffman_problem, "");
  const StbSize stb = stb_size(commented);
  EXPECT_TRUE(stb.read && stb.width == 37 && stb.height == 23);
  std::string error;
  const auto texture = io::decode_texture(commented, "commented", error);
  ASSERT_TRUE(texture) << error;
  const auto original = io::decode_texture(plain, "plain", error);
  ASSERT_TRUE(original) << error;
  EXPECT_EQ(texture->texels, original->texels);

  // The same bytes as segments of their own are what they say: the size they claim, and a table
  // refused before stb_image builds it.
  std::vector<unsigned char> unwrapped = plain;
  unwrapped.insert(unwrapped.begin() + 2, comment.begin() + 4, comment.end());
  const io::JpegSegments claimed = io::walk_jpeg_segments(unwrapped);
  ASSERT_TRUE(claimed.size);
  EXPECT_EQ(*claimed.size, (std::pair<int64_t, int64_t>{61440, 61440}));
  EXPECT_EQ(claimed.huffman_problem, "a Huffman table of 510 codes (at most 256)");
  EXPECT_FALSE(io::decode_texture(unwrapped, "unwrapped", error));
  EXPECT_EQ(error, "not a readable JPEG image: a Huffman table of 510 codes (at most 256)");
}

// A frame header may leave the height to a DNL segment after the first scan (T.81, B.2.5), which
// stb_image does not read: the message says so instead of calling the header damaged.
TEST(JpegSegments, AHeightLeftToTheDnlSegmentIsNamed) {
  const std::vector<unsigned char> delayed = {0xff, 0xd8, 0xff, 0xc0, 0x00, 0x0b, 0x08, 0x00, 0x00, 0x00, 0x10,
                                              0x01, 0x01, 0x11, 0x00, 0xff, 0xd9};
  const io::JpegSegments segments = io::walk_jpeg_segments(delayed);
  ASSERT_TRUE(segments.size);
  EXPECT_EQ(*segments.size, (std::pair<int64_t, int64_t>{16, 0}));
  EXPECT_FALSE(stb_size(delayed).read);
  std::string error;
  EXPECT_FALSE(io::decode_texture(delayed, "delayed", error));
  EXPECT_EQ(error, "not a readable JPEG image: its height comes after the first scan (a DNL segment), which Luz "
                   "does not read");
}

}  // namespace
}  // namespace luz
