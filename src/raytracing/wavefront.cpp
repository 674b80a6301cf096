// The wavefront renderer (wavefront.h). Sections: [queues] [one tile's samples]
#include "raytracing/wavefront.h"

#include <algorithm>
#include <utility>

#include "raytracing/sampling.h"

namespace luz::rt {

// ---- [queues] -----------------------------------------------------------------------------------
// One generation of rays, as a structure of arrays: the rays contiguous for Embree's stream, the
// rest read once per ray by the shading loop. Cleared, never shrunk: after the first tiles a
// thread's queues have the capacity they need and a tile allocates nothing.
struct RayQueue {
  std::vector<Ray> rays;
  std::vector<RayKind> kinds;
  std::vector<uint32_t> samples;   // the primary ray whose tree the ray belongs to
  std::vector<Rgb> throughputs;    // the product of the weights from that primary ray down
  std::vector<uint64_t> seeds;     // its place in the ray tree (sampling.h)

  size_t size() const { return rays.size(); }
  void clear() {
    rays.clear();
    kinds.clear();
    samples.clear();
    throughputs.clear();
    seeds.clear();
  }
  void push(const Ray& ray, RayKind kind, uint32_t sample, const Rgb& throughput, uint64_t seed) {
    rays.push_back(ray);
    kinds.push_back(kind);
    samples.push_back(sample);
    throughputs.push_back(throughput);
    seeds.push_back(seed);
  }
  void append(const RayQueue& other) {
    rays.insert(rays.end(), other.rays.begin(), other.rays.end());
    kinds.insert(kinds.end(), other.kinds.begin(), other.kinds.end());
    samples.insert(samples.end(), other.samples.begin(), other.samples.end());
    throughputs.insert(throughputs.end(), other.throughputs.begin(), other.throughputs.end());
    seeds.insert(seeds.end(), other.seeds.begin(), other.seeds.end());
  }
};

namespace {

// Everything one generation needs, kept per thread and reused from tile to tile.
struct Scratch {
  RayQueue queue, reflected, transmitted;  // this generation; the next one's two kinds
  std::vector<Hit> hits;
  std::vector<SurfacePoint> points;
  std::vector<LightSample> lights;  // every hit's light samples, hit k's from first[k]
  std::vector<size_t> first;
  std::vector<Ray> shadow_rays;
  BlockedFlags blocked;
};

}  // namespace

Wavefront::Wavefront(const Scene& scene, Whitted& shading, const Intersector& intersector,
                     const WhittedOptions& options, Counters& counters, std::vector<RecordedRay>* log)
    : scene_(scene), shading_(shading), intersector_(intersector), options_(options),
      counters_(counters), log_(log) {}

// Counted by kind with one pass over the kinds each (a counter incremented ray by ray waits on its
// own previous increment), and logged ray by ray when the benchmark keeps them.
void Wavefront::count(const RayQueue& queue) {
  if (log_) {
    for (size_t k = 0; k < queue.size(); ++k) log_->push_back({queue.rays[k], queue.kinds[k]});
  }
  for (const RayKind kind : {RayKind::primary, RayKind::reflected, RayKind::transmitted})
    counters_[kind] += uint64_t(std::count(queue.kinds.begin(), queue.kinds.end(), kind));
}

void Wavefront::count(std::span<const Ray> rays, RayKind kind) {
  if (log_)
    for (const Ray& ray : rays) log_->push_back({ray, kind});
  counters_[kind] += rays.size();
}

// ---- [one tile's samples] -----------------------------------------------------------------------
void Wavefront::trace(std::span<const Ray> primary, std::span<const uint64_t> seeds,
                      const Rgb& weight, std::span<Rgb> radiance) {
  thread_local Scratch scratch;
  RayQueue& queue = scratch.queue;
  queue.clear();
  for (size_t i = 0; i < primary.size(); ++i)
    queue.push(primary[i], RayKind::primary, uint32_t(i), weight, seeds[i]);

  // Slide 26's depth: primary rays have depth 1, and a hit at depth d spawns rays while d < max.
  for (int depth = 1; queue.size() > 0; ++depth) {
    const size_t n = queue.size();
    const std::span<const Ray> rays = queue.rays;
    count(queue);

    // 1. "Determinar intersección con objeto más cercano", for the whole queue at once.
    scratch.hits.resize(n);
    intersector_.intersect(rays, scratch.hits, counters_.intersection_tests);

    // 2. "calcular la normal", then the light samples of each hit from its ray's seed. Two loops:
    // each body is short enough for the processor to overlap the square roots and divisions of
    // several hits.
    scratch.points.resize(n);
    for (size_t k = 0; k < n; ++k)
      if (scratch.hits[k].found()) shading_.surface_at(rays[k], scratch.hits[k], scratch.points[k]);
    scratch.first.resize(n + 1);
    scratch.lights.clear();
    for (size_t k = 0; k < n; ++k) {
      scratch.first[k] = scratch.lights.size();
      if (scratch.hits[k].found())
        shading_.light_samples(scratch.points[k], -rays[k].direction, queue.seeds[k], scratch.lights);
    }
    scratch.first[n] = scratch.lights.size();

    // 3. Every shadow ray of the generation, as one stream.
    const bool* blocked = nullptr;  // shadows off: no light is blocked
    if (options_.shadows) {
      const size_t m = scratch.lights.size();
      scratch.shadow_rays.resize(m);
      for (size_t j = 0; j < m; ++j) scratch.shadow_rays[j] = scratch.lights[j].shadow;
      count(scratch.shadow_rays, RayKind::shadow);
      const std::span<bool> flags = scratch.blocked.first(m);
      intersector_.occluded(scratch.shadow_rays, flags, counters_.intersection_tests);
      blocked = flags.data();
    }

    // 4. Each hit's local colour, weighted by its throughput, into its sample's radiance; then
    // (a second loop, as in step 2) its reflected and transmitted rays, weighted once more, into
    // the next generation.
    for (size_t k = 0; k < n; ++k) {
      const Rgb& throughput = queue.throughputs[k];
      if (!scratch.hits[k].found()) {
        radiance[queue.samples[k]] += throughput * scene_.background;
        continue;
      }
      const size_t first = scratch.first[k];
      const std::span<const LightSample> lights(scratch.lights.data() + first, scratch.first[k + 1] - first);
      radiance[queue.samples[k]] +=
          throughput * shading_.local_color(scratch.points[k], lights, blocked ? blocked + first : nullptr);
    }
    scratch.reflected.clear();
    scratch.transmitted.clear();
    if (depth < max_depth_of(options_)) {
      SecondaryRays spawned;
      for (size_t k = 0; k < n; ++k) {
        if (!scratch.hits[k].found()) continue;
        shading_.secondary_rays(scratch.points[k], rays[k], spawned);
        for (const SecondaryRay& s : spawned) {
          RayQueue& next = s.kind == RayKind::reflected ? scratch.reflected : scratch.transmitted;
          next.push(s.ray, s.kind, queue.samples[k], queue.throughputs[k] * s.weight,
                    branch_seed(queue.seeds[k], s.kind));
        }
      }
    }

    // The next generation: the reflected rays, then the transmitted ones, each in the order of
    // their parents, so that neighbours in a stream mostly leave neighbouring hits in one way.
    std::swap(scratch.queue, scratch.reflected);
    queue.append(scratch.transmitted);
  }
}

}  // namespace luz::rt
