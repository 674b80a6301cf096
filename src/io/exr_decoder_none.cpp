// The web page's stand-in for exr_decoder.cpp: tinyexr needs zlib, which Emscripten only
// downloads, so the page reads PNG, JPEG and Radiance HDR and says so for OpenEXR.
#include "core/i18n.h"
#include "io/image_decoders.h"

namespace luz::io {

std::optional<Image> decode_exr(std::span<const unsigned char>, std::string& error) {
  error = unreadable(ImageFormat::exr, i18n::tr("this build reads no OpenEXR images"));
  return std::nullopt;
}

}  // namespace luz::io
