#include "io/jpeg_segments.h"

#include "core/i18n.h"

namespace luz::io {
using i18n::trf;

namespace {

constexpr unsigned char kStartOfImage = 0xd8, kEndOfImage = 0xd9, kHuffmanTables = 0xc4;

bool is_restart(unsigned char code) { return code >= 0xd0 && code <= 0xd7; }
// The frame headers stb_image decodes: baseline, extended and progressive Huffman coding.
bool is_frame_header(unsigned char code) { return code == 0xc0 || code == 0xc1 || code == 0xc2; }
// Markers without a length (T.81, B.1.1.3): SOI, EOI, the restarts and TEM; and FF 00, a stuffed
// FF byte in entropy-coded data (F.1.2.3), no marker at all.
bool stands_alone(unsigned char code) {
  return code == 0x00 || code == 0x01 || code == kStartOfImage || code == kEndOfImage || is_restart(code);
}

// A byte, or 0 past the end of the bytes: what stb_image reads there.
unsigned char byte(std::span<const unsigned char> bytes, size_t at) { return at < bytes.size() ? bytes[at] : 0; }
size_t big_endian16(std::span<const unsigned char> bytes, size_t at) {
  return size_t(byte(bytes, at)) << 8 | byte(bytes, at + 1);
}

struct Marker {
  unsigned char code = 0;
  size_t after = 0;  // where the segment's length (or the next marker) starts
};

// The first marker at or after `at`: an FF, the fill FFs after it (T.81, B.1.1.2), and a code.
// Bytes before it are passed over, as stb_image passes over padding between segments.
std::optional<Marker> next_marker(std::span<const unsigned char> bytes, size_t at) {
  for (; at < bytes.size(); ++at) {
    if (bytes[at] != 0xff) continue;
    size_t code = at + 1;
    while (code < bytes.size() && bytes[code] == 0xff) ++code;
    if (code == bytes.size()) return std::nullopt;
    return Marker{bytes[code], code + 1};
  }
  return std::nullopt;
}

// A DHT segment whose length starts at `at`: tables while the length says bytes remain, each a
// class and id, 16 counts of codes and then as many symbols, read as stb_image 2.27 reads them.
std::string huffman_problem(std::span<const unsigned char> bytes, size_t at) {
  int64_t remaining = int64_t(big_endian16(bytes, at)) - 2;
  for (size_t table = at + 2; remaining > 0;) {
    size_t symbols = 0;
    for (size_t length = 0; length < 16; ++length) symbols += byte(bytes, table + 1 + length);
    if (symbols > 256) return trf("a Huffman table of {} codes (at most 256)", symbols);
    table += 17 + symbols;
    remaining -= int64_t(17 + symbols);
  }
  return {};
}

}  // namespace

JpegSegments walk_jpeg_segments(std::span<const unsigned char> bytes) {
  JpegSegments found;
  if (bytes.size() < 2 || bytes[0] != 0xff || bytes[1] != kStartOfImage) return found;
  size_t at = 2;
  while (const std::optional<Marker> marker = next_marker(bytes, at)) {
    at = marker->after;
    if (marker->code == kEndOfImage) break;
    if (stands_alone(marker->code)) continue;
    if (marker->code == kHuffmanTables && found.huffman_problem.empty())
      found.huffman_problem = huffman_problem(bytes, at);
    // The frame header: its length, the sample precision, then height and width (T.81, B.2.2).
    if (is_frame_header(marker->code) && !found.size && at + 7 <= bytes.size())
      found.size = std::pair{int64_t(big_endian16(bytes, at + 5)), int64_t(big_endian16(bytes, at + 3))};
    const size_t length = big_endian16(bytes, at);
    if (length < 2) break;  // a length that does not count itself: stb_image stops there too
    // After a scan (SOS) its entropy-coded data follows, where an FF is followed by 00 (a stuffed
    // byte) or a restart marker, which the next turn passes over, up to the next segment.
    at += length;
  }
  return found;
}

}  // namespace luz::io
