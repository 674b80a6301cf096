// Whitted's tracer, slide 26. Sections: [Trazar] [Color] [lights] [rays]
#include "raytracing/whitted.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "raytracing/hit_math.h"
#include "raytracing/vector_clones.h"

namespace luz::rt {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

}  // namespace

Whitted::Whitted(const Scene& scene, const Intersector& intersector, const WhittedOptions& options,
                 Counters& counters, const DiffuseSource* diffuse)
    : scene_(scene), intersector_(intersector), options_(options), surfaces_(scene, options.terms.textures),
      counters_(counters), diffuse_(diffuse) {}

// ---- [Trazar] -----------------------------------------------------------------------------------
Rgb Whitted::trace(const Ray& ray, int depth, RayKind kind, uint64_t seed, Rgb weight,
                   const StreamedAnswers* streamed) {
  count(ray, kind, streamed != nullptr);
  tree_.ray(ray, kind, depth, weight);
  // "Determinar intersección con objeto más cercano".
  const Hit hit = streamed ? streamed->hit : intersector_.intersect(ray, counters_.intersection_tests);
  Rgb radiance = scene_.background;  // "sino devolver color del fondo"
  if (hit.found()) {
    // "calcular la normal"
    const SurfacePoint p = streamed ? streamed->point : surfaces_.surface_at(ray, hit);
    tree_.hit(hit.t, p.position, p.N, scene_.meshes[size_t(p.mesh)].name, p.material->name);
    streamed_ = streamed;  // lights_at() takes its answers for this hit, and only this one
    radiance = color(p, ray, depth, seed);
  }
  tree_.returned(radiance);
  return radiance;
}

// ---- [Color] ------------------------------------------------------------------------------------
// I = Ia*ka + sum_i S_i * IL_i * [kd*cos(theta) + ks*cos^n(alpha)] + kr*Ir + kt*It   (+ Le)
// Hybrid (a diffuse source given):
// I = B/pi (radiosity, interpolated)  + sum_i S_i * IL_i * ks*cos^n(alpha)  + kr*Ir + kt*It
Rgb Whitted::color(const SurfacePoint& p, const Ray& ray, int depth, uint64_t seed) {
  // "color := color ambiental"; "para cada luz": L := rayo desde p a la luz; si (L.N) > 0 y no
  // hay obstrucción, the light's term.
  const LightsAt lights = lights_at(p, -ray.direction, seed);
  Rgb color = local_color(p, lights.samples, shadow_rays(lights));
  tree_.local(color);

  // "si d < máxima": "si o es reflexivo", color := color + Trazar(R, d+1) * kr; "si o es
  // transmisivo y no hay reflexión interna total", color := color + Trazar(T, d+1) * kt.
  if (depth >= max_depth_of(options_)) return color;
  for (const SecondaryRay& s : secondary_rays(p, ray))
    color += s.weight * trace(s.ray, depth + 1, s.kind, branch_seed(seed, s.kind), s.weight);
  return color;
}

Rgb Whitted::local_color(const SurfacePoint& p, std::span<const LightSample> lights,
                         const bool* blocked) const {
  const Material& o = *p.material;
  Rgb color(0.0f);
  if (!diffuse_) {
    if (options_.terms.ambient) color = scene_.ambient * o.ka;
    // An emitter shows its own Le on its front side (as gl_FrontFacing in the rasteriser).
    if (options_.terms.emission && p.front && o.is_emissive())
      color += surfaces_.emission_at(p);  // the texel hit
  } else if (options_.terms.diffuse && p.front) {
    // The hybrid (slides 41-43): the diffuse part comes from the radiosity solution, B/pi
    // interpolated across the patches, which already holds everything view-independent:
    // Le (B = E + rho H with E = pi Le), the direct light of every source with its shadows, and
    // the interreflections Whitted's model lacks (so no ambient term). Only a surface's front
    // receives and emits in radiosity; a back face adds nothing here, as the radiosity picture
    // draws it black. The rest is view-dependent and comes from rays: the lights add only
    // their highlights IL ks cos^n(alpha) (add_light leaves kd out), then kr*Ir and kt*It, whose
    // hits are shaded by this same rule.
    color = diffuse_->diffuse_radiance(p.mesh, p.triangle, p.barycentrics);
  }
  for (size_t i = 0; i < lights.size(); ++i)
    if (!blocked || !blocked[i]) color += lights[i].term;  // S_i = 1: unblocked
  return color;
}

void Whitted::secondary_rays(const SurfacePoint& p, const Ray& ray, SecondaryRays& out) const {
  const Material& o = *p.material;
  const Split split = split_at(o.kr, o.kt, o.ior, p.front, ray.direction, p.N, options_.fresnel);
  out.count = 0;
  // "si o es reflexivo": R := rayo de reflexión.
  if (positive(split.kr)) {
    const glm::vec3 R = keep_on_side(reflect(ray.direction, p.N), p.geometric);
    out.rays[out.count++] = {Ray{offset_origin(p.position, p.geometric), R}, RayKind::reflected, split.kr};
  }
  // "si o es transmisivo y no hay reflexión interna total": T := rayo de refracción.
  if (positive(split.kt) && split.refracts) {
    const glm::vec3 inward = -p.geometric;
    out.rays[out.count++] = {Ray{offset_origin(p.position, inward), keep_on_side(split.T, inward)},
                             RayKind::transmitted, split.kt};
  }
}

// ---- [lights] -----------------------------------------------------------------------------------
void Whitted::light_samples(const SurfacePoint& p, const glm::vec3& V, uint64_t seed,
                            std::vector<LightSample>& out) {
  Random random(seed);
  // I_D's kd, once for all the lights; in the hybrid radiosity has I_D already (see local_color()).
  const Rgb kd = options_.terms.diffuse && !diffuse_ ? surfaces_.kd_at(p) : Rgb(0.0f);
  // Punctual lights: IL = I * f_att(d) * spot / pi, or E_perp / pi for directional ones.
  for (size_t i = 0; i < scene_.lights.size(); ++i) {
    const Light& light = scene_.lights[i];
    if (!light.enabled) continue;
    if (light.type == LightType::directional) {
      add_light(p, V, -glm::normalize(light.direction), light.intensity / kPi, kInfinity, int(i), kd, out);
      continue;
    }
    const glm::vec3 to_light = light.position - p.position;
    const float d = glm::length(to_light);
    if (d <= 0.0f) continue;
    const glm::vec3 L = to_light / d;
    const Rgb IL = light.intensity * light.attenuation.factor(d) * light.spot_factor(-L) / kPi;
    add_light(p, V, L, IL, d, int(i), kd, out);
  }
  // Emissive triangles, sampled over their area: each of N samples y stands for area A/N and
  // lights like a point of intensity Le * (A/N) * cos(theta_e) (SCENES.md; N = 1 is the
  // centroid, exactly the rasteriser's light).
  const int n = std::max(1, options_.light_samples);
  for (size_t a = 0; a < scene_.area_lights.size(); ++a) {
    const AreaLight& area = scene_.area_lights[a];
    if (area.mesh == p.mesh && area.triangle == p.triangle) continue;  // it cannot light itself
    std::span<const glm::vec3> points(&area.centroid, 1);
    if (n > 1) {
      const Mesh& mesh = scene_.meshes[size_t(area.mesh)];
      const size_t t = size_t(area.triangle);
      triangle_samples(mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
                       mesh.positions[mesh.indices[3 * t + 2]], n, random, light_points_);
      points = light_points_;
    }
    for (const glm::vec3& y : points) {
      const glm::vec3 to_light = y - p.position;
      const float d = glm::length(to_light);
      if (d < 1e-6f) continue;
      const glm::vec3 L = to_light / d;
      const float cos_theta_e = std::max(glm::dot(area.normal, -L), 0.0f);  // dark behind it
      const Rgb IL = area.radiance * (area.area / float(n)) * cos_theta_e / (d * d) / kPi;
      add_light(p, V, L, IL, d, int(scene_.lights.size() + a), kd, out);
    }
  }
}

void Whitted::add_light(const SurfacePoint& p, const glm::vec3& V, const glm::vec3& L,
                        const Rgb& IL, float distance, int light, const Rgb& kd,
                        std::vector<LightSample>& out) const {
  const float cos_theta = glm::dot(p.N, L);
  if (cos_theta <= 0.0f || !positive(IL)) return;  // "si (L·N) > 0"
  const Material& o = *p.material;
  Rgb term(0.0f);
  // I_D = IL kd cos(theta); in the hybrid radiosity has it already (see local_color()).
  if (options_.terms.diffuse && !diffuse_) term += IL * kd * cos_theta;
  const bool shiny = options_.terms.specular && positive(o.ks);
  const float highlight = shiny ? cos_power(cos_alpha(p.N, L, V, options_.terms.blinn), o.shininess) : 0.0f;
  if (shiny) term += IL * o.ks * highlight;  // I_S
  if (!lights_the_hit(kd, shiny, highlight)) return;
  LightSample& sample = out.emplace_back();  // written in place: see surface_reader.h
  sample.term = term;
  sample.shadow = shadow_ray(p.position, p.geometric, L, distance);
  sample.distance = distance;
  sample.light = light;
}

LightsAt Whitted::lights_at(const SurfacePoint& p, const glm::vec3& V, uint64_t seed) {
  if (const StreamedAnswers* streamed = std::exchange(streamed_, nullptr))
    return {streamed->lights, streamed->blocked};
  lights_.clear();
  light_samples(p, V, seed, lights_);
  return {lights_, nullptr};
}

const bool* Whitted::shadow_rays(const LightsAt& lights) {
  if (!options_.shadows) return nullptr;  // every light counts as unoccluded
  const std::span<bool> blocked = blocked_.first(lights.samples.size());
  for (size_t i = 0; i < blocked.size(); ++i) {
    const LightSample& sample = lights.samples[i];
    count(sample.shadow, RayKind::shadow, lights.blocked != nullptr);
    // S_i = 0 when the shadow ray meets anything before the light.
    blocked[i] = lights.blocked ? lights.blocked[i]
                                : intersector_.occluded(sample.shadow, counters_.intersection_tests);
    tree_.shadow(sample.shadow, blocked[i], sample.distance, sample.light, sample.term);
  }
  return blocked.data();
}

// ---- [rays] -------------------------------------------------------------------------------------
PrimaryRays::PrimaryRays(const Camera& camera, int width, int height) {
  // In camera space the image plane at z = -1 spans x in [-tan(yfov/2) aspect, +...] and
  // y in [-tan(yfov/2), +tan(yfov/2)], y up; then the camera's rotation takes it to the world.
  const float tan_half = std::tan(0.5f * camera.yfov);
  const float aspect = float(width) / float(height);
  const glm::mat3 rotation(camera.to_world);
  origin_ = camera.position();
  corner_ = rotation * glm::vec3(-tan_half * aspect, tan_half, -1.0f);
  right_ = rotation * glm::vec3(2.0f * tan_half * aspect / float(width), 0.0f, 0.0f);
  down_ = rotation * glm::vec3(0.0f, -2.0f * tan_half / float(height), 0.0f);
}

// Directions computed in blocks of three arrays, which the compiler vectorises, then copied into
// the rays. Inlined into each clone of its callers, so that the loops vectorise for each one's
// vector width there.
template <typename PointOf>
[[gnu::always_inline]] inline void PrimaryRays::through_points(std::span<Ray> rays, PointOf point_of) const {
  constexpr size_t block = 64;
  float dx[block], dy[block], dz[block];
  for (size_t start = 0; start < rays.size(); start += block) {
    const size_t n = std::min(block, rays.size() - start);
    for (size_t k = 0; k < n; ++k) {
      const glm::vec3 d = direction(point_of(start + k));
      dx[k] = d.x;
      dy[k] = d.y;
      dz[k] = d.z;
    }
    Ray* out = rays.data() + start;
    for (size_t k = 0; k < n; ++k) {
      out[k].origin = origin_;
      out[k].direction = glm::vec3(dx[k], dy[k], dz[k]);
      out[k].tfar = kInfinity;
    }
  }
}

LUZ_VECTOR_CLONES
void PrimaryRays::through(std::span<const glm::vec2> image_points, std::span<Ray> rays) const {
  through_points(rays.first(image_points.size()), [&](size_t i) { return image_points[i]; });
}

LUZ_VECTOR_CLONES
void PrimaryRays::through_pixel_centres(int x0, int y, std::span<Ray> rays) const {
  through_points(rays, [&](size_t i) { return glm::vec2(float(x0 + int(i)), float(y)) + 0.5f; });
}

const char* to_string(RayKind kind) {
  switch (kind) {
    case RayKind::primary: return "primary";
    case RayKind::shadow: return "shadow";
    case RayKind::reflected: return "reflected";
    case RayKind::transmitted: return "transmitted";
  }
  return "?";
}

}  // namespace luz::rt
