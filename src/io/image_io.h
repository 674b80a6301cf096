#pragma once
// Image files: PNG and OpenEXR written by Luz's own encoders (image_encoders.h); PNG, JPEG,
// Radiance HDR and OpenEXR read by stb_image and tinyexr in this process (image_decoders.h).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/scene.h"

namespace luz::io {

// The largest image read (textures, --environment, any read_image): 16384 pixels per side and
// 4096 x 4096 = 16.8 million pixels in all, about 200 MB of linear RGB floats. Bigger images are
// refused from their header, before decoding.
inline constexpr int kMaxImageSide = 16384;
inline constexpr int64_t kMaxImagePixels = int64_t(4096) * 4096;

// Writes `.exr` as linear float radiance, `.png` as radiance x 2^exposure through the sRGB
// curve, 8 bit (SCENES.md "Image output"). The file appears whole or not at all: the image is
// written beside it under a temporary name, then renamed (and the temporary removed if SIGINT or
// SIGTERM arrives meanwhile). An image with a non-finite pixel is refused. Throws luz::Error
// (kind output).
void write_image(const Image& image, const std::filesystem::path& path, float exposure);

// Reads a PNG, JPEG, Radiance HDR or OpenEXR file (told apart by their magic numbers, whatever
// the file's name) as linear RGB: 8 and 16-bit files are sRGB-decoded, float files taken as they
// are. Throws luz::Error (file_missing when the file is not there or cannot be read, bad_value
// when it is not such an image, its header claims too large a size, or it does not decode).
Image read_image(const std::filesystem::path& path);

// Decodes an encoded image (PNG or JPEG bytes, as glTF embeds them) into a texture of linear
// texels, sRGB-decoded; std::nullopt with `error` set when the bytes are not such an image.
std::optional<Texture> decode_texture(const std::vector<unsigned char>& bytes,
                                      const std::string& name, std::string& error);

bool is_supported_output(const std::filesystem::path& path);  // .png or .exr
bool is_png_output(const std::filesystem::path& path);        // the output an exposure changes

}  // namespace luz::io
