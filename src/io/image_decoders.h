#pragma once
// The image formats Luz reads, decoded in this process from bytes in memory: PNG, JPEG and
// Radiance HDR by stb_image, OpenEXR by tinyexr (Debian's libstb-dev and libtinyexr-dev). Each
// decoder reads the size its header claims and refuses it against the caps before it allocates a
// byte of pixels.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "core/image.h"

namespace luz::io {

enum class ImageFormat { png, jpeg, hdr, exr };

// The format the magic number at the start of `bytes` names, if it is one of the four.
std::optional<ImageFormat> image_format(std::span<const unsigned char> bytes);

// "PNG", "JPEG", "Radiance HDR", "OpenEXR": for messages.
const char* format_label(ImageFormat format);

// Linear RGB: 8 and 16-bit values are sRGB-decoded, floats taken as they are; grey is
// replicated, alpha dropped. std::nullopt with `error` set when the bytes are not a readable
// image of `format`: "header: ..." when the claimed size is refused, "not a readable PNG image:
// ..." when the decoder fails.
std::optional<Image> decode_image(std::span<const unsigned char> bytes, ImageFormat format, std::string& error);

// ---- For the decoders ----

// The caps on an image of width x height with `pixel_bytes` bytes a pixel and, for a PNG or JPEG
// of `encoded_bytes` (0: not one), what so many bytes can hold: an empty string when it passes.
std::string size_problem(int64_t width, int64_t height, int64_t pixel_bytes, uintmax_t encoded_bytes);

// "not a readable <format> image: <why>".
std::string unreadable(ImageFormat format, const std::string& why);

// stb_image_decoder.cpp: PNG, JPEG and Radiance HDR.
std::optional<Image> decode_with_stb(std::span<const unsigned char> bytes, ImageFormat format, std::string& error);
// exr_decoder.cpp: scanline and tiled single-part OpenEXR, half, float or uint channels.
std::optional<Image> decode_exr(std::span<const unsigned char> bytes, std::string& error);

}  // namespace luz::io
