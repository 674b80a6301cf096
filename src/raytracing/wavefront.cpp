// The wavefront renderer (wavefront.h). Sections: [queues] [one tile's samples]
#include "raytracing/wavefront.h"

#include <algorithm>
#include <utility>

#include "raytracing/sampling.h"

namespace luz::rt {

// ---- [queues] -----------------------------------------------------------------------------------
// One generation of rays, as a structure of arrays: the rays contiguous for Embree's stream, the
// rest read once per ray by the shading loop. A ray's kind is known from where it stands: a first
// generation is all primary rays, a later one its reflected rays, then its transmitted ones. Its
// first size() entries are the generation; the arrays only grow: after the first tiles a thread's
// queues have the room they need, a tile allocates nothing, and adding a ray checks the room
// once, not once per array. A first generation holds rays and seeds only: its ray q is sample q,
// and all its rays have the same throughput.
struct RayQueue {
  std::vector<Ray> rays;
  std::vector<uint32_t> samples;   // the primary ray whose tree the ray belongs to
  std::vector<Rgb> throughputs;    // the product of the weights from that primary ray down
  std::vector<uint64_t> seeds;     // its place in the ray tree (sampling.h)

  size_t size() const { return size_; }
  std::span<const Ray> generation() const { return {rays.data(), size_}; }
  void clear() { size_ = 0; }
  // Up to n rays more, written after the last through pointers a loop keeps in registers (through
  // the vectors, the compiler would reload them and the size after every store), each kept where
  // its flag holds: no branch on a flag that varies at random (a mirror's lanes among walls).
  // appended() makes the kept ones the queue's.
  struct Appender {
    Ray* rays;
    uint32_t* samples;
    Rgb* throughputs;
    uint64_t* seeds;
    size_t size;
    void put(const Ray& ray, uint32_t sample, const Rgb& throughput, uint64_t seed, bool keep) {
      rays[size] = ray;
      samples[size] = sample;
      throughputs[size] = throughput;
      seeds[size] = seed;
      size += keep ? 1 : 0;
    }
  };
  Appender appender(size_t n) {
    if (size_ + n > rays.size()) grow(2 * (size_ + n));
    return {rays.data(), samples.data(), throughputs.data(), seeds.data(), size_};
  }
  void appended(const Appender& appender) { size_ = appender.size; }
  // Room for a first generation of n rays, for the caller to write their rays and seeds.
  void start(size_t n) {
    if (n > rays.size()) grow(n);
    size_ = n;
  }
  void append(const RayQueue& other) {
    const size_t n = other.size(), at = size_;
    if (at + n > rays.size()) grow(2 * (at + n));
    const auto to = std::ptrdiff_t(at), count = std::ptrdiff_t(n);
    std::copy_n(other.rays.begin(), count, rays.begin() + to);
    std::copy_n(other.samples.begin(), count, samples.begin() + to);
    std::copy_n(other.throughputs.begin(), count, throughputs.begin() + to);
    std::copy_n(other.seeds.begin(), count, seeds.begin() + to);
    size_ += n;
  }

private:
  void grow(size_t capacity) {
    rays.resize(capacity);
    samples.resize(capacity);
    throughputs.resize(capacity);
    seeds.resize(capacity);
  }
  size_t size_ = 0;
};

namespace {

// Everything one generation needs, kept per thread and reused from tile to tile.
struct Scratch {
  RayQueue queue, reflected, transmitted;  // this generation; the next one's two kinds
  std::vector<Hit> hits;
  std::vector<uint32_t> found;  // the queue indices of the generation's hits
  HitLanes lanes;
  LaneLights lights;   // the generation's light samples, hit by hit
  BlockedFlags blocked;
  std::vector<Rgb> local;  // each hit's local colour
  SpawnLanes spawned;
};

// The indices of the hits that found a surface, in order, in `found`'s storage. Each index is
// written and kept where its ray hit: no branch, which on a generation of mirrored rays that hit
// or miss at random would be mispredicted at every other ray.
std::span<const uint32_t> found_hits(std::span<const Hit> hits, std::vector<uint32_t>& found) {
  if (found.size() < hits.size()) found.resize(hits.size());
  size_t m = 0;
  for (size_t q = 0; q < hits.size(); ++q) {
    found[m] = uint32_t(q);
    m += hits[q].found() ? 1 : 0;
  }
  return {found.data(), m};
}

// The reflected and transmitted rays of the lanes' hits, weighted by their parents' throughput,
// into the next generation's two queues; with their seeds where shading reads them (`seeded`).
// `first`: the queue is a first generation, each ray of throughput `weight`.
void spawn_rays(const HitLanes& lanes, const RayQueue& queue, bool first, const Rgb& weight, bool seeded,
                SpawnLanes& spawned, RayQueue& reflected, RayQueue& transmitted) {
  lanes.secondary_rays(spawned);
  if (!spawned.any) return;
  // The rays of one kind: lane k's leaves origin[k] along direction[k], its parent's throughput x
  // factor[k], where keep[k] is set.
  const auto spawn = [&](RayQueue& to, RayKind kind, const Vec3Lanes& origin, const Vec3Lanes& direction,
                         const Vec3Lanes& factor, const int32_t* keep) {
    RayQueue::Appender out = to.appender(lanes.size());
    for (size_t k = 0; k < lanes.size(); ++k) {
      const uint32_t q = lanes.ray(k);
      const uint32_t sample = first ? q : queue.samples[q];
      const Rgb throughput = first ? weight : queue.throughputs[q];
      const uint64_t seed = queue.seeds[q];
      out.put(Ray{origin[k], direction[k]}, sample, throughput * factor[k], seeded ? branch_seed(seed, kind) : 0,
              keep[k] != 0);
    }
    to.appended(out);
  };
  spawn(reflected, RayKind::reflected, spawned.reflected_origin, spawned.reflected_direction, spawned.kr,
        spawned.reflects);
  if (spawned.any_transmits)
    spawn(transmitted, RayKind::transmitted, spawned.transmitted_origin, spawned.transmitted_direction,
          spawned.kt, spawned.transmits);
}

Scratch& scratch_of_this_thread() {
  thread_local Scratch scratch;
  return scratch;
}

}  // namespace

Wavefront::Wavefront(const Scene& scene, Whitted& shading, std::span<const LaneMesh> meshes,
                     const Intersector& intersector, const WhittedOptions& options, Counters& counters,
                     std::vector<RecordedRay>* log)
    : scene_(scene), shading_(shading), meshes_(meshes), intersector_(intersector), options_(options),
      counters_(counters), log_(log) {}

void Wavefront::count(std::span<const Ray> rays, RayKind kind) {
  if (log_)
    for (const Ray& ray : rays)
      log_->push_back({ray, kind, &ray == rays.data() ? Traced::starts_stream : Traced::in_stream});
  counters_[kind] += rays.size();
}

// ---- [one tile's samples] -----------------------------------------------------------------------
Wavefront::FirstGeneration Wavefront::first_generation(size_t n) {
  RayQueue& queue = scratch_of_this_thread().queue;
  queue.start(n);
  return {{queue.rays.data(), n}, {queue.seeds.data(), n}};
}

void Wavefront::trace(const Rgb& weight, std::span<Rgb> radiance) {
  Scratch& scratch = scratch_of_this_thread();
  RayQueue& queue = scratch.queue;

  HitLanes& lanes = scratch.lanes;
  lanes.shade_with(scene_, shading_, options_, meshes_);
  // Slide 26's depth: primary rays have depth 1, and a hit at depth d spawns rays while d < max.
  size_t reflected = 0;  // of a later generation, its first rays
  for (int depth = 1; queue.size() > 0; ++depth) {
    const size_t n = queue.size();
    const std::span<const Ray> rays = queue.generation();
    if (depth == 1) {
      count(rays, RayKind::primary);
    } else {
      count(rays.first(reflected), RayKind::reflected);
      count(rays.subspan(reflected), RayKind::transmitted);
    }

    // 1. "Determinar intersección con objeto más cercano", for the whole queue at once: a stream
    // for each kind of ray (the reflected rays leave a surface more alike than with the
    // transmitted ones among them).
    scratch.hits.resize(n);
    const std::span<Hit> hits(scratch.hits);
    const size_t first_kind = depth == 1 ? n : reflected;
    intersector_.intersect(rays.first(first_kind), hits.first(first_kind), counters_.intersection_tests);
    if (first_kind < n)
      intersector_.intersect(rays.subspan(first_kind), hits.subspan(first_kind), counters_.intersection_tests);

    // 2. "calcular la normal", every hit's light samples and the local colour without them, and
    // its reflected and transmitted rays, weighted once more, into the next generation: kLanes
    // hits at a time, in the queue's order (the rays that hit nothing left out first, so that
    // every batch but the last fills its lanes).
    scratch.reflected.clear();
    scratch.transmitted.clear();
    scratch.local.resize(n);
    LaneLights& lights = scratch.lights;
    lights.size = 0;
    const bool spawn = depth < max_depth_of(options_);
    const bool seeded = shading_.draws_random_numbers();
    const std::span<const uint32_t> found = found_hits(hits, scratch.found);
    for (size_t start = 0; start < found.size(); start += kLanes) {
      lanes.load(found.subspan(start, std::min(kLanes, found.size() - start)), rays, hits, queue.seeds);
      lanes.light_samples(lights);
      lanes.unlit_colors(scratch.local);
      if (spawn)
        spawn_rays(lanes, queue, depth == 1, weight, seeded, scratch.spawned, scratch.reflected,
                   scratch.transmitted);
    }

    // 3. Every shadow ray of the generation, as one stream.
    const std::span<const Ray> shadow_rays(lights.shadow.data(), lights.size);
    const bool* blocked = nullptr;  // shadows off: no light is blocked
    if (options_.shadows) {
      count(shadow_rays, RayKind::shadow);
      const std::span<bool> flags = scratch.blocked.first(lights.size);
      intersector_.occluded(shadow_rays, flags, counters_.intersection_tests);
      blocked = flags.data();
    }

    // 4. Each hit's local colour: S_i = 1, each unblocked sample's term, a hit's in the order of
    // its lights. Then each ray's local colour (the background where it hit nothing), weighted
    // by its throughput, into its sample's radiance: the first generation's sets it.
    for (size_t j = 0; j < lights.size; ++j)
      if (!blocked || !blocked[j]) scratch.local[lights.hit[j]] += lights.term[j];
    const auto local = [&](size_t q) {
      return hits[q].found() ? scratch.local[q] : scene_.background;
    };
    if (depth == 1) {
      for (size_t q = 0; q < n; ++q) radiance[q] = weight * local(q);
    } else {
      for (size_t q = 0; q < n; ++q) radiance[queue.samples[q]] += queue.throughputs[q] * local(q);
    }

    // The next generation: the reflected rays, then the transmitted ones, each in the order of
    // their parents, so that neighbours in a stream mostly leave neighbouring hits in one way.
    reflected = scratch.reflected.size();
    std::swap(scratch.queue, scratch.reflected);
    queue.append(scratch.transmitted);
  }
}

}  // namespace luz::rt
