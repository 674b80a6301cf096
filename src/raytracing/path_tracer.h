#pragma once
// The path tracer: slide 14's general illumination equation
//
//   L(x -> V) = Le(x -> V) + integral over the sphere of f(x, L -> V) L(x <- L) cos(theta) dL
//
// solved by Monte Carlo, one random path per sample (Kajiya 1986), on the Embree scene and the
// TBB tiles the Whitted tracer uses. At every hit:
//   - Le, on an emitter's front side: fully for the camera ray and after a mirror or glass
//     bounce, weighed by multiple importance sampling (MIS) after a smooth bounce;
//   - next-event estimation: every punctual light (delta lights: nothing else can find them)
//     and one point on one emissive triangle, chosen in proportion to power, with a shadow ray
//     each, the area light's share weighed by MIS against the BSDF's density;
//   - the next ray from the BSDF (path_bsdf.h), while depth < max_depth; Russian roulette from
//     roulette_depth on.
// MIS uses Veach's power heuristic (thesis, 9.2.4): w = p_a^2 / (p_a^2 + p_b^2).
//
// Samples accumulate in a PathFilm (mean and standard error per pixel), so a picture can be
// refined progressively: add N samples, read the mean and the noise, add more.
//
//   PathRenderer tracer(scene);                         // Embree's BVH built here, once
//   PathFilm film(width, height);
//   tracer.add_samples(film, camera, options, 16);      // 16 more samples per pixel
//   Image mean = film.mean(), error = film.standard_error();
#include <atomic>
#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/image.h"
#include "core/scene.h"
#include "raytracing/intersector.h"
#include "raytracing/path_options.h"
#include "raytracing/sampling.h"
#include "raytracing/tiles.h"

namespace luz::rt {

// Per pixel: the number of samples, their sum and the sum of their squares (doubles: a sum of
// 10^6 floats keeps its precision), from which the mean and its standard error follow.
class PathFilm {
public:
  PathFilm() = default;
  PathFilm(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }

  void add(int x, int y, const Rgb& sample);
  int samples(int x, int y) const { return count_[index(x, y)]; }
  int min_samples() const;  // fewest samples of any pixel (all equal unless a pass was cancelled)

  Image mean() const;
  // The standard error of each pixel's mean, s / sqrt(N), with s^2 the unbiased sample
  // variance (N - 1 in the denominator); 0 where N < 2.
  Image standard_error() const;
  void clear();

private:
  size_t index(int x, int y) const { return size_t(y) * size_t(width_) + size_t(x); }
  int width_ = 0, height_ = 0;
  std::vector<int> count_;
  std::vector<glm::dvec3> sum_, sum_squares_;
};

// An emissive triangle picked for next-event estimation.
struct EmitterChoice {
  int light = -1;        // index into Scene::area_lights
  float probability = 0; // of that triangle
};

// The emissive triangles with probabilities in proportion to their power A * mean(Le), so the
// density of a point y chosen on triangle j (area measure) is mean(Le_j) / sum_i A_i mean(Le_i),
// which MIS needs when a ray meets an emitter by chance. Le_j is the triangle's AreaLight
// radiance: its material's Le, or with an emissive texture the texture's mean over it (the point
// is then chosen uniformly on the triangle and weighed by the texel it lands on).
class EmitterTable {
public:
  explicit EmitterTable(const Scene& scene);
  EmitterChoice pick(float u) const;
  // The density on triangle `triangle` of scene mesh `mesh`; 0 when it emits nothing.
  float area_density(int mesh, int triangle) const;
  bool empty() const { return cdf_.empty(); }

private:
  std::vector<float> cdf_;
  double total_power_ = 0.0;
  std::unordered_map<uint64_t, float> mean_le_;  // mean(Le_j) by (mesh << 32 | triangle)
};

// Called once per finished tile of a pass, never by two threads at once: the tile, how many
// tiles of the pass are done (this one included) and how many there are.
using PathProgress = std::function<void(const Tile& tile, int done, int total)>;

class PathRenderer {
public:
  explicit PathRenderer(const Scene& scene);
  ~PathRenderer();
  PathRenderer(const PathRenderer&) = delete;
  PathRenderer& operator=(const PathRenderer&) = delete;

  // Rebuilds the BVH from the scene's current geometry. Lights, materials and emission are read
  // at every call of add_samples.
  void scene_changed();

  // Adds `spp` samples to every pixel of `film`, tiles in parallel. A pixel's k-th sample uses a
  // generator seeded by (pixel, options.seed, k), so the film is the same bit for bit however
  // the threads run and however the samples are split into calls. When `cancel` becomes true the
  // tiles not yet started are skipped (their pixels keep fewer samples).
  void add_samples(PathFilm& film, const Camera& camera, const PathOptions& options, int spp,
                   const PathProgress& on_tile = {}, const std::atomic<bool>* cancel = nullptr);
  // The same for the film's tiles [first, first + count) alone (make_tiles of the film's size and
  // options.tile_size), in parallel: a pass in steps, for a caller that traces a few tiles at a
  // time (the page built without threads, between its frames). `on_tile` counts them within
  // the call.
  void add_samples(PathFilm& film, const Camera& camera, const PathOptions& options, int spp, size_t first,
                   size_t count, const PathProgress& on_tile = {}, const std::atomic<bool>* cancel = nullptr);

  // The mean of options.spp samples per pixel.
  Image render(const Camera& camera, int width, int height, const PathOptions& options);

  // One sample of the radiance arriving along `ray` (tests, the viewer's probe).
  Rgb radiance(const Ray& ray, const PathOptions& options, Random& random) const;

private:
  const Scene& scene_;
  std::unique_ptr<Intersector> embree_;
};

}  // namespace luz::rt
