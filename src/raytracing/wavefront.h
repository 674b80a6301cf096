#pragma once
// Whitted's tracer breadth first: the wavefront renderer. The same rays as slide 26's recursion
// (Whitted::trace), traced generation by generation instead of depth first:
//
//   queue := the primary rays of a tile's samples
//   while the queue is not empty:
//     1. the queue's nearest hits, as one Embree stream
//     2. each hit's surface point and light samples
//     3. all their shadow rays, as one stream
//     4. each hit's local colour x its throughput (the product of the weights kr, kt and 1/spp
//        from its primary ray down) added to its sample's radiance; its reflected and
//        transmitted rays into the next queue
//
// Embree traces a stream of rays faster than the same rays one by one (it traverses them in
// packets, and its memory stays in cache), and the shading of a queue runs as one loop.
// By the distributive law the sum of throughput x local colour over a sample's ray tree is what
// the recursion's nested local + kr (local + kr (...)) + kt (...) adds up to; only the rounding
// differs. Every per-hit step is the recursion's own function (Whitted::surface_at,
// light_samples, local_color, secondary_rays), and every ray draws its random numbers from its
// place in the tree (sampling.h), so the two renderers agree within float rounding
// (test_whitted_streams holds them to it on every shipped scene).
//
// The recursion stays the reference: it draws the ray tree (trace_pixel) and serves adaptive
// sampling, whose samples depend on each other's results.
#include <cstdint>
#include <span>
#include <vector>

#include "core/scene.h"
#include "raytracing/counters.h"
#include "raytracing/intersector.h"
#include "raytracing/ray.h"
#include "raytracing/whitted.h"
#include "raytracing/whitted_options.h"

namespace luz::rt {

struct RayQueue;  // one generation of rays (wavefront.cpp)

class Wavefront {
public:
  // `shading`: the Whitted tracer whose per-hit functions shade the hits (the hybrid's diffuse
  // source is its). `log`: where the traced rays are kept for the benchmark, or nullptr.
  Wavefront(const Scene& scene, Whitted& shading, const Intersector& intersector,
            const WhittedOptions& options, Counters& counters, std::vector<RecordedRay>* log);

  // For each primary ray i (whose ray tree has seed seeds[i], see sampling.h): weight x the
  // radiance arriving along it, added to radiance[i]. Counts every ray traced, as the
  // recursion counts them.
  void trace(std::span<const Ray> primary, std::span<const uint64_t> seeds, const Rgb& weight,
             std::span<Rgb> radiance);

private:
  // Counts every ray of a generation, or of a stream of one kind, as traced (and logs them).
  void count(const RayQueue& queue);
  void count(std::span<const Ray> rays, RayKind kind);

  const Scene& scene_;
  Whitted& shading_;
  const Intersector& intersector_;
  const WhittedOptions& options_;
  Counters& counters_;
  std::vector<RecordedRay>* log_;
};

}  // namespace luz::rt
