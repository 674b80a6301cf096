#pragma once
// Whitted's tracer breadth first: the wavefront renderer. The same rays as slide 26's recursion
// (Whitted::trace), traced generation by generation instead of depth first:
//
//   queue := the primary rays of a tile's samples
//   while the queue is not empty:
//     1. the queue's nearest hits, as an Embree stream for each kind of ray
//     2. each hit's surface point, light samples and local colour before its lights, and its
//        reflected and transmitted rays into the next queue
//     3. all the light samples' shadow rays, as one stream
//     4. each hit's local colour (its unblocked lights added) x its throughput (the product of
//        the weights kr, kt and 1/spp from its primary ray down) added to its sample's radiance
//
// Embree traces a stream of rays faster than the same rays one by one (it traverses them in
// packets, and its memory stays in cache). Step 2 runs over 64 hits at a time as a structure of
// arrays (hit_lanes.h), in loops the compiler vectorises.
// By the distributive law the sum of throughput x local colour over a sample's ray tree is what
// the recursion's nested local + kr (local + kr (...)) + kt (...) adds up to; only the rounding
// differs. The arithmetic of every per-hit step is the recursion's own (hit_math.h), the shadow
// rays go to Embree in the order the recursion's first generation sends them (Embree may answer
// a ray that grazes an edge by the rays beside it in its packet), and every ray draws its random
// numbers from its place in the tree (sampling.h), so the two renderers agree within float
// rounding (test_whitted_streams holds them to it on every shipped scene).
//
// The recursion stays the reference: it draws the ray tree (trace_pixel) and serves adaptive
// sampling, whose samples depend on each other's results.
#include <cstdint>
#include <span>
#include <vector>

#include "core/scene.h"
#include "raytracing/counters.h"
#include "raytracing/hit_lanes.h"
#include "raytracing/intersector.h"
#include "raytracing/ray.h"
#include "raytracing/whitted.h"
#include "raytracing/whitted_options.h"

namespace luz::rt {

class Wavefront {
public:
  // `shading`: the Whitted tracer whose per-hit functions shade the hits (the hybrid's diffuse
  // source is its), `meshes` lane_meshes() of it. `log`: where the traced rays are kept for the
  // benchmark, or nullptr.
  Wavefront(const Scene& scene, Whitted& shading, std::span<const LaneMesh> meshes,
            const Intersector& intersector, const WhittedOptions& options, Counters& counters,
            std::vector<RecordedRay>* log);

  // Where the caller writes a tile's n primary rays, and the seed of each one's ray tree
  // (sampling.h), before trace(): this thread's first queue itself, so they are not copied.
  struct FirstGeneration {
    std::span<Ray> rays;
    std::span<uint64_t> seeds;
  };
  FirstGeneration first_generation(size_t n);

  // For each primary ray i of first_generation(): weight x the radiance arriving along it,
  // written to radiance[i]. Counts every ray traced, as the recursion counts them.
  void trace(const Rgb& weight, std::span<Rgb> radiance);

private:
  // Counts the rays of a stream of one kind as traced (and logs them).
  void count(std::span<const Ray> rays, RayKind kind);

  const Scene& scene_;
  Whitted& shading_;
  std::span<const LaneMesh> meshes_;
  const Intersector& intersector_;
  const WhittedOptions& options_;
  Counters& counters_;
  std::vector<RecordedRay>* log_;
};

}  // namespace luz::rt
