// Ray-cast form factors (Wallace, Elmquist & Haines 1989). See ray_form_factors.h.
#include "radiosity/ray_form_factors.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/parallel_for.h"
#include "radiosity/element_form_factor.h"
#include "radiosity/radiosity_options.h"
#include "raytracing/embree_scene.h"

namespace luz {
namespace {

// SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number generators", OOPSLA
// 2014): a generator whose whole state is one integer, so every (shot, element) pair starts its
// own sequence and the row does not depend on which thread computed which element.
struct Random {
  uint64_t state;
  float next() {
    state += 0x9e3779b97f4a7c15ULL;
    uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return float(z >> 40) * 0x1.0p-24f;  // [0, 1)
  }
};

// A point of triangle (a, b, c), uniform over its area for (u, v) uniform over the unit square
// (the square root keeps strata of u equal in area).
glm::vec3 point_in(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, float u, float v) {
  const float s = std::sqrt(u);
  return (1.0f - s) * a + (s * (1.0f - v)) * b + (s * v) * c;
}

// True when some corner of the triangle lies strictly in front of the plane (x, n).
bool any_in_front(const glm::vec3 (&corners)[3], const glm::vec3& x, const glm::vec3& n) {
  for (const glm::vec3& c : corners)
    if (glm::dot(n, c - x) > 0.0f) return true;
  return false;
}

// The solid angle of triangle (a, b, c) seen from the origin (Van Oosterom & Strackee, "The
// Solid Angle of a Plane Triangle", IEEE Trans. Biomed. Eng. 1983):
//   tan(Omega / 2) = |a . (b x c)| / (|a||b||c| + (a . b)|c| + (a . c)|b| + (b . c)|a|).
double triangle_solid_angle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double numerator = std::abs(glm::dot(a, glm::cross(b, c)));
  const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

float scene_size(const PatchMesh& mesh) {
  Bounds bounds;
  for (const glm::vec3& v : mesh.vertices) bounds.grow(v);
  return bounds.empty() ? 1.0f : glm::length(bounds.extent());
}

}  // namespace

ShooterEmission::ShooterEmission(const PatchMesh& mesh, size_t shooter, std::span<const Rgb> sent)
    : members_(mesh.members.data() + mesh.shooters[shooter].first, mesh.shooters[shooter].count) {
  double area = 0.0;
  cumulative_.reserve(members_.size());
  weight_.reserve(members_.size());
  for (size_t k = 0; k < members_.size(); ++k) {
    area += double(mesh.patches[members_[k]].area);
    cumulative_.push_back(float(area));
    // Overshooting may send a negative amount from an element; it weighs as nothing.
    weight_.push_back(sent.empty() ? 1.0f : std::max(0.0f, (sent[k].r + sent[k].g + sent[k].b) / 3.0f));
  }
  for (float& c : cumulative_) c = area > 0.0 ? float(double(c) / area) : 1.0f;
}

ShooterEmission::Point ShooterEmission::at(const PatchMesh& mesh, float s, float t) const {
  const size_t k = size_t(std::upper_bound(cumulative_.begin(), cumulative_.end() - 1, s) - cumulative_.begin());
  const float below = k > 0 ? cumulative_[k - 1] : 0.0f;
  const float share = cumulative_[k] - below;
  const float u = share > 0.0f ? std::clamp((s - below) / share, 0.0f, 1.0f) : 0.5f;
  const Patch& element = mesh.patches[members_[k]];
  const glm::vec3 position = point_in(mesh.vertices[element.vertices[0]], mesh.vertices[element.vertices[1]],
                                      mesh.vertices[element.vertices[2]], u, t);
  return {position, weight_[k]};
}

RayFormFactors::RayFormFactors(const Scene& scene, const PatchMesh& mesh)
    : mesh_(mesh), offset_(1e-5f * scene_size(mesh)),
      bvh_(std::make_unique<rt::EmbreeIntersector>(scene)), values_(mesh.size(), 0.0f) {}

RayFormFactors::~RayFormFactors() = default;

// Every element's value on parallel threads (core/parallel_for.h), then the elements with a positive one, in order.
// The page's main thread, which shoots, takes its share: the values (element_factor,
// element_solid_angle, element_sunlit_area) reach no function-local static with a dynamic
// initialiser and no thread-local object with a destructor, and allocate nothing.
template <typename Value>
const std::vector<FormFactor>& RayFormFactors::for_each_element(const Value& value) {
  std::atomic<uint64_t> traced{0};
  values_.resize(mesh_.size());  // adaptive subdivision adds elements between rows
  parallel_for_ranges(
      size_t(0), mesh_.size(), size_t(256),
      [&](size_t first, size_t end) {
        uint64_t rays = 0;  // summed per range: one atomic add, not one per element
        for (size_t j = first; j != end; ++j) values_[j] = float(value(j, rays));
        traced.fetch_add(rays, std::memory_order_relaxed);
      },
      parallel::MainThread::joins);
  row_.clear();
  for (size_t j = 0; j < values_.size(); ++j)
    if (values_[j] > 0.0f) row_.push_back({uint32_t(j), values_[j]});
  last_rays_ = traced;
  return row_;
}

// F_ij for one element: 0 unless the two face each other; else V * F(j -> i) * A_j / A_i.
double RayFormFactors::element_factor(size_t i, const ShooterEmission& emission, size_t j, size_t m,
                                      uint32_t seed, uint32_t shot, uint64_t& traced) const {
  const ShootingPatch& shooter = mesh_.shooters[i];
  const Patch& element = mesh_.patches[j];
  if (mesh_.shooter_of[j] == i) return 0.0;  // its own elements lie in its plane
  const glm::vec3 corners[3] = {mesh_.vertices[element.vertices[0]],
                                mesh_.vertices[element.vertices[1]],
                                mesh_.vertices[element.vertices[2]]};
  if (!any_in_front(shooter.corners, element.centre, element.normal) ||
      !any_in_front(corners, shooter.centre, shooter.normal))
    return 0.0;
  const double unoccluded = element_to_patch_form_factor(mesh_, element, shooter);
  if (!(unoccluded > 0.0)) return 0.0;

  // V: m rays, from a random point of the element to a point of the patch in its k-th stratum of
  // area, each weighted by what is sent from where it ends. A ray between a point and one behind
  // its own surface carries no light in the integral (the contour integral clips that part off):
  // it counts neither as open nor as blocked.
  Random random{(uint64_t(seed) << 48) ^ (uint64_t(shot) << 24) ^ uint64_t(j)};
  std::array<rt::Ray, kMaxVisibilityRays> rays;
  std::array<float, kMaxVisibilityRays> weight;
  std::array<bool, kMaxVisibilityRays> blocked{};
  size_t valid = 0;
  for (size_t k = 0; k < m; ++k) {
    const float u = random.next(), v = random.next();
    const glm::vec3 from = point_in(corners[0], corners[1], corners[2], u, v);
    const float su = (float(k) + random.next()) / float(m), sv = random.next();
    const ShooterEmission::Point to = emission.at(mesh_, su, sv);
    const glm::vec3 d = to.position - from;
    if (!(glm::dot(d, element.normal) > 0.0f && glm::dot(d, shooter.normal) < 0.0f)) continue;
    const glm::vec3 start = from + offset_ * element.normal, end = to.position + offset_ * shooter.normal;
    const float length = glm::length(end - start);
    weight[valid] = to.weight;
    rays[valid++] = {start, (end - start) / length, length * (1.0f - 1e-4f)};
  }
  if (valid == 0) return 0.0;
  uint64_t tests = 0;
  for (size_t k = 0; k < valid; ++k) blocked[k] = bvh_->occluded(rays[k], tests);
  traced += valid;
  double open = 0.0, all = 0.0;
  for (size_t k = 0; k < valid; ++k) {
    all += double(weight[k]);
    if (!blocked[k]) open += double(weight[k]);
  }
  if (!(all > 0.0)) {  // every ray ends where nothing is sent: the rays alone say what is seen
    all = double(valid);
    open = double(std::count(blocked.begin(), blocked.begin() + long(valid), false));
  }
  if (!(open > 0.0)) return 0.0;
  return open / all * unoccluded * double(element.area) / double(shooter.area);
}

const std::vector<FormFactor>& RayFormFactors::row(size_t shooter, int rays, uint32_t seed,
                                                   uint32_t shot, std::span<const Rgb> sent) {
  const size_t m = size_t(std::clamp(rays, 1, kMaxVisibilityRays));
  const ShooterEmission emission(mesh_, shooter, sent);
  return for_each_element([&](size_t j, uint64_t& traced) {
    return element_factor(shooter, emission, j, m, seed, shot, traced);
  });
}

double RayFormFactors::element_solid_angle(const Light& light, size_t j, size_t m, uint32_t seed,
                                           uint32_t shot, uint64_t& traced) const {
  const Patch& element = mesh_.patches[j];
  if (!(glm::dot(element.normal, light.position - element.centre) > 0.0f)) return 0.0;  // its back
  const glm::vec3 corners[3] = {mesh_.vertices[element.vertices[0]],
                                mesh_.vertices[element.vertices[1]],
                                mesh_.vertices[element.vertices[2]]};
  const double spot = double(light.spot_factor(glm::normalize(element.centre - light.position)));
  if (!(spot > 0.0)) return 0.0;
  const glm::dvec3 from(light.position);
  const double omega = triangle_solid_angle(glm::dvec3(corners[0]) - from, glm::dvec3(corners[1]) - from,
                                            glm::dvec3(corners[2]) - from);
  Random random{(uint64_t(seed) << 48) ^ (uint64_t(shot) << 24) ^ uint64_t(j)};
  std::array<rt::Ray, kMaxVisibilityRays> rays;
  std::array<bool, kMaxVisibilityRays> blocked{};
  for (size_t k = 0; k < m; ++k) {  // from the element's point toward the light, as for patches
    const float u = (float(k) + random.next()) / float(m), v = random.next();
    const glm::vec3 start = point_in(corners[0], corners[1], corners[2], u, v) + offset_ * element.normal;
    const glm::vec3 d = light.position - start;
    const float length = glm::length(d);
    rays[k] = {start, d / length, length * (1.0f - 1e-4f)};
  }
  uint64_t tests = 0;
  bvh_->occluded(std::span(rays.data(), m), std::span(blocked.data(), m), tests);
  traced += m;
  const auto open = std::count(blocked.begin(), blocked.begin() + long(m), false);
  return spot * omega * double(open) / double(m);
}

const std::vector<FormFactor>& RayFormFactors::solid_angles(const Light& light, int rays,
                                                            uint32_t seed, uint32_t shot) {
  const size_t m = size_t(std::clamp(rays, 1, kMaxVisibilityRays));
  return for_each_element([&](size_t j, uint64_t& traced) {
    return element_solid_angle(light, j, m, seed, shot, traced);
  });
}

// A sun has no position: its rays leave the element against the light's direction and go on
// out of the scene (tfar infinite), and the element's projected area replaces the solid angle.
double RayFormFactors::element_sunlit_area(const Light& sun, size_t j, size_t m, uint32_t seed,
                                           uint32_t shot, uint64_t& traced) const {
  const Patch& element = mesh_.patches[j];
  const glm::vec3 towards = -sun.direction;
  const double cos_theta = double(glm::dot(element.normal, towards));
  if (!(cos_theta > 0.0)) return 0.0;  // its back faces the sun, or the light grazes it
  const glm::vec3 corners[3] = {mesh_.vertices[element.vertices[0]],
                                mesh_.vertices[element.vertices[1]],
                                mesh_.vertices[element.vertices[2]]};
  Random random{(uint64_t(seed) << 48) ^ (uint64_t(shot) << 24) ^ uint64_t(j)};
  std::array<rt::Ray, kMaxVisibilityRays> rays;
  std::array<bool, kMaxVisibilityRays> blocked{};
  for (size_t k = 0; k < m; ++k) {
    const float u = (float(k) + random.next()) / float(m), v = random.next();
    const glm::vec3 start = point_in(corners[0], corners[1], corners[2], u, v) + offset_ * element.normal;
    rays[k] = {start, towards, rt::kInfinity};
  }
  uint64_t tests = 0;
  bvh_->occluded(std::span(rays.data(), m), std::span(blocked.data(), m), tests);
  traced += m;
  const auto open = std::count(blocked.begin(), blocked.begin() + long(m), false);
  return double(element.area) * cos_theta * double(open) / double(m);
}

const std::vector<FormFactor>& RayFormFactors::sunlit_areas(const Light& sun, int rays, uint32_t seed,
                                                            uint32_t shot) {
  const size_t m = size_t(std::clamp(rays, 1, kMaxVisibilityRays));
  return for_each_element([&](size_t j, uint64_t& traced) {
    return element_sunlit_area(sun, j, m, seed, shot, traced);
  });
}

}  // namespace luz
