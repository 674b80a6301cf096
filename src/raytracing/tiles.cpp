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

}  // namespace luz::rt
