#include "raytracing/tiles.h"

#include <algorithm>

namespace luz::rt {

std::vector<Tile> make_tiles(int width, int height, int size) {
  size = std::max(size, 1);
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += size)
    for (int x = 0; x < width; x += size)
      tiles.push_back({x, y, std::min(x + size, width), std::min(y + size, height)});
  return tiles;
}

std::vector<Tile> joined_tiles(std::vector<Tile> tiles, int width) {
  std::sort(tiles.begin(), tiles.end(),
            [](const Tile& a, const Tile& b) { return a.y0 != b.y0 ? a.y0 < b.y0 : a.x0 < b.x0; });
  std::vector<Tile> runs;
  for (const Tile& t : tiles) {
    if (!runs.empty() && runs.back().y0 == t.y0 && runs.back().y1 == t.y1 && runs.back().x1 == t.x0)
      runs.back().x1 = t.x1;
    else
      runs.push_back(t);
  }
  std::vector<Tile> joined;
  const auto whole_row = [width](const Tile& t) { return t.x0 == 0 && t.x1 == width; };
  for (const Tile& r : runs) {
    if (!joined.empty() && whole_row(joined.back()) && whole_row(r) && joined.back().y1 == r.y0)
      joined.back().y1 = r.y1;
    else
      joined.push_back(r);
  }
  return joined;
}

}  // namespace luz::rt
