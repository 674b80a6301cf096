// Tiles on TBB. Sections: [slide 26's loop] [adaptive] [streams] [the renderer] [one tile]
// [one pixel]
#include "raytracing/renderer.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <span>
#include <cmath>
#include <utility>

#include "core/parallel_for.h"
#include "core/std_compat.h"
#include "raytracing/brute_force.h"
#include "raytracing/embree_scene.h"
#include "raytracing/hit_lanes.h"
#include "raytracing/sampling.h"
#include "raytracing/wavefront.h"

namespace luz::rt {

namespace {

// The buffers of one tile, kept per thread.
struct TileScratch {
  std::vector<Ray> rays;
  std::vector<Hit> hits;
  std::vector<glm::vec2> offsets;
  std::vector<glm::vec2> points;  // the samples' image points
  std::vector<StreamedAnswers> answers;
  std::vector<size_t> first;
  std::vector<uint64_t> seeds;
  std::vector<Rgb> radiance;
  std::vector<LightSample> lights;
  std::vector<Ray> shadow_rays;
  BlockedFlags blocked;
  void resize(size_t n) {
    if (rays.size() >= n) return;
    rays.resize(n);
    points.resize(n);
    hits.resize(n);
    answers.resize(n);
    first.resize(n + 1);
    seeds.resize(n);
    radiance.resize(n);
  }
};

// The first ray of each kind that the tile traced in a stream starts that stream (Whitted::count
// logs the first generation's rays as in a stream, not knowing which comes first).
void mark_stream_starts(std::vector<RecordedRay>& log) {
  bool started[kRayKinds] = {};
  for (RecordedRay& r : log)
    if (r.traced == Traced::in_stream && !std::exchange(started[size_t(r.kind)], true))
      r.traced = Traced::starts_stream;
}

// Per-thread scratch, reused from tile to tile: no allocation or clearing per tile.
TileScratch& scratch_of_this_thread() {
  thread_local TileScratch scratch;
  return scratch;
}

// Stratified sampling's samples a pixel: a non-square spp is taken down to a square.
int samples_per_pixel(const WhittedOptions& options) {
  const int side = std::max(1, int(std::floor(std::sqrt(double(std::max(options.spp, 1))) + 1e-9)));
  return side * side;
}

// ---- [slide 26's loop] --------------------------------------------------------------------------
//   para cada pixel
//     color := Trazar(rayoPrimario, 1)
//     Poner_pixel(pixel, color)
// with `samples` primary rays a pixel (stratified and jittered; one: the centre), each weighed
// 1/samples, every one traced alone by the recursion.
void trace_pixels(const Tile& tile, const PrimaryRays& camera_rays, int samples, Whitted& whitted,
                  Image& image, Counters& counters) {
  const Rgb weight(1.0f / float(samples));
  std::vector<glm::vec2> offsets;
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      Random jitter(x, y, -1);
      stratified_pixel_samples(samples, jitter, offsets);
      Rgb color(0.0f);  // Trazar(rayoPrimario, 1), for each of the pixel's primary rays
      for (int s = 0; s < samples; ++s) {
        const Ray primary = camera_rays.through(glm::vec2(float(x), float(y)) + offsets[size_t(s)]);
        color += whitted.trace(primary, 1, RayKind::primary, sample_seed(x, y, s), weight);
      }
      image.at(x, y) = color * weight;  // Poner_pixel(pixel, color)
    }
  counters.samples += size_t(tile.width()) * size_t(tile.height()) * size_t(samples);
}

// ---- [adaptive] ---------------------------------------------------------------------------------
// Whitted's adaptive supersampling: corners first (shared by neighbouring pixels), then each
// pixel subdivided where its corners differ. Every point's random numbers are seeded by the
// point itself, so a corner gives the same radiance from either pixel.
void adaptive_tile(const Tile& tile, const PrimaryRays& camera_rays, const WhittedOptions& options,
                   Whitted& whitted, Image& image, Counters& counters) {
  const auto radiance = [&](float x, float y) {
    ++counters.samples;
    return whitted.trace(camera_rays.through({x, y}), 1, RayKind::primary,
                         sample_seed(bit_cast<int>(x), bit_cast<int>(y), 1));
  };
  const int cw = tile.width() + 1;
  std::vector<Rgb> corners(size_t(cw) * size_t(tile.height() + 1));
  for (int y = tile.y0; y <= tile.y1; ++y)
    for (int x = tile.x0; x <= tile.x1; ++x)
      corners[size_t(y - tile.y0) * cw + size_t(x - tile.x0)] = radiance(float(x), float(y));
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      const auto corner = [&](int dx, int dy) {
        return corners[size_t(y - tile.y0 + dy) * cw + size_t(x - tile.x0 + dx)];
      };
      const Rgb c[4] = {corner(0, 0), corner(1, 0), corner(0, 1), corner(1, 1)};
      image.at(x, y) = adaptive_pixel(float(x), float(y), c, options.adaptive_levels,
                                      options.adaptive_threshold, radiance);
    }
}

// ---- [streams] ----------------------------------------------------------------------------------
// The tile's primary rays and each one's seed, sample by sample in pixel order: the samples of
// trace_pixels, made several to an instruction.
void primary_samples(const Tile& tile, const PrimaryRays& camera_rays, int samples, bool seeded,
                     TileScratch& scratch, std::span<Ray> rays, std::span<uint64_t> seeds) {
  size_t i = 0;
  if (samples == 1) {
    // One sample a pixel: its centre, stratified_pixel_samples' rule, taken here without the call
    // and the generator per pixel.
    for (int y = tile.y0; y < tile.y1; ++y) {
      camera_rays.through_pixel_centres(tile.x0, y, rays.subspan(i, size_t(tile.width())));
      for (int x = tile.x0; x < tile.x1; ++x) seeds[i++] = seeded ? sample_seed(x, y, 0) : 0;
    }
    return;
  }
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      Random jitter(x, y, -1);
      stratified_pixel_samples(samples, jitter, scratch.offsets);
      for (int s = 0; s < samples; ++s, ++i) {
        scratch.points[i] = glm::vec2(float(x), float(y)) + scratch.offsets[size_t(s)];
        seeds[i] = seeded ? sample_seed(x, y, s) : 0;
      }
    }
  camera_rays.through(std::span(scratch.points).first(rays.size()), rays);
}

// Every generation as streams (wavefront.h); each sample's radiance comes back x 1/spp. The
// primary rays and seeds are written straight into the wavefront's first queue.
void wavefront_tile(const Scene& scene, const Intersector& hits_of, const Tile& tile,
                    const PrimaryRays& camera_rays, const WhittedOptions& options, Whitted& whitted,
                    std::span<const LaneMesh> meshes, Image& image, Counters& counters,
                    std::vector<RecordedRay>* log) {
  const int samples = samples_per_pixel(options);
  const size_t n = size_t(tile.width()) * size_t(tile.height()) * size_t(samples);
  TileScratch& scratch = scratch_of_this_thread();
  scratch.resize(n);
  Wavefront wavefront(scene, whitted, meshes, hits_of, options, counters, log);
  const Wavefront::FirstGeneration primary = wavefront.first_generation(n);
  primary_samples(tile, camera_rays, samples, whitted.draws_random_numbers(), scratch, primary.rays,
                  primary.seeds);
  counters.samples += n;

  const std::span<Rgb> radiance(scratch.radiance.data(), n);
  wavefront.trace(Rgb(1.0f / float(samples)), radiance);
  size_t i = 0;
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      Rgb sum(0.0f);
      for (int s = 0; s < samples; ++s, ++i) sum += radiance[i];
      image.at(x, y) = sum;
    }
}

// The recursion, with the first generation traced as streams (see StreamedAnswers):
//   1. the tile's primary rays, intersected as one stream;
//   2. each hit's surface point and light samples;
//   3. all their shadow rays, as one stream;
//   4. trace() of each primary ray with those answers: Color() and its recursion.
void streamed_tile(const Intersector& hits_of, const Tile& tile, const PrimaryRays& camera_rays,
                   const WhittedOptions& options, Whitted& whitted, Image& image, Counters& counters,
                   std::vector<RecordedRay>* log) {
  const int samples = samples_per_pixel(options);
  const size_t n = size_t(tile.width()) * size_t(tile.height()) * size_t(samples);
  TileScratch& scratch = scratch_of_this_thread();
  scratch.resize(n);
  const std::span<Ray> rays(scratch.rays.data(), n);
  const std::span<uint64_t> seeds(scratch.seeds.data(), n);
  primary_samples(tile, camera_rays, samples, whitted.draws_random_numbers(), scratch, rays, seeds);
  counters.samples += n;

  std::span<Hit> hits(scratch.hits.data(), n);
  hits_of.intersect(rays, hits, counters.intersection_tests);  // 1.

  std::vector<StreamedAnswers>& answers = scratch.answers;
  std::vector<size_t>& first = scratch.first;      // sample i's lights: first[i] .. first[i + 1]
  std::vector<LightSample>& lights = scratch.lights;
  lights.clear();
  for (size_t i = 0; i < n; ++i) {  // 2.
    first[i] = lights.size();
    answers[i].hit = hits[i];
    if (hits[i].found()) {
      whitted.surfaces().surface_at(rays[i], hits[i], answers[i].point);
      whitted.light_samples(answers[i].point, -rays[i].direction, seeds[i], lights);
    }
  }
  first[n] = lights.size();
  if (options.shadows) {  // 3.
    scratch.shadow_rays.resize(lights.size());
    for (size_t k = 0; k < lights.size(); ++k) scratch.shadow_rays[k] = lights[k].shadow;
    hits_of.occluded(scratch.shadow_rays, scratch.blocked.first(lights.size()),
                     counters.intersection_tests);
  }

  const bool* blocked = options.shadows ? scratch.blocked.first(lights.size()).data() : nullptr;
  const Rgb weight(1.0f / float(samples));
  size_t i = 0;
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      Rgb sum(0.0f);
      for (int s = 0; s < samples; ++s, ++i) {  // 4.
        answers[i].lights = std::span(lights).subspan(first[i], first[i + 1] - first[i]);
        answers[i].blocked = blocked ? blocked + first[i] : nullptr;
        sum += whitted.trace(rays[i], 1, RayKind::primary, seeds[i], weight, &answers[i]);
      }
      image.at(x, y) = sum * weight;
    }
  if (log) mark_stream_starts(*log);
}

}  // namespace

// ---- [the renderer] -----------------------------------------------------------------------------
WhittedRenderer::WhittedRenderer(const Scene& scene) : scene_(scene) { scene_changed(); }

WhittedRenderer::~WhittedRenderer() = default;

void WhittedRenderer::scene_changed() {
  embree_ = std::make_unique<EmbreeIntersector>(scene_);
  corners_.clear();
  for (const Mesh& mesh : scene_.meshes) corners_.push_back(triangle_corners(mesh));
  std::lock_guard lock(brute_force_mutex_);
  brute_force_.reset();
}

const Intersector& WhittedRenderer::intersector(const WhittedOptions& options) {
  if (!options.brute_force) return *embree_;
  std::lock_guard lock(brute_force_mutex_);
  if (!brute_force_) brute_force_ = std::make_unique<BruteForceIntersector>(scene_);
  return *brute_force_;
}

// What a render keeps between its steps: the view, the picture, and each tile's counters and ray
// log until they are summed (integers, so the order does not matter) and concatenated in tile
// order at the end.
struct WhittedRenderer::Steps::State {
  Camera camera;
  int width = 0, height = 0;
  WhittedOptions options;
  std::chrono::steady_clock::time_point start;
  Image image;
  std::vector<Tile> tiles;
  std::vector<LaneMesh> meshes;  // what the wavefront's lanes read of each mesh, once for every tile
  std::vector<Counters> tile_counters;
  std::vector<std::vector<RecordedRay>> tile_rays;
  size_t next = 0;  // the first tile not traced yet
  int done = 0;     // tiles finished
  std::mutex report;
};

WhittedRenderer::Steps::Steps() = default;
WhittedRenderer::Steps::~Steps() = default;
WhittedRenderer::Steps::Steps(Steps&&) noexcept = default;
WhittedRenderer::Steps& WhittedRenderer::Steps::operator=(Steps&&) noexcept = default;
bool WhittedRenderer::Steps::done() const { return !state_ || state_->next >= state_->tiles.size(); }
size_t WhittedRenderer::Steps::tiles() const { return state_ ? state_->tiles.size() : 0; }

Image WhittedRenderer::render(const Camera& camera, int width, int height,
                              const WhittedOptions& options, const TileCallback& on_tile,
                              const std::atomic<bool>* cancel) {
  Steps steps = begin(camera, width, height, options);
  trace(steps, steps.tiles(), on_tile, cancel);
  return finish(steps);
}

WhittedRenderer::Steps WhittedRenderer::begin(const Camera& camera, int width, int height,
                                              const WhittedOptions& options) {
  Steps steps;
  steps.state_ = std::make_unique<Steps::State>();
  Steps::State& s = *steps.state_;
  s.start = std::chrono::steady_clock::now();
  s.camera = camera, s.width = width, s.height = height, s.options = options;
  // Every tile writes all its pixels, so the picture is not cleared first (a serial pass over
  // 12 MB at 1024x1024); a tile skipped by a cancel clears its own.
  s.image = Image(width, height, Image::Uncleared{});
  s.tiles = make_tiles(width, height, options.tile_size);
  intersector(options);  // build the brute-force triangles before the threads start
  if (options.renderer == RendererKind::wavefront)
    s.meshes = lane_meshes(scene_, Whitted(scene_, *embree_, options, counters_, diffuse_), options, corners_);
  counters_ = Counters{};
  rays_.clear();
  s.tile_counters.resize(s.tiles.size());
  s.tile_rays.resize(keep_rays_ ? s.tiles.size() : 0);
  return steps;
}

void WhittedRenderer::trace(Steps& steps, size_t tiles, const TileCallback& on_tile,
                            const std::atomic<bool>* cancel) {
  Steps::State& s = *steps.state_;
  const size_t first = s.next, last = std::min(s.tiles.size(), s.next + tiles);
  s.next = last;
  // Each tile writes only its own pixels and its own counters and ray log.
  parallel_for(first, last, [&](size_t i) {
    const Tile& tile = s.tiles[i];
    if (cancel && cancel->load(std::memory_order_relaxed)) {
      for (int y = tile.y0; y < tile.y1; ++y) std::fill_n(&s.image.at(tile.x0, y), tile.width(), Rgb(0.0f));
      return;
    }
    render_tile(tile, s.camera, s.width, s.height, s.options, s.meshes, s.image, s.tile_counters[i],
                keep_rays_ ? &s.tile_rays[i] : nullptr);
    std::lock_guard lock(s.report);
    ++s.done;
    if (on_tile) on_tile(TileDone{tile, s.done, int(s.tiles.size()), s.image});
  });
}

Image WhittedRenderer::finish(Steps& steps) {
  Steps::State& s = *steps.state_;
  for (const Counters& c : s.tile_counters) counters_ += c;
  for (auto& r : s.tile_rays) rays_.insert(rays_.end(), r.begin(), r.end());
  counters_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - s.start).count();
  return std::move(s.image);
}

// ---- [one tile] ---------------------------------------------------------------------------------
// A tile by the options' strategy: adaptive sampling (Whitted's), or stratified sampling traced by
// the wavefront or by the recursion with its first generation streamed. The ray tree of a pixel
// takes slide 26's loop itself (trace_pixels).
void WhittedRenderer::render_tile(const Tile& tile, const Camera& camera, int width, int height,
                                  const WhittedOptions& options, std::span<const LaneMesh> meshes,
                                  Image& image, Counters& counters, std::vector<RecordedRay>* log,
                                  RayTree* tree) {
  const Intersector& hits_of = intersector(options);
  const PrimaryRays camera_rays(camera, width, height);
  Whitted whitted(scene_, hits_of, options, counters, diffuse_);
  whitted.log_rays(log);
  whitted.record_tree(tree);
  if (options.sampling == Sampling::adaptive)
    adaptive_tile(tile, camera_rays, options, whitted, image, counters);
  else if (tree)
    trace_pixels(tile, camera_rays, samples_per_pixel(options), whitted, image, counters);
  else if (options.renderer == RendererKind::wavefront)
    wavefront_tile(scene_, hits_of, tile, camera_rays, options, whitted, meshes, image, counters, log);
  else
    streamed_tile(hits_of, tile, camera_rays, options, whitted, image, counters, log);
}

Image WhittedRenderer::render_per_pixel(const Camera& camera, int width, int height,
                                        const WhittedOptions& options) {
  Image image(width, height);
  Counters counters;
  Whitted whitted(scene_, intersector(options), options, counters, diffuse_);
  trace_pixels(Tile{0, 0, width, height}, PrimaryRays(camera, width, height), samples_per_pixel(options),
               whitted, image, counters);
  return image;
}

// ---- [one pixel] --------------------------------------------------------------------------------
RayTree WhittedRenderer::trace_pixel(const Camera& camera, int width, int height, int x, int y,
                                     const WhittedOptions& options) {
  RayTree tree;
  tree.x = x;
  tree.y = y;
  tree.width = width;
  tree.height = height;
  Image image(width, height);
  Counters counters;
  render_tile(Tile{x, y, x + 1, y + 1}, camera, width, height, options, {}, image, counters, nullptr,
              &tree);
  tree.pixel = image.at(x, y);
  // Each node's share of the pixel: the product of the weights from its primary ray down.
  std::vector<Rgb> throughput(tree.nodes.size());
  for (RayTreeNode& node : tree.nodes) {
    const Rgb above = node.parent >= 0 ? throughput[size_t(node.parent)] : Rgb(1.0f);
    throughput[size_t(node.id)] = above * node.weight;
    node.contribution = throughput[size_t(node.id)] * node.radiance;
  }
  return tree;
}

Hit WhittedRenderer::primary_hit(const Camera& camera, int width, int height,
                                 glm::vec2 image_point, const WhittedOptions& options) {
  uint64_t tests = 0;
  return intersector(options).intersect(primary_ray(camera, width, height, image_point), tests);
}

}  // namespace luz::rt
