#pragma once
// Progressive refinement radiosity, as slide 39 writes it (Cohen, Chen, Wallace and Greenberg,
// "A Progressive Refinement Approach to Fast Radiosity Image Generation", SIGGRAPH 1988):
//
//   1. for every patch: radiosity = 0, unshot ("carga emisora") = E
//   2. take the patch i with the most unshot power (unshot * area) and shoot it:
//        radiosity[i] += unshot[i]; unshot[i] = 0;
//        for every j: compute F_ji; unshot[j] += rho_j * F_ji * (what i shot)
//   3. display every patch with radiosity + unshot
//   4. repeat until no difference shows (the unshot power is a small part of the emitted one)
//
// F_ji comes from the shooter's row F_ij by reciprocity, F_ji = F_ij A_i / A_j; the row from its
// hemicube, or cast with rays (options.form_factors, ray_form_factors.h).
// The scene's punctual lights are shot first, each once: point and spot lights as point sources
// (point_source.h), directional ones (a sun) as parallel light, each element receiving
// E_perp cos(theta) where a ray toward the light is unblocked (ray_form_factors.h).
//
// Substructuring (patch_mesh.h): i runs over the shooting patches and j over the elements. Each
// element keeps its own radiosity and unshot radiosity; a patch's unshot radiosity is the
// area-weighted mean of its elements', and when it shoots, all of its elements' unshot
// radiosity goes out at once, through one row of form factors to the elements (the hemicube's
// item buffer holds element IDs; rays go to element points). A receiver next to the patch sees
// each of its elements with its own form factor (seen_from). What is displayed is the elements'
// radiosity + unshot.
//
// Overshooting (options.overshoot = w > 1): the shooter sends w x its unshot radiosity and keeps
// (1 - w) x unshot, a negative amount shot back later; radiosity + unshot, what is displayed,
// is unchanged by the shot itself, and the iteration converges to the same B (successive
// over-relaxation of Southwell's method, Gortler, Cohen & Slusallek 1993). The patch to shoot
// is then the one with the largest |unshot power|, and "unshot power" sums magnitudes.
//
// Adaptive subdivision (options.meshing): when the unshot power first falls below each of
// kRefineAt's fractions (once every light has shot), elements whose irradiance differs from a
// neighbour's are cut in two (mesh_bisection.h) and each new element gathers what every patch
// and light has shot so far, F(j -> i) x V x what i sent in all its shots (radiosity[i] is
// exactly that sum), so it holds what it would have received had it existed from the start.
// Its unshot radiosity is then that minus what its parent had already sent; the light the
// coarser element had counted wrongly is moved between "escaped", "absorbed" and "unshot", so
// the energy balance holds at every step. The solver refines the mesh it was given: two solvers
// must not share one then (step() refuses a mesh another has changed).
//
// The solver steps on the thread that owns the GL context: step() is one shot, so the viewer
// can spend a time budget per frame and show each step. All quantities are RGB exitances
// (W/m^2) per patch; powers are those times the area, summed as the mean of R, G and B.
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/color.h"
#include "core/scene.h"
#include "radiosity/hemicube.h"
#include "radiosity/item_buffer.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/point_source.h"
#include "radiosity/ray_form_factors.h"
#include "radiosity/radiosity_options.h"

namespace luz {

class MeshBisection;

// One row of the history: after shot `shot` (1-based), the unshot power left.
struct ShotRecord {
  int shot = 0;
  int shooter = -1;           // patch index, or -1 - k for the scene's light k
  double unshot_power = 0.0;  // W (mean of R, G, B)
  double fraction = 0.0;      // unshot_power / emitted_power
  double seconds = 0.0;       // since the solver started
};

// Where the emitted power has gone so far (W, mean of R, G, B). emitted = absorbed + unshot +
// escaped at every step; escaped is what left the scene or hit the back of a patch (0 up to the
// hemicube's discretisation in a closed room of front faces).
// Adaptive subdivision's passes: when the unshot power first falls below each fraction of the
// emitted power (the first once the direct light has been shot, the others for the gradients the
// interreflections make).
inline constexpr double kRefineAt[] = {0.5, 0.15, 0.05};

struct EnergyTally {
  double emitted = 0.0;
  double absorbed = 0.0;
  double unshot = 0.0;
  double escaped = 0.0;
};

class ProgressiveSolver {
public:
  // Needs a current GL context (the hemicube draws through it) for its whole life. `mesh` and
  // `scene` must outlive the solver; with adaptive subdivision the solver refines `mesh`, and
  // reset() puts it back as it was given. warnings() names the materials radiosity shows black.
  ProgressiveSolver(const Scene& scene, PatchMesh& mesh, const RadiosityOptions& options);

  // Step 1 again: radiosity = 0, unshot = E, lights unshot, history cleared.
  void reset();
  // One shot: the next punctual light, else the patch with the most unshot power. Returns
  // false (and shoots nothing) when done(): converged, out of shots, or nothing left to shoot.
  bool step();
  bool done() const;
  // Step 2 for shooting patch i, mesh().shooters[i] (public so a test or the viewer can shoot a
  // chosen patch; without substructuring shooter i is element i).
  void shoot(size_t i);
  // Shoots the scene's light k: a point source, or parallel light for a directional one.
  void shoot_light(size_t k);
  // One pass of adaptive subdivision now (step() makes them at kRefineAt); returns the elements
  // it added.
  size_t refine();

  // ---- State ----
  // Per element.
  const std::vector<Rgb>& radiosity() const { return radiosity_; }
  const std::vector<Rgb>& unshot() const { return unshot_; }
  // The light that has arrived, per square metre (W/m^2): displayed = E + rho x irradiance.
  const std::vector<Rgb>& irradiance() const { return irradiance_; }
  // Step 3: what each element shows, radiosity + unshot (exitance B, W/m^2).
  std::vector<Rgb> displayed() const;
  // A shooting patch's radiosity: the area-weighted mean of its elements' displayed values.
  Rgb patch_radiosity(size_t shooter) const;
  // Cohen et al. 1988's ambient term: the unshot power spread over the scene's area, times
  // 1 / (1 - mean reflectance) for its interreflections. A patch would show rho_i * ambient
  // more once everything were shot.
  Rgb ambient() const;
  // Sum over shooting patches (and lights not yet shot) of |unshot power|.
  double unshot_power() const;
  double emitted_power() const { return tally_.emitted; }
  double unshot_fraction() const;
  EnergyTally energy() const;
  int shots() const { return shots_; }
  // The work done so far: the elements in the mesh at each shot, summed over the shots.
  double element_shots() const { return element_shots_; }
  // Shooting patch, -1 - k for light k, or -1 before any.
  int last_shooter() const { return last_shooter_; }
  size_t lights_left() const { return lights_.size() - next_light_; }
  // Adaptive subdivision's passes so far, and the elements they added.
  int refinement_passes() const { return refinement_passes_; }
  size_t refined_elements() const { return refinement_passes_ > 0 ? mesh_.size() - original_.size() : 0; }
  const std::vector<ShotRecord>& history() const { return history_; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  // Seconds spent in the last shot on drawing, reading back, accumulating (hemicube) and on
  // updating the unshot values.
  const RowTimes& last_row_times() const { return row_times_; }
  double last_update_seconds() const { return update_seconds_; }

  // The stopping rule, the rotation and the display switches may change between steps;
  // patch size and hemicube resolution need a new mesh and solver.
  RadiosityOptions& options() { return options_; }
  const RadiosityOptions& options() const { return options_; }
  const PatchMesh& mesh() const { return mesh_; }
  Hemicube& hemicube() { return hemicube_; }

private:
  // Step 2's pieces (shooting.cpp): the patch's unshot radiosity into its radiosity, returning
  // what it shoots; the power arriving at each element of its row; the energy balance of a shot.
  float hemicube_rotation();
  Rgb take_unshot(size_t shooter);
  void arriving_from(const ShootingPatch& shooter, const std::vector<FormFactor>& row, const Rgb& shot);
  void tally_shot(const std::vector<FormFactor>& row, double sent);
  void count_shot(int shooter);
  void record(int shooter);
  // A light's row (solid angles, or a sun's sunlit areas) and the power it sends.
  const std::vector<FormFactor>& light_row(const Light& light);
  Rgb light_power(const Light& light) const;
  void refuse_a_changed_mesh() const;
  size_t most_unshot_patch() const;
  static double power(const Rgb& exitance, float area);
  double form_factor_to(const ShootingPatch& shooter, const FormFactor& hemicube) const;
  glm::vec3 emission_centre(const ShootingPatch& shooter) const;
  const std::vector<FormFactor>& row(size_t shooter, float rotation);
  Rgb seen_from(const ShootingPatch& shooter, const Patch& receiver, const Rgb& shot,
                const std::vector<Rgb>& parts) const;
  // Element j receives `arriving` W/m^2: its irradiance grows by it and its unshot radiosity by
  // rho_j times it.
  void receive(size_t element, const Rgb& arriving);
  // Element j's unshot radiosity grows by `gain` (its patch's unshot power with it).
  void add_unshot(size_t element, const Rgb& gain);
  static Rgb light_flux(const Light& light, const Patch& receiver, float value);
  double beam_cross_section() const;
  bool refinement_due() const;
  // Adaptive subdivision's pieces (adaptive_subdivision.cpp).
  std::vector<uint32_t> too_coarse(const MeshBisection& bisection,
                                   const std::vector<uint32_t>& candidates) const;
  Rgb gather(uint32_t element, const std::vector<uint32_t>& senders, const std::vector<Rgb>& sent,
             const std::vector<ShooterEmission>& emissions,
             const std::vector<std::vector<Rgb>>& parts) const;
  // What a shooting patch has sent in all its shots, per square metre.
  Rgb patch_sent(size_t shooter) const;
  RayFormFactors& rays();

  const Scene& scene_;
  PatchMesh& mesh_;
  PatchMesh original_;  // the mesh as given, kept at the first refinement for reset()
  int revision_ = 0;    // of the mesh as this solver last left it
  RadiosityOptions options_;
  PatchItems items_;
  Hemicube hemicube_;
  glm::vec3 eye_{0.0f};  // where the shooting patch's hemicube stands (emission_centre)
  std::unique_ptr<RayFormFactors> rays_;  // made at the first shot with FormFactorMethod::rays
  std::unique_ptr<PointSource> cube_;  // made when the scene has punctual lights
  std::vector<size_t> lights_;         // the scene's lights that shoot (the enabled ones)
  size_t next_light_ = 0;
  std::vector<Rgb> light_power_;       // I * sum(spot d_omega), or a sun's E_perp * pi R^2
  std::vector<Rgb> radiosity_, unshot_, irradiance_;  // per element
  std::vector<Rgb> sent_;                 // per element of the patch shooting now
  std::vector<Rgb> arriving_;             // per entry of its row: the power arriving (W)
  std::vector<glm::dvec3> patch_unshot_;  // per shooting patch: sum of A_j unshot_j (W)
  EnergyTally tally_;
  int shots_ = 0;
  double element_shots_ = 0.0;
  int last_shooter_ = -1;
  int refinement_passes_ = 0;
  bool budget_reached_ = false;  // adaptive subdivision stopped at options_.refine_budget
  size_t next_refinement_ = 0;  // into kRefineAt
  std::mt19937 random_;
  std::vector<ShotRecord> history_;
  std::vector<std::string> warnings_;
  RowTimes row_times_;
  double update_seconds_ = 0.0;
  double started_ = 0.0;
  double mean_rho_ = 0.0;
};

}  // namespace luz
