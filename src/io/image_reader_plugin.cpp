// The luz_image_reader plugin: OpenImageIO behind image_reader_plugin.h's C interface.
#include "io/image_reader_plugin.h"

#include <cstdio>
#include <memory>
#include <string>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

namespace {

struct Opened {
  std::unique_ptr<OIIO::Filesystem::IOMemReader> proxy;  // encoded bytes in memory, or null
  std::unique_ptr<OIIO::ImageInput> input;
};

void set_error(char* error, size_t size, const std::string& text) {
  if (size > 0) std::snprintf(error, size, "%s", text.c_str());
}

void* open_file(const char* path, char* error, size_t error_size) {
  auto opened = std::make_unique<Opened>();
  opened->input = OIIO::ImageInput::open(path);
  if (!opened->input) {
    set_error(error, error_size, OIIO::geterror());
    return nullptr;
  }
  return opened.release();
}

void* open_memory(const unsigned char* bytes, size_t size, const char* format, char* error, size_t error_size) {
  auto opened = std::make_unique<Opened>();
  opened->proxy = std::make_unique<OIIO::Filesystem::IOMemReader>(const_cast<unsigned char*>(bytes), size);
  opened->input = OIIO::ImageInput::create(format, /*do_open=*/false);
  OIIO::ImageSpec spec;
  if (!opened->input || !opened->input->set_ioproxy(opened->proxy.get()) ||
      !opened->input->open(std::string("image.") + format, spec)) {
    set_error(error, error_size, opened->input && opened->input->has_error() ? opened->input->geterror() : "");
    (void)OIIO::geterror();  // clear OpenImageIO's pending message
    return nullptr;
  }
  return opened.release();
}

bool is_integer(const OIIO::TypeDesc& format) {
  return format == OIIO::TypeDesc::UINT8 || format == OIIO::TypeDesc::UINT16;
}

void header(void* handle, LuzImageHeader* out) {
  const OIIO::ImageInput& input = *static_cast<Opened*>(handle)->input;
  const OIIO::ImageSpec& spec = input.spec();
  const std::string format = input.format_name();
  out->width = spec.width;
  out->height = spec.height;
  out->channels = spec.nchannels;
  out->bytes_per_channel = is_integer(spec.format) ? int(spec.format.size()) : 4;
  out->png_or_jpeg = format == "png" || format == "jpeg";
}

// 8 and 16-bit files (PNG, JPEG) are read in their own format straight into the caller's buffer:
// read_image would first allocate a scratch buffer of its own, 64 MB whatever the image's size.
// Other formats (EXR, HDR) are read as floats.
int read(void* handle, void* pixels, char* error, size_t error_size) {
  OIIO::ImageInput& input = *static_cast<Opened*>(handle)->input;
  const OIIO::ImageSpec& spec = input.spec();
  const bool read = is_integer(spec.format)
                        ? input.read_native_scanlines(0, 0, spec.y, spec.y + spec.height, spec.z, 0, spec.nchannels, pixels)
                        : input.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels);
  if (!read) set_error(error, error_size, input.geterror());
  return read ? 1 : 0;
}

void close(void* handle) { delete static_cast<Opened*>(handle); }

constexpr LuzImageReader kReader = {open_file, open_memory, header, read, close};

}  // namespace

extern "C" __attribute__((visibility("default"))) const LuzImageReader* luz_image_reader(void) { return &kReader; }
