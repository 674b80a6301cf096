// The path tracer. Sections: [film] [emitters] [one path] [lights] [tiles]
#include "raytracing/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/parallel_for.h"
#include "raytracing/embree_scene.h"
#include "raytracing/optics.h"
#include "raytracing/path_bsdf.h"
#include "raytracing/surface_reader.h"
#include "raytracing/whitted.h"

namespace luz::rt {

namespace {

float mean(const Rgb& c) { return std::max(0.0f, (c.r + c.g + c.b) / 3.0f); }
float max_of(const Rgb& c) { return std::max(c.r, std::max(c.g, c.b)); }

// Veach's power heuristic for two strategies with one sample each.
float power_heuristic(float pdf_a, float pdf_b) {
  const float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
  return a + b > 0.0f ? a / (a + b) : 0.0f;
}

}  // namespace

// ---- [film] -------------------------------------------------------------------------------------
PathFilm::PathFilm(int width, int height)
    : width_(width), height_(height), count_(size_t(width) * size_t(height), 0),
      sum_(count_.size(), glm::dvec3(0.0)), sum_squares_(count_.size(), glm::dvec3(0.0)) {}

void PathFilm::add(int x, int y, const Rgb& sample) {
  const size_t i = index(x, y);
  const glm::dvec3 s(sample);
  ++count_[i];
  sum_[i] += s;
  sum_squares_[i] += s * s;
}

int PathFilm::min_samples() const {
  return count_.empty() ? 0 : *std::min_element(count_.begin(), count_.end());
}

Image PathFilm::mean() const {
  Image image(width_, height_);
  for (size_t i = 0; i < count_.size(); ++i)
    if (count_[i] > 0) image.pixels[i] = Rgb(sum_[i] / double(count_[i]));
  return image;
}

Image PathFilm::standard_error() const {
  Image image(width_, height_);
  for (size_t i = 0; i < count_.size(); ++i) {
    const double n = double(count_[i]);
    if (n < 2.0) continue;
    const glm::dvec3 m = sum_[i] / n;
    // s^2 = (sum x^2 - N m^2) / (N - 1), clamped at 0 against rounding; SE = s / sqrt(N).
    const glm::dvec3 variance = glm::max((sum_squares_[i] - n * m * m) / (n - 1.0), glm::dvec3(0.0));
    image.pixels[i] = Rgb(glm::sqrt(variance / n));
  }
  return image;
}

void PathFilm::clear() {
  std::fill(count_.begin(), count_.end(), 0);
  std::fill(sum_.begin(), sum_.end(), glm::dvec3(0.0));
  std::fill(sum_squares_.begin(), sum_squares_.end(), glm::dvec3(0.0));
}

// ---- [emitters] ---------------------------------------------------------------------------------
EmitterTable::EmitterTable(const Scene& scene) {
  double running = 0.0;
  for (const AreaLight& light : scene.area_lights) {
    running += double(light.area) * double(mean(light.radiance));
    cdf_.push_back(float(running));
    mean_le_[uint64_t(light.mesh) << 32 | uint32_t(light.triangle)] = float(mean(light.radiance));
  }
  total_power_ = running;
  if (total_power_ <= 0.0) {
    cdf_.clear();
    return;
  }
  for (float& c : cdf_) c = float(double(c) / total_power_);
}

EmitterChoice EmitterTable::pick(float u) const {
  if (cdf_.empty()) return {};
  const size_t i = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin());
  const size_t k = std::min(i, cdf_.size() - 1);
  return {int(k), cdf_[k] - (k > 0 ? cdf_[k - 1] : 0.0f)};
}

float EmitterTable::area_density(int mesh, int triangle) const {
  const auto found = mean_le_.find(uint64_t(mesh) << 32 | uint32_t(triangle));
  if (total_power_ <= 0.0 || found == mean_le_.end()) return 0.0f;
  return float(double(found->second) / total_power_);
}

// ---- [one path] ---------------------------------------------------------------------------------
namespace {

// One thread's tracer: follows paths one vertex at a time (an iterative form of the recursive
// L = Le + integral f L cos: the throughput carries the product of the f cos / pdf factors).
class PathTracer {
public:
  PathTracer(const Scene& scene, const Intersector& intersector, const EmitterTable& emitters,
             const PathOptions& options)
      : scene_(scene), intersector_(intersector), emitters_(emitters), options_(options),
        surfaces_(scene, options.textures) {}

  Rgb radiance(Ray ray, Random& random) {
    Rgb L(0.0f);
    Rgb throughput(1.0f);
    bool after_delta = true;  // the camera ray, like a mirror bounce, cannot be light-sampled
    float bsdf_pdf = 0.0f;    // the density with which the smooth part chose `ray`
    const int max_depth = max_depth_of(options_);
    for (int depth = 1;; ++depth) {
      const Hit hit = intersector_.intersect(ray, tests_);
      if (!hit.found()) {
        L += throughput * scene_.background;  // rays that leave the scene
        break;
      }
      const SurfacePoint p = surfaces_.surface_at(ray, hit);
      const Material& m = *p.material;
      const glm::vec3 V = -ray.direction;

      // Le: an emitter met by the path. After a smooth bounce next-event estimation could have
      // chosen this point too, so both strategies are weighed.
      if (p.front && m.is_emissive()) {
        float w = 1.0f;
        if (!after_delta) {
          const float cos_e = std::max(glm::dot(p.geometric, V), 1e-6f);
          const float light_pdf = emitters_.area_density(p.mesh, p.triangle) * hit.t * hit.t / cos_e;
          w = power_heuristic(bsdf_pdf, light_pdf);
        }
        L += throughput * surfaces_.emission_at(p) * w;
      }

      // Next-event estimation. At the last depth no BSDF ray follows to find the emitters, so the
      // light sample then stands alone (MIS weight 1).
      const bool last = depth >= max_depth;
      const Bsdf bsdf(surfaces_.kd_at(p), m.ks, m.shininess, m.kr, m.kt, m.ior, p.N, V, p.front);
      if (bsdf.has_smooth_part()) L += throughput * direct_light(p, bsdf, random, last);

      // "si d < máxima": the next ray, from the BSDF.
      if (last) break;
      const float u_lobe = random.next(), u1 = random.next(), u2 = random.next();
      const std::optional<BsdfSample> s = bsdf.sample(u_lobe, u1, u2);
      if (!s) break;
      throughput *= s->weight;
      after_delta = s->delta;
      bsdf_pdf = s->pdf;
      const glm::vec3 side = s->transmitted ? -p.geometric : p.geometric;
      ray = Ray{offset_origin(p.position, side), keep_on_side(s->direction, side)};

      // Russian roulette: continue with probability q, and weigh the survivors by 1/q.
      if (depth + 1 >= options_.roulette_depth) {
        const float q = std::min(max_of(throughput), 0.95f);
        if (!(q > 0.0f) || random.next() >= q) break;
        throughput /= q;
      }
    }
    return L;
  }

private:
  // ---- [lights] ---------------------------------------------------------------------------------
  // Next-event estimation at p: sum over the punctual lights of f cos(theta) E_i (the delta
  // lights' irradiance, SCENES.md's units), plus one emissive triangle's estimate, weighed by
  // MIS against the BSDF ray unless `alone`.
  Rgb direct_light(const SurfacePoint& p, const Bsdf& bsdf, Random& random, bool alone) {
    Rgb sum(0.0f);
    for (const Light& light : scene_.lights) {
      if (!light.enabled) continue;
      glm::vec3 L;
      float distance = kInfinity;
      Rgb E;  // irradiance on a surface facing the light
      if (light.type == LightType::directional) {
        L = -glm::normalize(light.direction);
        E = light.intensity;
      } else {
        const glm::vec3 to_light = light.position - p.position;
        distance = glm::length(to_light);
        if (distance <= 0.0f) continue;
        L = to_light / distance;
        E = light.intensity * light.attenuation.factor(distance) * light.spot_factor(-L);
      }
      const float cos_theta = glm::dot(p.N, L);
      if (cos_theta <= 0.0f || max_of(E) <= 0.0f) continue;
      const Rgb contribution = bsdf.eval(L) * cos_theta * E;
      if (max_of(contribution) > 0.0f && visible(p, L, distance)) sum += contribution;
    }

    // An emissive triangle by power, a point on it uniformly by area (Shirley's map
    // b0 = 1 - sqrt(u), b1 = v sqrt(u)); the estimate f cos Le cos_e / d^2 / pdf_area.
    const float u = random.next(), u1 = random.next(), u2 = random.next();
    const EmitterChoice choice = emitters_.pick(u);
    if (choice.light < 0) return sum;
    const AreaLight& area = scene_.area_lights[size_t(choice.light)];
    if (area.mesh == p.mesh && area.triangle == p.triangle) return sum;  // it cannot light itself
    const Mesh& mesh = scene_.meshes[size_t(area.mesh)];
    const size_t t = size_t(area.triangle);
    const glm::vec3& a = mesh.positions[mesh.indices[3 * t]];
    const glm::vec3& b = mesh.positions[mesh.indices[3 * t + 1]];
    const glm::vec3& c = mesh.positions[mesh.indices[3 * t + 2]];
    const float s = std::sqrt(u1);
    const float b0 = 1.0f - s, b1 = u2 * s;
    const glm::vec3 y = b0 * a + b1 * b + (1.0f - b0 - b1) * c;
    const glm::vec3 to_light = y - p.position;
    const float d = glm::length(to_light);
    if (d < 1e-6f) return sum;
    const glm::vec3 L = to_light / d;
    const float cos_theta = glm::dot(p.N, L);
    const float cos_e = glm::dot(area.normal, -L);  // Le only on the front side
    if (cos_theta <= 0.0f || cos_e <= 0.0f) return sum;
    const float area_pdf = choice.probability / area.area;
    const float light_pdf = area_pdf * d * d / cos_e;  // the same density per solid angle
    const Rgb f = bsdf.eval(L);
    if (max_of(f) <= 0.0f || !visible(p, L, d)) return sum;
    const float w = alone ? 1.0f : power_heuristic(light_pdf, bsdf.pdf(L));
    // Le at y: (u, v) = (b1, b2) in Scene::emission_at's barycentrics.
    const Rgb Le = scene_.emission_at(area.mesh, t, glm::vec2(b1, 1.0f - b0 - b1));
    return sum + f * Le * (cos_theta * w / light_pdf);
  }

  // The shadow ray: nothing between p and the light (just short of it: an emitter's point lies
  // on the emitter, which must not block it).
  bool visible(const SurfacePoint& p, const glm::vec3& L, float distance) {
    const glm::vec3 side = glm::dot(L, p.geometric) >= 0.0f ? p.geometric : -p.geometric;
    const Ray shadow{offset_origin(p.position, side), L,
                     std::isinf(distance) ? kInfinity : distance * (1.0f - 1e-4f)};
    return !intersector_.occluded(shadow, tests_);
  }

  const Scene& scene_;
  const Intersector& intersector_;
  const EmitterTable& emitters_;
  const PathOptions& options_;
  SurfaceReader surfaces_;  // the hits read as the Whitted tracer reads them: point, normals, kd
  uint64_t tests_ = 0;
};

}  // namespace

// ---- [tiles] ------------------------------------------------------------------------------------
PathRenderer::PathRenderer(const Scene& scene) : scene_(scene) { scene_changed(); }

PathRenderer::~PathRenderer() = default;

void PathRenderer::scene_changed() { embree_ = std::make_unique<EmbreeIntersector>(scene_); }

void PathRenderer::add_samples(PathFilm& film, const Camera& camera, const PathOptions& options,
                               int spp, const PathProgress& on_tile,
                               const std::atomic<bool>* cancel) {
  add_samples(film, camera, options, spp, 0, make_tiles(film.width(), film.height(), options.tile_size).size(),
              on_tile, cancel);
}

void PathRenderer::add_samples(PathFilm& film, const Camera& camera, const PathOptions& options, int spp,
                               size_t first_tile, size_t count, const PathProgress& on_tile,
                               const std::atomic<bool>* cancel) {
  const EmitterTable emitters(scene_);
  const PrimaryRays camera_rays(camera, film.width(), film.height());
  const std::vector<Tile> tiles = make_tiles(film.width(), film.height(), options.tile_size);
  const size_t last_tile = std::min(tiles.size(), first_tile + count);
  std::mutex report;
  int done = 0;
  parallel_for(std::min(first_tile, last_tile), last_tile, [&](size_t i) {
    if (cancel && cancel->load(std::memory_order_relaxed)) return;
    const Tile& tile = tiles[i];
    PathTracer tracer(scene_, *embree_, emitters, options);
    for (int y = tile.y0; y < tile.y1; ++y)
      for (int x = tile.x0; x < tile.x1; ++x) {
        const int pixel = y * film.width() + x;
        const int first = film.samples(x, y);
        for (int k = first; k < first + spp; ++k) {
          // The generator of sample k of this pixel: independent of the thread and of how many
          // samples earlier calls added.
          Random random(pixel, int(options.seed), k);
          const glm::vec2 jitter(random.next(), random.next());  // box filter over the pixel
          const Ray ray = camera_rays.through(glm::vec2(float(x), float(y)) + jitter);
          const Rgb L = tracer.radiance(ray, random);
          // A NaN or Inf sample (a degenerate triangle, a 0/0) would poison the pixel for good.
          film.add(x, y, is_finite(L) ? L : Rgb(0.0f));
        }
      }
    std::lock_guard lock(report);
    ++done;
    if (on_tile) on_tile(tile, done, int(last_tile - std::min(first_tile, last_tile)));
  });
}

Image PathRenderer::render(const Camera& camera, int width, int height, const PathOptions& options) {
  PathFilm film(width, height);
  add_samples(film, camera, options, std::max(1, options.spp));
  return film.mean();
}

Rgb PathRenderer::radiance(const Ray& ray, const PathOptions& options, Random& random) const {
  const EmitterTable emitters(scene_);
  PathTracer tracer(scene_, *embree_, emitters, options);
  return tracer.radiance(ray, random);
}

}  // namespace luz::rt
