#pragma once
// A walk over a JPEG's segments (ITU T.81, B.1.1): what stb_image will read from them, checked
// before it reads it. A segment is a marker (FF, then a code) and, except for SOI, EOI and the
// restart markers, a big-endian length that counts itself and the data after it; a scan (SOS) is
// followed by its entropy-coded data, in which FF is followed by 00 (a stuffed byte) or a restart
// marker, so the next segment starts at the first FF followed by anything else. Bytes that look
// like a marker inside a segment's data (an EXIF thumbnail in APP1, a comment) are data.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace luz::io {

struct JpegSegments {
  // Width and height of the first frame header stb_image reads (SOF0, SOF1 or SOF2: baseline,
  // extended and progressive Huffman coding).
  std::optional<std::pair<int64_t, int64_t>> size;
  // A Huffman table (DHT) stb_image 2.27 would build past its end: its 16 counts of codes add up
  // to more than the 256 symbols a table holds (ITU T.81, B.2.4.2). Empty when there is none.
  std::string huffman_problem;
};

// Walks from SOI to EOI or the end of the bytes. Where stb_image skips bytes between segments to
// find the next FF (some writers pad), so does the walk; where a segment's length runs past the
// end, its tables read as zeros, as stb_image reads them.
JpegSegments walk_jpeg_segments(std::span<const unsigned char> bytes);

}  // namespace luz::io
