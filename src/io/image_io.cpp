// TEMPORARY stand-in written by the loader's author so that the glTF loader builds and its tests
// run: only decode_texture, the least the loader needs. The real image_io.cpp (a colleague's)
// replaces this file whole.
#include "io/image_io.h"

#include <cstring>
#include <memory>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

namespace luz::io {

std::optional<Texture> decode_texture(const std::vector<unsigned char>& bytes,
                                      const std::string& name, std::string& error) {
  // OpenImageIO picks the reader by file extension, so name the bytes after their magic number.
  const char* extension = nullptr;
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), "\x89PNG", 4) == 0) extension = ".png";
  if (bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8) extension = ".jpg";
  if (!extension) {
    error = "neither PNG nor JPEG";
    return std::nullopt;
  }
  OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
  auto input = OIIO::ImageInput::open(std::string("texture") + extension, nullptr, &reader);
  if (!input) {
    error = OIIO::geterror();
    return std::nullopt;
  }
  const OIIO::ImageSpec& spec = input->spec();
  const int channels = spec.nchannels;
  if (spec.width <= 0 || spec.height <= 0 || channels <= 0) {
    error = "empty image";
    return std::nullopt;
  }
  std::vector<float> values(size_t(spec.width) * size_t(spec.height) * size_t(channels));
  if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, values.data())) {
    error = input->geterror();
    return std::nullopt;
  }
  Texture texture;
  texture.name = name;
  texture.width = spec.width;
  texture.height = spec.height;
  texture.texels.resize(size_t(spec.width) * size_t(spec.height));
  for (size_t i = 0; i < texture.texels.size(); ++i) {
    const float* p = &values[i * size_t(channels)];
    // Grey (and grey + alpha) images repeat their one colour channel.
    const Rgb encoded = channels >= 3 ? Rgb(p[0], p[1], p[2]) : Rgb(p[0]);
    texture.texels[i] = Rgb(srgb_decode(encoded.r), srgb_decode(encoded.g), srgb_decode(encoded.b));
  }
  return texture;
}

}  // namespace luz::io
