#pragma once
// Whitted's ray tracer (Whitted 1980; slides 25-26), as the slide writes it:
//
//   Trazar(Rayo r, Profundidad d)        -> Whitted::trace
//     nearest hit, or the background
//   Color(objeto, r, punto, normal, d)   -> Whitted::color
//     color := ambient; for each light: a shadow ray, and the light's term if nothing blocks it;
//     if d < maximum: the reflected ray Trazar(R, d+1) x kr, the transmitted ray Trazar(T, d+1) x kt
//     unless there is total internal reflection.
//
// One Whitted object traces one sample at a time on one thread (the renderer makes one per tile);
// the scene and the intersector are shared read-only.
//
// Random numbers: each ray carries a seed, its place in its sample's ray tree (sampling.h:
// sample_seed for the primary ray, branch_seed for a reflected or transmitted one), and only the
// light samples at its own hit draw from it. The wavefront renderer (wavefront.h), which traces
// the same rays in another order, gives each ray the same seed and so the same picture.
//
// The pieces of Color(): the hit's surface (SurfaceReader, surface_reader.h, which the path tracer
// reads its hits with too), light_samples(), local_color() and secondary_rays(). Their
// arithmetic is in hit_math.h, which the wavefront renderer's lanes (hit_lanes.h) run too, so
// that it cannot drift from the slide's code.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/scene.h"
#include "raytracing/counters.h"
#include "raytracing/diffuse_source.h"
#include "raytracing/intersector.h"
#include "raytracing/ray.h"
#include "raytracing/ray_tree.h"
#include "raytracing/sampling.h"
#include "raytracing/surface_reader.h"
#include "raytracing/whitted_options.h"

namespace luz::rt {

// A ray kept for the benchmark, which traces the same rays again without shading and in the same
// calls: a stream is the rays of one kind from one that `starts_stream` up to the next such ray
// of that kind (or one traced alone), all handed to Embree at once.
enum class Traced : uint8_t { alone, starts_stream, in_stream };
struct RecordedRay {
  Ray ray;
  RayKind kind;
  Traced traced = Traced::alone;
};

// A ray spawned at a hit ("Trazar(R, d+1) * kr", "Trazar(T, d+1) * kt") and the weight its
// radiance is multiplied by.
struct SecondaryRay {
  Ray ray;
  RayKind kind = RayKind::reflected;  // reflected or transmitted
  Rgb weight{0.0f};                   // kr, or kt (with Fresnel: kr + kt F, kt (1 - F))
};

// The secondary rays of one hit: none, one or both, the reflected ray first.
struct SecondaryRays {
  SecondaryRay rays[2];
  int count = 0;
  const SecondaryRay* begin() const { return rays; }
  const SecondaryRay* end() const { return rays + count; }
};

// One light's term at a point and the shadow ray that decides whether it counts (S_i).
struct LightSample {
  Rgb term{0.0f};        // IL * [kd cos(theta) + ks cos^n(alpha)]: the light's share if unblocked
  Ray shadow;            // from just off the surface to just short of the light
  float distance = 0.0f; // to the light (infinite for a directional one)
  int light = -1;        // index into Scene::lights, then lights.size() + index into area_lights
};

// What the renderer traced ahead for one primary ray, as streams (renderer.cpp render_tile): a
// tile's primary rays are coherent, and so are their shadow rays toward one light, and Embree
// traces coherent rays faster as a stream than one by one (its performance recommendations).
// trace() takes these answers for that ray instead of tracing it and its shadow rays again.
struct StreamedAnswers {
  Hit hit;                             // the primary ray's nearest hit
  SurfacePoint point;                  // its surface point, when it hit
  std::span<const LightSample> lights; // light_samples() at that point
  const bool* blocked = nullptr;       // per light sample: its shadow ray is blocked
};

// The light samples of one hit and, when they were streamed, their shadow rays' answers.
struct LightsAt {
  std::span<const LightSample> samples;
  const bool* blocked = nullptr;  // nullptr: the shadow rays are traced when asked
};

class Whitted {
public:
  // `diffuse`: the hybrid's diffuse part (see WhittedRenderer::set_diffuse_source); nullptr:
  // Whitted's own local terms.
  Whitted(const Scene& scene, const Intersector& intersector, const WhittedOptions& options,
          Counters& counters, const DiffuseSource* diffuse = nullptr);

  // Trazar(r, d): the radiance arriving along `ray`. `seed`: the ray's place in its sample's
  // ray tree (see above; a primary ray's is sample_seed()). `weight` is what the caller will
  // multiply the result by (kr, kt, 1/spp); it is only written into the ray tree. `streamed`:
  // the answers for this ray traced ahead (see StreamedAnswers), primary rays only.
  Rgb trace(const Ray& ray, int depth, RayKind kind, uint64_t seed, Rgb weight = Rgb(1.0f),
            const StreamedAnswers* streamed = nullptr);
  // Color(o, r, p, N, d), for the hit of the ray of that seed.
  Rgb color(const SurfacePoint& p, const Ray& ray, int depth, uint64_t seed);

  // What reads this tracer's hits: the surface point, its material and kd x texture.
  const SurfaceReader& surfaces() const { return surfaces_; }
  // Whether shading draws random numbers at all: only the area lights' samples beyond the
  // centroid do. Without them no ray's seed is ever read, and the renderers need not make one.
  bool draws_random_numbers() const {
    return options_.light_samples > 1 && !scene_.area_lights.empty();
  }
  // The hybrid's diffuse part, or nullptr: Whitted's own local terms.
  const DiffuseSource* diffuse_source() const { return diffuse_; }
  // Every light's term at p for a viewer in direction V, if (L.N) > 0, with its shadow ray
  // (not traced): punctual lights and the samples of the emissive triangles, these drawn from
  // the generator of `seed`, the seed of the ray that hit p.
  void light_samples(const SurfacePoint& p, const glm::vec3& V, uint64_t seed,
                     std::vector<LightSample>& out);
  // The local part of Color() at p: Ia*ka + Le (the hybrid: B/pi), plus the term of every light
  // sample whose shadow ray is not blocked. `blocked`: one flag per sample; nullptr: none is.
  Rgb local_color(const SurfacePoint& p, std::span<const LightSample> lights, const bool* blocked) const;
  // The reflected and transmitted rays of the hit p of `ray`, with their weights: Fresnel's
  // split of kt (when on), Snell's law, total internal reflection (no transmitted ray).
  // Written in place, as SurfaceReader::surface_at().
  void secondary_rays(const SurfacePoint& p, const Ray& ray, SecondaryRays& out) const;
  SecondaryRays secondary_rays(const SurfacePoint& p, const Ray& ray) const {
    SecondaryRays out;
    secondary_rays(p, ray, out);
    return out;
  }
  // Record every ray and its result in `tree` (trace_pixel), or log the rays (benchmark).
  void record_tree(RayTree* tree) { tree_ = RayTreeRecorder(tree); }
  void log_rays(std::vector<RecordedRay>* log) { log_ = log; }

private:
  // The hit's light samples: the streamed ones when trace() was given them for this hit, else
  // sampled here. The one lookup of the streamed answers, so that color() has a single path.
  LightsAt lights_at(const SurfacePoint& p, const glm::vec3& V, uint64_t seed);
  // "y no hay obstrucción": per light sample, whether its shadow ray meets anything before its
  // light (traced here, or the streamed answer); nullptr when shadows are off (none blocks).
  const bool* shadow_rays(const LightsAt& lights);
  // Light `light`'s term at p (kd: surfaces().kd_at(p)) and its shadow ray, if it lights p at all.
  void add_light(const SurfacePoint& p, const glm::vec3& V, const glm::vec3& L, const Rgb& IL,
                 float distance, int light, const Rgb& kd, std::vector<LightSample>& out) const;
  // Counts and logs a ray of `kind` as traced (inline: it runs for every ray); `streamed`: the
  // renderer traced it in its tile's stream (the first generation's rays).
  void count(const Ray& ray, RayKind kind, bool streamed) {
    ++counters_[kind];
    if (log_) log_->push_back({ray, kind, streamed ? Traced::in_stream : Traced::alone});
  }

  const Scene& scene_;
  const Intersector& intersector_;
  const WhittedOptions& options_;
  SurfaceReader surfaces_;
  Counters& counters_;
  const DiffuseSource* diffuse_;
  std::vector<glm::vec3> light_points_;  // scratch for area-light samples
  std::vector<LightSample> lights_;      // scratch for Color()'s light samples
  BlockedFlags blocked_;                 // scratch for their shadow rays' answers
  const StreamedAnswers* streamed_ = nullptr;  // the answers for the hit about to be shaded
  RayTreeRecorder tree_;
  std::vector<RecordedRay>* log_ = nullptr;
};

// The primary rays of a camera for an image of width x height pixels, as the rasteriser projects
// (glm::perspective with the camera's yfov and the image's aspect). Image points are in pixel
// units (0..width, 0..height, y down); a pixel's centre is (x + 0.5, y + 0.5).
class PrimaryRays {
public:
  PrimaryRays(const Camera& camera, int width, int height);
  // Inline so that the caller builds the ray in place (a returned Ray reloaded from the stack
  // stalls on store forwarding, which cost a tenth of a render).
  void through(glm::vec2 image_point, Ray& ray) const {
    ray.origin = origin_;
    ray.direction = direction(image_point);
    ray.tfar = kInfinity;
  }
  Ray through(glm::vec2 image_point) const {
    Ray ray;
    through(image_point, ray);
    return ray;
  }
  // The ray through each point, as through() makes it (the same bits), several to an instruction.
  void through(std::span<const glm::vec2> image_points, std::span<Ray> rays) const;
  // The same for the centres of pixels x0 .. x0 + rays.size() - 1 of row y (one sample a pixel).
  void through_pixel_centres(int x0, int y, std::span<Ray> rays) const;

private:
  glm::vec3 direction(glm::vec2 image_point) const {
    return glm::normalize(corner_ + image_point.x * right_ + image_point.y * down_);
  }
  // rays[i] through image point point_of(i), for every i (whitted.cpp).
  template <typename PointOf>
  void through_points(std::span<Ray> rays, PointOf point_of) const;

  glm::vec3 origin_;
  glm::vec3 corner_;  // the direction through image point (0, 0), unnormalised
  glm::vec3 right_;   // its change per pixel to the right
  glm::vec3 down_;    // its change per pixel down
};

inline Ray primary_ray(const Camera& camera, int width, int height, glm::vec2 image_point) {
  return PrimaryRays(camera, width, height).through(image_point);
}

}  // namespace luz::rt
