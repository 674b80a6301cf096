#include "oiio_images.h"

#include <stdexcept>

#include <OpenImageIO/imageio.h>

namespace luz::test {

namespace {

OIIO::TypeDesc type_of(Sample sample) {
  switch (sample) {
    case Sample::uint8: return OIIO::TypeDesc::UINT8;
    case Sample::uint16: return OIIO::TypeDesc::UINT16;
    case Sample::half: return OIIO::TypeDesc::HALF;
    case Sample::float32: return OIIO::TypeDesc::FLOAT;
  }
  return OIIO::TypeDesc::UNKNOWN;
}

}  // namespace

void oiio_write(const std::filesystem::path& path, int width, int height, const std::vector<std::string>& channel_names,
                Sample sample, const std::vector<float>& values,
                const std::vector<std::pair<std::string, std::string>>& attributes, int tile) {
  auto output = OIIO::ImageOutput::create(path.string());
  if (!output) throw std::runtime_error("OpenImageIO cannot write " + path.string() + ": " + OIIO::geterror());
  OIIO::ImageSpec spec(width, height, int(channel_names.size()), type_of(sample));
  spec.channelnames = channel_names;
  spec.alpha_channel = -1;
  for (size_t c = 0; c < channel_names.size(); ++c)
    if (channel_names[c] == "A") spec.alpha_channel = int(c);
  for (const auto& [name, value] : attributes) spec.attribute(name, value);
  if (tile > 0) spec.tile_width = spec.tile_height = tile;
  if (!output->open(path.string(), spec) || !output->write_image(OIIO::TypeDesc::FLOAT, values.data()) ||
      !output->close())
    throw std::runtime_error("OpenImageIO cannot write " + path.string() + ": " + output->geterror());
}

OiioImage oiio_read(const std::filesystem::path& path) {
  // The colours as stored: OpenImageIO would multiply a PNG's colours by their alpha, which glTF's
  // textures never are ("Images": not premultiplied) and Luz does not do.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(path.string(), &config);
  if (!input) throw std::runtime_error("OpenImageIO cannot read " + path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = input->spec();
  OiioImage image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.values.resize(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.values.data()))
    throw std::runtime_error("OpenImageIO cannot read " + path.string() + ": " + input->geterror());
  return image;
}

}  // namespace luz::test
