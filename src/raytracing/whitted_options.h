#pragma once
// The switches of the Whitted tracer (slides 20-27). One struct, defaults here only: the viewer's
// panel edits it, `luz render --model whitted` fills it from flags, tests construct it.
#include "core/term_switches.h"

namespace luz::rt {

enum class Sampling {
  stratified,  // spp samples per pixel on a sqrt(spp) x sqrt(spp) grid, jittered (1: the centre)
  adaptive,    // Whitted 1980: rays at the pixel's corners, squares subdivided where they differ
};

// In which order stratified sampling traces a tile's rays (the picture is the same, see
// wavefront.h); adaptive sampling and the ray tree always take the recursion.
enum class RendererKind {
  wavefront,  // generation by generation, each generation's rays and shadow rays as Embree streams
  recursive,  // slide 26's recursion, depth first: the primary and their shadow rays streamed, the
              // deeper rays one by one
};

struct WhittedOptions {
  // Slide 26: the primary ray has depth 1 and a hit at depth d spawns reflected and transmitted
  // rays only while d < max_depth. So 1 is the local model with shadows and no secondary rays;
  // 0 is taken as 1.
  int max_depth = 5;
  bool shadows = true;      // shadow rays (S_i); off: every light counts as unoccluded
  bool fresnel = false;     // kr + kt*F and kt*(1-F) instead of kr and kt (SCENES.md)
  int light_samples = 1;    // per emissive triangle: 1 = its centroid, N = N-rooks over its area

  TermSwitches terms;       // the local formula at every hit, as the local models have it

  // Slide 27's problems and their solutions.
  bool brute_force = false; // every ray against every triangle instead of Embree's BVH
  Sampling sampling = Sampling::stratified;
  int spp = 1;              // stratified: samples per pixel, a square (1, 4, 9, 16, ...)
  int adaptive_levels = 2;  // adaptive: subdivide a pixel at most this often (2: 4x4 squares)
  float adaptive_threshold = 0.05f;  // adaptive: corners differing by more (sRGB-encoded) split

  RendererKind renderer = RendererKind::wavefront;
  int tile_size = 16;       // pixels per side of a tile, the unit of parallel work and progress

  // The viewer tells a stale picture by it (options edited since the trace started).
  bool operator==(const WhittedOptions&) const = default;
};

// The effective maximum depth (0 counts as 1, see max_depth).
inline int max_depth_of(const WhittedOptions& options) {
  return options.max_depth < 1 ? 1 : options.max_depth;
}

}  // namespace luz::rt
