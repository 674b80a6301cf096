#pragma once
// The settings of the path tracer (slide 14's equation solved by Monte Carlo). One struct,
// defaults here only: `luz render --model path` fills it from flags, tests construct it, the
// viewer's panel will edit it.
#include <cstdint>

namespace luz::rt {

struct PathOptions {
  // Depth counts as on slide 26 (SCENES.md): the primary ray has depth 1 and a hit at depth d
  // spawns the next ray only while d < max_depth. So 1 is direct light only (emission seen and
  // the lights' next-event estimates at the first hit); 0 is taken as 1.
  int max_depth = 16;
  // Russian roulette from this depth on: a path continues with probability
  // q = min(max(throughput), 0.95) and its throughput is divided by q, which keeps the
  // estimator unbiased (Arvo & Kirk 1990) and ends the long paths that carry little light.
  int roulette_depth = 4;
  int spp = 16;             // samples per pixel (any positive number)
  uint32_t seed = 0;        // the same seed, size and spp give the same picture bit for bit
  bool textures = true;     // baseColorTexture multiplies kd
  int tile_size = 16;       // pixels per side of a tile, the unit of parallel work
  bool operator==(const PathOptions&) const = default;
};

inline int max_depth_of(const PathOptions& options) {
  return options.max_depth < 1 ? 1 : options.max_depth;
}

}  // namespace luz::rt
