#pragma once
// Image files written and read by OpenImageIO: the independent implementation that Luz's own
// readers (stb_image, tinyexr) and writers are held to. Only the tests link it.
#include <filesystem>
#include <string>
#include <vector>

namespace luz::test {

// How a file stores its samples.
enum class Sample { uint8, uint16, half, float32 };

struct OiioImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;  // width x height x channels, rows top first, as OpenImageIO converts to float
};

// Writes `values` (width x height x channel_names.size(), rows top first; integer formats take
// 0..1) to `path` in the format its extension names, stored as `sample`. `tile` > 0 writes a tiled
// file (OpenEXR). `attributes` are OpenImageIO's format hints ("compression", "jpeg:subsampling").
void oiio_write(const std::filesystem::path& path, int width, int height, const std::vector<std::string>& channel_names,
                Sample sample, const std::vector<float>& values,
                const std::vector<std::pair<std::string, std::string>>& attributes = {}, int tile = 0);

// The values as the file stores them (colours not multiplied by alpha).
OiioImage oiio_read(const std::filesystem::path& path);

}  // namespace luz::test
