#pragma once
// The two picture formats Luz writes, encoded here (deflate, from libdeflate, is the only library
// they need), so that writing a picture loads nothing else.
#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"

namespace luz::io {

// A PNG of 8-bit RGB pixels, rows top to bottom (ISO/IEC 15948, the W3C PNG specification):
// each row filtered by whichever of the five filters leaves the smallest sum of absolute
// differences (the specification's recommended heuristic, 12.8), then deflated; an sRGB chunk
// says how the values are encoded.
std::string encode_png(const std::vector<uint8_t>& rgb, int width, int height);

// A scanline OpenEXR file of 32-bit float R, G, B channels, ZIP-compressed in blocks of 16
// scanlines (the layout of openexr.com's "OpenEXR File Layout" and "Technical Introduction").
std::string encode_exr(const Image& image);

}  // namespace luz::io
