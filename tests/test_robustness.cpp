// Bad input never crashes: each case of a malformed file, a hostile size or an interrupted run
// ends in exit 1 (exit 2 for a flag) with one clear line, and no renderer writes a non-finite
// pixel. Also the two headless back ends, EGL and OSMesa, drawing the same picture.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <string>
#include <tuple>
#include <vector>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/image.h"
#include "gltf_fixture.h"
#include "io/image_io.h"
#include "oiio_images.h"
#include "support.h"
#include "viewer_support.h"

namespace luz::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string scene(const char* name) { return (scene_dir() / name).string(); }

bool one_line_naming(const std::string& output, const std::string& name) {
  return output.find(name) != std::string::npos;
}

// A PNG whose header claims `width` x `height` (with one tiny IDAT): the decoder must look at
// the header before it allocates.
std::vector<unsigned char> png_claiming(uint32_t width, uint32_t height) {
  std::vector<unsigned char> png = png_rgb8(1, 1, {1, 2, 3});
  // IHDR's data starts at byte 16: width then height, big-endian (its CRC is not checked first).
  for (int i = 0; i < 4; ++i) {
    png[16 + size_t(i)] = static_cast<unsigned char>(width >> (24 - 8 * i));
    png[20 + size_t(i)] = static_cast<unsigned char>(height >> (24 - 8 * i));
  }
  // The IHDR's CRC (over its type and 13 data bytes, bytes 12..28), so that only the size lies.
  uint32_t crc = 0xFFFFFFFFu;
  for (size_t i = 12; i < 29; ++i) {
    crc ^= png[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  crc ^= 0xFFFFFFFFu;
  for (int i = 0; i < 4; ++i) png[29 + size_t(i)] = static_cast<unsigned char>(crc >> (24 - 8 * i));
  return png;
}

TEST(Robustness, HugePngHeaderIsRefusedBeforeDecoding) {
  std::string error;
  EXPECT_FALSE(io::decode_texture(png_claiming(65535, 65535), "huge", error));
  EXPECT_NE(error.find("beyond the limit"), std::string::npos) << error;
  // As --environment: exit 1 naming the file, no bad_alloc.
  ScratchDir dir;
  write_file(dir / "huge.png", png_claiming(65535, 65535));
  const CommandResult run = run_luz({"render", scene("whitted.gltf"), "--reflection-map", "--environment",
                                     (dir / "huge.png").string(), "--size", "16x12", "--out",
                                     (dir / "out.png").string()});
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_TRUE(one_line_naming(run.output, "huge.png: header: 65535 x 65535 pixels is beyond the limit")) << run.output;
}

// Within the caps, a header can still claim far more pixels than its bytes can hold: refused
// before the pixels are allocated, while a large image that does compress that well loads.
TEST(Robustness, PngClaimingMorePixelsThanItsBytesCanHoldIsRefused) {
  std::string error;
  EXPECT_FALSE(io::decode_texture(png_claiming(2000, 2000), "liar", error));
  EXPECT_NE(error.find("2000 x 2000 pixels cannot come from"), std::string::npos) << error;
  const std::vector<unsigned char> flat = png_rgb8(1024, 1024, std::vector<unsigned char>(size_t(1024) * 1024 * 3, 200));
  const auto texture = io::decode_texture(flat, "flat", error);
  ASSERT_TRUE(texture) << error << " (" << flat.size() << " bytes)";
  EXPECT_EQ(texture->width, 1024);
}

// A JPEG's frame header, whose size is refused before anything is allocated for it (a fuzzed
// 140-byte file once made a JPEG reader allocate 2 GB as it opened it). SOI, an APP0 segment to
// walk over, then SOF0 of one component with height and width, big-endian.
std::vector<unsigned char> jpeg_claiming(uint16_t width, uint16_t height) {
  return {0xff, 0xd8, 0xff, 0xe0, 0x00, 0x04, 0x00, 0x00, 0xff, 0xc0, 0x00, 0x0b, 0x08,
          static_cast<unsigned char>(height >> 8), static_cast<unsigned char>(height & 0xff),
          static_cast<unsigned char>(width >> 8), static_cast<unsigned char>(width & 0xff), 0x01, 0x01, 0x11, 0x00,
          0xff, 0xd9};
}

TEST(Robustness, JpegClaimingAHugeSizeIsRefusedBeforeDecoding) {
  std::string error;
  EXPECT_FALSE(io::decode_texture(jpeg_claiming(62978, 31234), "huge", error));
  EXPECT_EQ(error, "header: 62978 x 31234 pixels is beyond the limit of 16384 per side and 16777216 in all");
  EXPECT_FALSE(io::decode_texture(jpeg_claiming(4000, 4000), "liar", error));
  EXPECT_TRUE(error.starts_with("header: 4000 x 4000 pixels cannot come from 23 bytes")) << error;
  // Garbage before the frame header (a segment's length that lies) is skipped, as decoders do.
  std::vector<unsigned char> resync = jpeg_claiming(62978, 31234);
  resync[5] = 0x02;  // APP0's length now ends inside it: two bytes of junk before SOF0
  EXPECT_FALSE(io::decode_texture(resync, "resync", error));
  EXPECT_TRUE(error.starts_with("header: 62978 x 31234 pixels is beyond the limit")) << error;
  // As --environment: the same check on the file, exit 1 naming it.
  ScratchDir dir;
  write_file(dir / "huge.jpg", jpeg_claiming(62978, 31234));
  const CommandResult run = run_luz({"render", scene("whitted.gltf"), "--reflection-map", "--environment",
                                     (dir / "huge.jpg").string(), "--size", "16x12", "--out",
                                     (dir / "out.png").string()});
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_TRUE(one_line_naming(run.output, "huge.jpg: header: 62978 x 31234 pixels is beyond the limit")) << run.output;
}

// A JPEG Huffman table holds at most 256 codes (ITU T.81, B.2.4.2): one whose counts add up to more
// is refused before the decoder builds it (stb_image would write past the table: a fuzzed file),
// whether it comes before the frame header or after it.
TEST(Robustness, JpegHuffmanTableOfMoreThan256CodesIsRefused) {
  std::vector<unsigned char> table = {0xff, 0xc4, 0x01, 0x3f, 0x00, 255, 45};  // 2 + 17 + 300 bytes
  table.resize(table.size() + 14, 0);
  table.resize(table.size() + 300, 7);
  const std::vector<unsigned char> jpeg = jpeg_claiming(16, 16);
  for (const size_t at : {size_t(8), jpeg.size() - 2}) {  // after APP0; after SOF0
    std::vector<unsigned char> bad = jpeg;
    bad.insert(bad.begin() + std::ptrdiff_t(at), table.begin(), table.end());
    std::string error;
    EXPECT_FALSE(io::decode_texture(bad, "huffman", error));
    EXPECT_EQ(error, "not a readable JPEG image: a Huffman table of 300 codes (at most 256)") << at;
  }
}

TEST(Robustness, CorruptPngSaysSoInOneLineWithoutLibpngsOwn) {
  ScratchDir dir;
  std::vector<unsigned char> png = png_rgb8(4, 4, std::vector<unsigned char>(48, 7));
  png[png.size() - 20] ^= 0xFF;  // inside the IDAT's compressed stream
  write_file(dir / "bad.png", png);
  const CommandResult run = run_luz({"render", scene("whitted.gltf"), "--reflection-map", "--environment",
                                     (dir / "bad.png").string(), "--size", "16x12", "--out",
                                     (dir / "out.png").string()});
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_EQ(run.output.find("libpng error"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("luz: " + (dir / "bad.png").string()), std::string::npos) << run.output;
}

// A file of each format Luz reads, cut short, as --environment: exit 1 and one line that names the
// file, nothing written. Cut where no decoder can make a picture of what is left: PNG and OpenEXR
// halfway (PNG needs its IEND chunk, OpenEXR the chunks its offsets point at), JPEG and Radiance
// HDR inside their headers.
TEST(Robustness, CutImageFilesEndInOneLineNamingTheFile) {
  ScratchDir dir;
  const std::vector<float> values(size_t(32) * 16 * 3, 0.5f);
  for (const auto& [name, sample, keep] : {std::tuple{"cut.png", Sample::uint8, 0.5}, {"cut.exr", Sample::half, 0.5},
                                           {"cut.jpg", Sample::uint8, 0.05}, {"cut.hdr", Sample::float32, 0.05}}) {
    oiio_write(dir / name, 32, 16, {"R", "G", "B"}, sample, values);
    std::ifstream in(dir / name, std::ios::binary);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), {});
    bytes.resize(size_t(double(bytes.size()) * keep));
    write_file(dir / name, bytes);
    const CommandResult run = run_luz({"render", scene("whitted.gltf"), "--reflection-map", "--environment",
                                       (dir / name).string(), "--size", "16x12", "--out", (dir / "out.png").string()});
    EXPECT_EQ(run.exit_code, 1) << name << ": " << run.output;
    EXPECT_NE(run.output.find("luz: " + (dir / name).string() + ": "), std::string::npos) << run.output;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    EXPECT_FALSE(fs::exists(dir / "out.png")) << name;
  }
}

TEST(Robustness, ImageWriterRefusesNonFinitePixels) {
  ScratchDir dir;
  Image image(4, 2);
  image.pixels[5] = Rgb(0.5f, std::numeric_limits<float>::quiet_NaN(), 0.5f);
  for (const char* name : {"nan.png", "nan.exr"}) {
    try {
      io::write_image(image, dir / name, 0.0f);
      ADD_FAILURE() << name << " written";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("pixel (1, 1) is not finite"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir / name));
  }
  EXPECT_TRUE(fs::is_empty(dir.path));  // no temporary left either
}

TEST(Robustness, HugeBaseColourIsClampedAndEveryModelStaysFinite) {
  GltfBuilder b;
  Primitive floor;
  floor.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  floor.indices = {0, 2, 1, 0, 3, 2};
  floor.material = b.material({{"pbrMetallicRoughness", {{"baseColorFactor", {1e30, 1e30, 1e30, 1}},
                                                         {"metallicFactor", 0.0}}}});
  Primitive lamp;
  lamp.positions = {{-0.2f, 1, -0.2f}, {0.2f, 1, -0.2f}, {0.2f, 1, 0.2f}, {-0.2f, 1, 0.2f}};
  lamp.indices = {0, 1, 2, 0, 2, 3};
  lamp.material = b.material({{"emissiveFactor", {1, 1, 1}}});
  b.node({{"mesh", b.mesh({floor, lamp})}});
  ScratchDir dir;
  const fs::path file = b.write_gltf(dir);
  for (const std::string model : {"phong", "whitted", "radiosity", "hybrid"}) {
    const fs::path out = dir / (model + ".exr");
    std::vector<std::string> args = {"render", file.string(), "--model", model, "--size", "24x18",
                                     "--out", out.string()};
    if (model == "radiosity" || model == "hybrid")
      args.insert(args.end(), {"--hemicube-res", "64", "--shots", "20"});
    const CommandResult run = run_luz(args);
    ASSERT_EQ(run.exit_code, 0) << model << ": " << run.output;
    EXPECT_NE(run.output.find("clamped to 1"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("inf%"), std::string::npos) << run.output;
    const Image image = io::read_image(out);
    for (const Rgb& c : image.pixels)
      ASSERT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b)) << model;
  }
}

TEST(Robustness, SigtermDuringTheWriteLeavesNoTemporary) {
  // A child writes a large EXR (a fraction of a second of zip compression, with the temporary
  // open meanwhile); the parent waits for the hidden temporary to appear beside the target, then
  // sends SIGTERM.
  ScratchDir dir;
  const fs::path target = dir / "big.exr";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    Image image(2048, 2048);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = Rgb(float(i % 977) / 977.0f);
    try {
      io::write_image(image, target, 0.0f);
    } catch (...) {
    }
    _exit(0);
  }
  bool seen = false;
  for (int tries = 0; tries < 200000 && !seen; ++tries) {
    for (const fs::directory_entry& entry : fs::directory_iterator(dir.path))
      if (entry.path().filename().string().rfind(".big.tmp", 0) == 0) seen = true;
    if (!seen) usleep(100);
  }
  ASSERT_TRUE(seen) << "the temporary never appeared";
  kill(child, SIGTERM);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM)
      << "the write finished before the signal; status " << status;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir.path))
    ADD_FAILURE() << "left behind: " << entry.path();
}

TEST(Robustness, CsvOnlyWhenTheRunSucceeds) {
  ScratchDir dir;
  const fs::path csv = dir / "history.csv";
  const CommandResult failed = run_luz({"render", scene("cornell_box.gltf"), "--model", "radiosity",
                                        "--size", "16x12", "--shots", "5", "--csv", csv.string(),
                                        "--out", (dir / "missing" / "out.png").string()});
  EXPECT_EQ(failed.exit_code, 1) << failed.output;
  EXPECT_FALSE(fs::exists(csv));
  const CommandResult ok = run_luz({"render", scene("cornell_box.gltf"), "--model", "radiosity", "--size",
                                    "16x12", "--shots", "5", "--csv", csv.string(), "--out",
                                    (dir / "out.png").string()});
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_TRUE(fs::exists(csv));
}

TEST(Robustness, ShadowMapSizeBeyondTheContextIsAUsageErrorNamingTheMost) {
  // llvmpipe holds at most 1 GB in one texture: 12 layers (two point lights) of 6144^2 floats
  // do not fit. A context that holds them renders (exit 0); none may fail with exit 1. The size
  // suggested is the largest power of two below the request that the context holds: it renders,
  // and it is 4096 (half a request that is not a power of two would waste three quarters).
  ScratchDir dir;
  const auto render = [&](int size) {
    return run_luz({"render", scene("phong_spheres.gltf"), "--shadows", "--shadow-map-size", std::to_string(size),
                    "--size", "16x12", "--out", (dir / "out.png").string()});
  };
  const CommandResult run = render(6144);
  if (run.exit_code == 0) GTEST_SKIP() << "this context holds 6144^2 x 12 shadow maps";
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("--shadow-map-size 6144: this OpenGL context"), std::string::npos) << run.output;
  std::smatch suggestion;
  ASSERT_TRUE(std::regex_search(run.output, suggestion, std::regex("use --shadow-map-size ([0-9]+) or less")))
      << run.output;
  const int suggested = std::stoi(suggestion[1]);
  EXPECT_EQ(render(suggested).exit_code, 0) << "the suggested size " << suggested << " does not render";
  if (suggested < 4096) {
    EXPECT_NE(render(4096).exit_code, 0) << "4096 renders, yet " << suggested << " was suggested";
  }
}

TEST(Robustness, ShotsZeroSaysTheRangeBriefly) {
  const CommandResult run = run_luz({"render", scene("cornell_box.gltf"), "--model", "radiosity", "--shots",
                                     "0", "--out", "x.png"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_LT(run.output.size(), 200u) << run.output;
}

TEST(Robustness, IllegalBase64SaysNotBase64) {
  GltfBuilder b = one_triangle();
  ScratchDir dir;
  const fs::path file = b.write_gltf(dir, "scene.gltf", true);
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const size_t at = text.find("base64,") + 7;
  text[at + 1] = '*';  // not in the alphabet; the length stays a multiple of 4
  write_file(file, text);
  const CommandResult run = run_luz({"render", file.string(), "--out", (dir / "out.png").string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("not base64"), std::string::npos) << run.output;
}

TEST(HeadlessBackends, EglAndOsmesaDrawTheSamePicture) {
  ScratchDir dir;
  std::vector<Codes> pictures;
  for (const char* backend : {"egl", "osmesa"}) {
    const fs::path out = dir / (std::string(backend) + ".png");
    const CommandResult run = run_luz({"render", scene("phong_spheres.gltf"), "--gl", backend, "--size",
                                       "160x120", "--out", out.string()});
    if (run.exit_code != 0 && run.output.find(backend == std::string("egl") ? "EGL" : "OSMesa") != std::string::npos)
      GTEST_SKIP() << backend << " is not available here: " << run.output;
    ASSERT_EQ(run.exit_code, 0) << backend << ": " << run.output;
    pictures.push_back(codes(out));
  }
  expect_same_picture(pictures[0], pictures[1]);
}

}  // namespace
}  // namespace luz::test
