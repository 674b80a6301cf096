#pragma once
// The image cut into square tiles, the unit of parallel work (pbrt renders 16x16 tiles the same
// way) and of progress: the viewer uploads a tile as soon as it is done.
#include <vector>

namespace luz::rt {

struct Tile {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels [x0, x1) x [y0, y1)
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

// Row by row from the top left; the last row and column may be narrower.
std::vector<Tile> make_tiles(int width, int height, int size);

// The same pixels as `tiles` (tiles of make_tiles, each once, in any order) in fewer rectangles:
// tiles side by side in a row of tiles joined, then rows of the picture's whole `width` one above
// the other. The viewer uploads a rectangle a call, and a call costs more than its pixels.
std::vector<Tile> joined_tiles(std::vector<Tile> tiles, int width);

}  // namespace luz::rt
