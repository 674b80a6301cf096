// Progressive refinement radiosity (slide 39; Cohen et al. 1988). See shooting.h.
//
// Sections: [powers] [construction and reset] [step 2: shoot a patch] [point lights]
//           [the loop] [state]
#include "radiosity/shooting.h"

#include "core/error.h"
#include "core/i18n.h"
#include "core/parallel_for.h"
#include "radiosity/element_form_factor.h"
#include "radiosity/polygon_form_factor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace luz {
namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double mean(const Rgb& c) { return (double(c.r) + double(c.g) + double(c.b)) / 3.0; }
double mean(const glm::dvec3& c) { return (c.r + c.g + c.b) / 3.0; }

// The solid angle a light sends its intensity into, sum(spot) over the sphere: 4 pi for a point
// light; for a spot, the integral of its (axially symmetric) factor, 2 pi sin(theta) dtheta.
double emitting_solid_angle(const Light& light) {
  if (light.type != LightType::spot) return 4.0 * std::numbers::pi;
  const int steps = 20000;
  double total = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double theta = (k + 0.5) * std::numbers::pi / steps;
    // A unit vector at angle theta from the spot's axis.
    const glm::vec3 axis = light.direction;
    const glm::vec3 side = any_tangent(axis);
    const glm::vec3 direction = float(std::cos(theta)) * axis + float(std::sin(theta)) * side;
    total += double(light.spot_factor(direction)) * 2.0 * std::numbers::pi * std::sin(theta) *
             (std::numbers::pi / steps);
  }
  return total;
}

bool is_zero(const Rgb& c) { return c.r <= 0.0f && c.g <= 0.0f && c.b <= 0.0f; }

// The materials the scene's meshes show as metals with a highlight only (kd = 0, ks > 0, no
// mirror, no glass): radiosity computes diffuse light only, so they are black in its picture,
// while the other models show their highlight. Most are glTF metals by omission (metallicFactor
// is 1 where a file leaves it out, as Khronos's Box does): the message says what to change.
// Mirrors and glass are black in radiosity too, but on purpose: the hybrid is for them.
std::vector<std::string> metal_warnings(const Scene& scene) {
  std::vector<std::string> warnings;
  std::vector<bool> shown(scene.materials.size(), false);
  for (const Mesh& mesh : scene.meshes) shown.at(size_t(mesh.material)) = true;
  for (size_t k = 0; k < scene.materials.size(); ++k) {
    const Material& m = scene.materials[k];
    if (!shown[k] || !is_zero(m.kd) || m.is_emissive() || is_zero(m.ks)) continue;
    if (!is_zero(m.kr) || !is_zero(m.kt)) continue;
    warnings.push_back(i18n::trf("radiosity: material \"{}\" is a metal (kd = 0, a highlight only; glTF "
                                 "reads a material that leaves metallicFactor out as metallic); radiosity "
                                 "computes diffuse light only, so it is black here, and the hybrid adds its "
                                 "highlight. For a diffuse surface give it metallicFactor 0 (Blender: "
                                 "Metallic 0)", m.name));
  }
  return warnings;
}

}  // namespace

// ---- [powers] ----------------------------------------------------------------------------------
double ProgressiveSolver::power(const Rgb& exitance, float area) {
  return mean(exitance) * double(area);
}

// ---- [construction and reset] ------------------------------------------------------------------
ProgressiveSolver::ProgressiveSolver(const Scene& scene, PatchMesh& mesh,
                                     const RadiosityOptions& options)
    : scene_(scene), mesh_(mesh), revision_(mesh.revision), options_(options), items_(mesh),
      hemicube_(mesh, items_, options.hemicube_res, options.hemicube_passes, options.hemicube_sums) {
  warnings_ = metal_warnings(scene);
  for (size_t k = 0; k < scene.lights.size(); ++k) {
    const Light& light = scene.lights[k];
    if (!light.enabled) continue;
    lights_.push_back(k);
  }
  // A sun's rays are cast whatever the form factors (a light at infinity has no place for a cube).
  if (std::any_of(lights_.begin(), lights_.end(),
                  [&](size_t k) { return scene.lights[k].type != LightType::directional; }))
    cube_ = std::make_unique<PointSource>(mesh, items_, options.hemicube_res);
  double rho_area = 0.0, area = 0.0;
  for (const Patch& p : mesh.patches) {
    rho_area += mean(p.rho) * double(p.area);
    area += double(p.area);
  }
  mean_rho_ = area > 0.0 ? rho_area / area : 0.0;
  reset();
}

// Step 1: radiosity = 0, unshot = E for every patch, on the mesh as it was given.
void ProgressiveSolver::reset() {
  if (refinement_passes_ > 0) {
    const int revision = mesh_.revision;
    mesh_ = original_;
    mesh_.revision = revision + 1;
    revision_ = mesh_.revision;
    items_.upload(mesh_);
    refinement_passes_ = 0;
  }
  budget_reached_ = false;
  next_refinement_ = 0;
  radiosity_.assign(mesh_.size(), Rgb(0.0f));
  unshot_.assign(mesh_.size(), Rgb(0.0f));
  irradiance_.assign(mesh_.size(), Rgb(0.0f));
  patch_unshot_.assign(mesh_.shooters.size(), glm::dvec3(0.0));
  tally_ = EnergyTally{};
  for (size_t j = 0; j < mesh_.size(); ++j) {
    add_unshot(j, mesh_.patches[j].emission);
    tally_.emitted += power(unshot_[j], mesh_.patches[j].area);
  }
  light_power_.clear();
  for (const size_t k : lights_) {
    light_power_.push_back(light_power(scene_.lights[k]));
    tally_.emitted += mean(light_power_.back());
  }
  next_light_ = 0;
  shots_ = 0;
  element_shots_ = 0.0;
  last_shooter_ = -1;
  random_.seed(options_.seed);
  history_.clear();
  started_ = now_seconds();
  record(-1);  // shot 0: everything unshot
}

// ---- [step 2: shoot a patch] -------------------------------------------------------------------
// Step 2 for shooting patch i, line by line as slide 39 writes it. What the slide leaves out, the
// hemicube's rotation, where it stands, the energy balance, the timings and the history, is in
// the helpers after it.
void ProgressiveSolver::shoot(size_t i) {
  const ShootingPatch& shooter = mesh_.shooters[i];
  const float rotation = hemicube_rotation();

  // radiosidad[i] = radiosidad[i] + carga[i];  carga[i] = 0
  // (the slide zeroes carga[i] before the loop that uses it: what is shot is kept aside first).
  const Rgb shot = take_unshot(i);

  // para cada j: calcular F_ji
  const std::vector<FormFactor>& row = this->row(i, rotation);

  // carga[j] = carga[j] + rho_j F_ji carga[i]
  const auto update_start = std::chrono::steady_clock::now();
  arriving_from(shooter, row, shot);
  for (size_t k = 0; k < row.size(); ++k) {
    const Patch& receiver = mesh_.patches[row[k].patch];
    receive(row[k].patch, arriving_[k] / receiver.area);
  }
  tally_shot(row, power(shot, shooter.area));
  update_seconds_ = seconds_since(update_start);
  count_shot(int(i));
}

// A random turn of the hemicube about the patch's normal for each shot (options.random_rotation),
// so that its aliasing falls elsewhere every time; 0 without it.
float ProgressiveSolver::hemicube_rotation() {
  return options_.random_rotation
      ? std::uniform_real_distribution<float>(0.0f, 2.0f * std::numbers::pi_v<float>)(random_)
      : 0.0f;
}

// Patch i's unshot radiosity moves to its radiosity, element by element, and what it shoots comes
// back: the area-weighted mean of its elements' (sent_ keeps each element's part). Overshooting
// sends w times it and leaves (1 - w) times it behind.
Rgb ProgressiveSolver::take_unshot(size_t i) {
  const ShootingPatch& shooter = mesh_.shooters[i];
  const float w = options_.overshoot;
  glm::dvec3 shot_power_rgb(0.0);
  sent_.clear();
  for (uint32_t k = shooter.first; k < shooter.first + shooter.count; ++k) {
    const uint32_t e = mesh_.members[k];
    const Rgb sent = w * unshot_[e];
    sent_.push_back(sent);
    shot_power_rgb += glm::dvec3(sent) * double(mesh_.patches[e].area);
    radiosity_[e] += sent;
    unshot_[e] -= sent;
  }
  patch_unshot_[i] *= double(1.0f - w);
  return Rgb(shot_power_rgb / double(shooter.area));
}

// The power arriving at each j of the row, F_ij A_i x what i sends, into arriving_ (on TBB's
// threads: the analytic factors are most of a shot's work). By reciprocity, F_ji = F_ij A_i / A_j,
// j's unshot radiosity then grows by rho_j F_ji x what i sends = rho_j x arriving_ / A_j. The
// page's main thread takes its share: form_factor_to and seen_from reach no function-local static
// with a dynamic initialiser and no thread-local object with a destructor (core/parallel_for.h).
void ProgressiveSolver::arriving_from(const ShootingPatch& shooter, const std::vector<FormFactor>& row,
                                      const Rgb& shot) {
  arriving_.resize(row.size());
  parallel_for_ranges(
      size_t(0), row.size(), size_t(128),
      [&](size_t first, size_t end) {
        for (size_t k = first; k != end; ++k) {
          const Patch& receiver = mesh_.patches[row[k].patch];
          const double F_ij = form_factor_to(shooter, row[k]);
          arriving_[k] = float(F_ij * double(shooter.area)) * seen_from(shooter, receiver, shot, sent_);
        }
      },
      parallel::MainThread::joins);
}

// The energy balance of a shot that sent `sent` watts: of the power arriving_ at each receiver of
// `row`, rho_j is reflected and the rest absorbed; what arrived nowhere escaped the scene.
void ProgressiveSolver::tally_shot(const std::vector<FormFactor>& row, double sent) {
  double delivered = 0.0;
  for (size_t k = 0; k < row.size(); ++k) {
    const Patch& receiver = mesh_.patches[row[k].patch];
    tally_.absorbed += mean((Rgb(1.0f) - receiver.rho) * arriving_[k]);
    delivered += mean(arriving_[k]);
  }
  tally_.escaped += sent - delivered;
}

// One shot more, and its line in the history.
void ProgressiveSolver::count_shot(int shooter) {
  ++shots_;
  record(shooter);
}

// F from the shooting patch to element j, given the hemicube's point-to-area value from the
// patch's centre. The analytic method takes from the hemicube only what it is good at, which
// part of element j can be seen (its value over the exact unoccluded factor from the same
// point, the hemicube's eye), and integrates the rest exactly: F_ji by Lambert's contour
// integral from element j to the patch's triangle, so F_ij = visible * F_ji A_j / A_i. Every
// receiver of the row is done so (mixing two estimates in one row would not sum to what the
// patch sends).
double ProgressiveSolver::form_factor_to(const ShootingPatch& shooter, const FormFactor& hemicube) const {
  if (options_.form_factors != FormFactorMethod::analytic) return double(hemicube.value);
  const Patch& element = mesh_.patches[hemicube.patch];
  const glm::vec3 corners[3] = {mesh_.vertices[element.vertices[0]],
                                mesh_.vertices[element.vertices[1]],
                                mesh_.vertices[element.vertices[2]]};
  const glm::vec3 eye = eye_ + Hemicube::eye_height(shooter.clearance) * shooter.normal;
  const double unoccluded = point_to_polygon_form_factor(eye, shooter.normal, corners);
  if (!(unoccluded > 0.0)) return double(hemicube.value);
  const double visible = double(hemicube.value) / unoccluded;
  return visible * element_to_patch_form_factor(mesh_, element, shooter) * double(element.area) /
         double(shooter.area);
}

// The hemicube's point of a shot: the centroid of the patch's elements weighted by what each
// sends (the patch's centre when they all send alike). A floor patch half under a block then
// looks at the room from its open half, where its light leaves from, not from under the block,
// which would hide all of it. (The rays weigh each point by its element instead.)
glm::vec3 ProgressiveSolver::emission_centre(const ShootingPatch& shooter) const {
  glm::dvec3 sum(0.0);
  double weight = 0.0;
  for (uint32_t k = 0; k < shooter.count; ++k) {
    const Patch& element = mesh_.patches[mesh_.members[shooter.first + k]];
    const double w = std::max(0.0, mean(sent_[k])) * double(element.area);
    sum += w * glm::dvec3(element.centre);
    weight += w;
  }
  return weight > 0.0 ? glm::vec3(sum / weight) : shooter.centre;
}

// The shooter's row F_ij: from its hemicube, standing where the patch's light leaves from
// (emission_centre, of what take_unshot kept in sent_), or cast with rays (which need no GL and
// are timed as the row's "draw").
const std::vector<FormFactor>& ProgressiveSolver::row(size_t i, float rotation) {
  const ShootingPatch& shooter = mesh_.shooters[i];
  eye_ = emission_centre(shooter);
  if (options_.form_factors != FormFactorMethod::rays) {
    const std::vector<FormFactor>& row =
        hemicube_.row(eye_, shooter.normal, shooter.clearance, rotation);
    row_times_ = hemicube_.last_times();
    return row;
  }
  const auto start = std::chrono::steady_clock::now();
  const std::vector<FormFactor>& row =
      rays().row(i, options_.visibility_rays, options_.seed, uint32_t(shots_), sent_);
  row_times_ = RowTimes{};
  row_times_.draw = seconds_since(start);
  return row;
}

// What element j receives of the shot, per square metre the shooter sends it: the patch's
// area-weighted mean `shot`, except, with the analytic methods, next to the patch (where the
// shooter is not small seen from j), where each of its elements counts with its own form factor
// from j: the mean of its elements' sent radiosity weighted by F(j -> element). A patch half
// under a block then lights the block's foot with its bright half, as its elements would.
// `parts`: what each of the patch's elements sent, in the order of its members.
Rgb ProgressiveSolver::seen_from(const ShootingPatch& shooter, const Patch& receiver,
                                 const Rgb& shot, const std::vector<Rgb>& parts) const {
  if (options_.form_factors == FormFactorMethod::hemicube || shooter.count < 2) return shot;
  if (!near_the_patch(receiver, shooter)) return shot;
  const glm::vec3 corners[3] = {mesh_.vertices[receiver.vertices[0]],
                                mesh_.vertices[receiver.vertices[1]],
                                mesh_.vertices[receiver.vertices[2]]};
  glm::dvec3 weighted(0.0);
  double total = 0.0;
  for (uint32_t k = 0; k < shooter.count; ++k) {
    const Patch& part = mesh_.patches[mesh_.members[shooter.first + k]];
    const glm::vec3 polygon[3] = {mesh_.vertices[part.vertices[0]], mesh_.vertices[part.vertices[1]],
                                  mesh_.vertices[part.vertices[2]]};
    const double F = triangle_to_polygon_form_factor(corners[0], corners[1], corners[2],
                                                     receiver.normal, polygon);
    weighted += F * glm::dvec3(parts[k]);
    total += F;
  }
  return total > 0.0 ? Rgb(weighted / total) : shot;
}

void ProgressiveSolver::receive(size_t element, const Rgb& arriving) {
  irradiance_[element] += arriving;
  add_unshot(element, mesh_.patches[element].rho * arriving);
}

void ProgressiveSolver::add_unshot(size_t element, const Rgb& gain) {
  unshot_[element] += gain;
  patch_unshot_[mesh_.shooter_of[element]] +=
      glm::dvec3(gain) * double(mesh_.patches[element].area);
}

// ---- [point lights] ----------------------------------------------------------------------------
// The flux I * omega reaching an element of solid angle omega from the light, with the classroom
// attenuation where the scene asks for it (f_att(d) d^2: 1 for the physical 1/d^2). For a sun,
// `value` is the element's sunlit area A cos(theta) V and the flux E_perp times it (no distance,
// no attenuation: the light is parallel).
Rgb ProgressiveSolver::light_flux(const Light& light, const Patch& receiver, float value) {
  if (light.type == LightType::directional) return light.intensity * value;
  const float omega = value;
  float attenuation = 1.0f;
  if (light.attenuation.classroom) {
    const float d = glm::length(receiver.centre - light.position);
    attenuation = light.attenuation.factor(d) * d * d;
  }
  return light.intensity * (omega * attenuation);
}

// Patch j receives the flux Phi_j = I * omega_j (omega_j: its spot-weighted solid angle from the
// light), so its irradiance is Phi_j / A_j and it gains rho_j Phi_j / A_j of unshot exitance.
// A sun gives Phi_j = E_perp A_j cos(theta_j) V_j (its sunlit area, from rays).
void ProgressiveSolver::shoot_light(size_t k) {
  const Light& light = scene_.lights[lights_[k]];
  const std::vector<FormFactor>& omegas = light_row(light);
  row_times_ = RowTimes{};
  arriving_.resize(omegas.size());
  for (size_t n = 0; n < omegas.size(); ++n) {
    const Patch& receiver = mesh_.patches[omegas[n].patch];
    arriving_[n] = light_flux(light, receiver, omegas[n].value);
    receive(omegas[n].patch, arriving_[n] / receiver.area);
  }
  tally_shot(omegas, mean(light_power_[k]));
  count_shot(-1 - int(k));
}

// What a light reaches: per element, its spot-weighted solid angle from the light (a point source
// drawn with a cube, or cast with rays), or a sun's sunlit area (rays: a light at infinity has no
// place for a cube).
const std::vector<FormFactor>& ProgressiveSolver::light_row(const Light& light) {
  const int rays = 4 * options_.visibility_rays;
  if (light.type == LightType::directional)
    return this->rays().sunlit_areas(light, rays, options_.seed, uint32_t(shots_));
  if (options_.form_factors == FormFactorMethod::rays)
    return this->rays().solid_angles(light, rays, options_.seed, uint32_t(shots_));
  return cube_->solid_angles(light);
}

// The power a light sends: I x its emitting solid angle, or for a sun E_perp over its beam's
// cross-section (beam_cross_section).
Rgb ProgressiveSolver::light_power(const Light& light) const {
  return light.type == LightType::directional ? light.intensity * float(beam_cross_section())
                                              : light.intensity * float(emitting_solid_angle(light));
}

// What a sun sends at the scene: E_perp over the disc that the scene's bounding sphere shows the
// beam, pi R^2 with R half the diagonal of the elements' bounds. Every element it reaches lies
// in that disc, seen along the beam, and no two cover the same part of it (a ray stops at the
// first), so what arrives is at most this; the rest escapes.
double ProgressiveSolver::beam_cross_section() const {
  Bounds bounds;
  for (const glm::vec3& v : mesh_.vertices) bounds.grow(v);
  if (bounds.empty()) return 0.0;
  const double radius = 0.5 * double(glm::length(bounds.extent()));
  return std::numbers::pi * radius * radius;
}

// ---- [the loop] --------------------------------------------------------------------------------
size_t ProgressiveSolver::most_unshot_patch() const {
  size_t best = 0;
  double best_power = -1.0;
  for (size_t i = 0; i < patch_unshot_.size(); ++i) {
    const double p = std::abs(mean(patch_unshot_[i]));
    if (p > best_power) {
      best_power = p;
      best = i;
    }
  }
  return best;
}

bool ProgressiveSolver::done() const {
  if (options_.max_shots > 0 && shots_ >= options_.max_shots) return true;
  if (unshot_power() <= 0.0) return true;
  return options_.converge > 0.0f && unshot_fraction() < double(options_.converge);
}

// Step 4: repeat until no difference shows. One call is one shot, so the viewer can spend a time
// budget per frame and redraw (step 3) between shots.
bool ProgressiveSolver::step() {
  refuse_a_changed_mesh();
  if (done()) return false;
  if (next_light_ < lights_.size()) {
    shoot_light(next_light_++);  // punctual lights first, each once
    return true;
  }
  if (refinement_due()) refine();
  shoot(most_unshot_patch());  // "elegir el retazo más cargado (i) y propagar"
  return true;
}

void ProgressiveSolver::refuse_a_changed_mesh() const {
  if (mesh_.revision != revision_)
    throw Error(ErrorKind::bad_value, i18n::tr("radiosity: the mesh was changed by another solver's "
                                               "adaptive subdivision; give each solver its own mesh"));
}

void ProgressiveSolver::record(int shooter) {
  last_shooter_ = shooter;
  if (shots_ > 0) element_shots_ += double(mesh_.size());  // shot 0 is the start
  ShotRecord r;
  r.shot = shots_;
  r.shooter = shooter;
  r.unshot_power = unshot_power();
  r.fraction = unshot_fraction();
  r.seconds = now_seconds() - started_;
  history_.push_back(r);
}

// ---- [state] -----------------------------------------------------------------------------------
// Step 3: display every patch with radiosity + unshot.
std::vector<Rgb> ProgressiveSolver::displayed() const {
  std::vector<Rgb> b(radiosity_.size());
  for (size_t i = 0; i < b.size(); ++i) b[i] = radiosity_[i] + unshot_[i];  // step 3
  return b;
}

Rgb ProgressiveSolver::patch_sent(size_t shooter) const {
  const ShootingPatch& s = mesh_.shooters[shooter];
  glm::dvec3 sum(0.0);
  for (uint32_t k = s.first; k < s.first + s.count; ++k) {
    const uint32_t e = mesh_.members[k];
    sum += glm::dvec3(radiosity_[e]) * double(mesh_.patches[e].area);
  }
  return Rgb(sum / double(s.area));
}

Rgb ProgressiveSolver::patch_radiosity(size_t shooter) const {
  const ShootingPatch& s = mesh_.shooters[shooter];
  glm::dvec3 sum(0.0);
  for (uint32_t k = s.first; k < s.first + s.count; ++k) {
    const uint32_t e = mesh_.members[k];
    sum += glm::dvec3(radiosity_[e] + unshot_[e]) * double(mesh_.patches[e].area);
  }
  return Rgb(sum / double(s.area));
}

double ProgressiveSolver::unshot_power() const {
  double total = 0.0;
  for (const glm::dvec3& u : patch_unshot_) total += std::abs(mean(u));
  for (size_t k = next_light_; k < lights_.size(); ++k) total += mean(light_power_[k]);
  return total;
}

double ProgressiveSolver::unshot_fraction() const {
  return tally_.emitted > 0.0 ? unshot_power() / tally_.emitted : 0.0;
}

// With overshooting, patches hold negative unshot power: the balance sums it with its sign.
EnergyTally ProgressiveSolver::energy() const {
  EnergyTally t = tally_;
  t.unshot = 0.0;
  for (const glm::dvec3& u : patch_unshot_) t.unshot += mean(u);
  for (size_t k = next_light_; k < lights_.size(); ++k) t.unshot += mean(light_power_[k]);
  return t;
}

Rgb ProgressiveSolver::ambient() const {
  Rgb unshot_power_rgb(0.0f);
  for (size_t i = 0; i < unshot_.size(); ++i) unshot_power_rgb += unshot_[i] * mesh_.patches[i].area;
  for (size_t k = next_light_; k < lights_.size(); ++k) unshot_power_rgb += light_power_[k];
  const float area = mesh_.total_area();
  if (!(area > 0.0f) || mean_rho_ >= 1.0) return Rgb(0.0f);
  // Cohen et al. 1988: ambient = R * sum(unshot_j A_j) / sum(A_j), R = 1 / (1 - rho_mean).
  return unshot_power_rgb / area / float(1.0 - mean_rho_);
}

}  // namespace luz
