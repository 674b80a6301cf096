// Sections: [construction] [a frame's shooting] [drawing] [the clicked patch] [json]
#include "app/models/radiosity/radiosity_session.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "app/common/i18n.h"
#include "radiosity/vertex_colours.h"

namespace luz::app {

// ---- [construction] ----------------------------------------------------------------------------
RadiositySession::RadiositySession(const Scene& scene, const RadiosityOptions& options)
    : scene_(scene), built_with_(options), mesh_(PatchMesh::build(scene, options)),
      solver_(scene, mesh_, options), renderer_(scene, mesh_), shown_with_(options) {
  for (const std::string& warning : solver_.warnings()) fmt::print(stderr, "{}\n", trf("warning: {}", warning));
}

bool RadiositySession::built_for(const RadiosityOptions& o) const {
  return o.patch_size == built_with_.patch_size && o.target_patches == built_with_.target_patches &&
         o.hemicube_res == built_with_.hemicube_res && o.hemicube_passes == built_with_.hemicube_passes &&
         o.hemicube_sums == built_with_.hemicube_sums && o.elements_per_edge == built_with_.elements_per_edge;
}

// ---- [a frame's shooting] ----------------------------------------------------------------------
void RadiositySession::advance(RadiosityState& state, const RadiosityOptions& options, float exposure,
                               bool heat_map) {
  RadiosityDrive& drive = state.drive;
  // Everything but the mesh and the hemicube may change between shots (shooting.h).
  RadiosityOptions& o = solver_.options();
  o.random_rotation = options.random_rotation;
  o.seed = options.seed;  // used from the next reset on
  o.max_shots = options.max_shots;
  o.converge = options.converge;
  o.overshoot = options.overshoot;
  o.form_factors = options.form_factors;
  o.visibility_rays = options.visibility_rays;
  o.meshing = options.meshing;  // from the next pass on; restart to refine from the start
  o.refine_threshold = options.refine_threshold;
  o.refine_levels = options.refine_levels;
  o.ambient_estimate = options.ambient_estimate;
  o.flat_patches = options.flat_patches;
  o.outlines = options.outlines;

  if (state.reset) {  // slide 39 step 1; paused, so the class can follow the first shots
    state.reset = false;
    state.steps = 0;
    state.stop_at = 0;
    drive.running = false;
    solver_.reset();
    colours_stale_ = true;
    item_view_shot_ = -1;
  }

  // Single shots and running shots share the frame's budget: a long `step 500` or a run both
  // leave the window responsive, and at least one shot is made per frame so a slow shot still
  // moves on.
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const auto until = start + std::chrono::duration<double, std::milli>(std::max(drive.budget_ms, 0.0f));
  int shot = 0;
  while (state.steps > 0 || drive.running) {
    if (state.stop_at > 0 && solver_.shots() >= state.stop_at) {  // wait-shots: pause right there
      state.stop_at = 0;
      drive.running = false;
      break;
    }
    if (!solver_.step()) {  // converged, out of shots, or nothing to shoot
      state.steps = 0;
      state.stop_at = 0;
      drive.running = false;
      break;
    }
    ++shot;
    if (state.steps > 0) --state.steps;
    if (drive.by_time ? clock::now() >= until : shot >= std::max(drive.shots_per_frame, 1)) break;
  }
  if (state.stop_at > 0 && solver_.shots() >= state.stop_at) {  // reached on this frame's last shot
    state.stop_at = 0;
    drive.running = false;
  }
  // This frame's last shot may have met the stopping rule: everything asked of the solver ends
  // now, as the next step() would end it, not a frame later. So "done" and "not running" are
  // seen together, and a `wait-shots N` past the rule is answered: the loop above runs only
  // while shots are asked for (steps, running), so no later frame would clear its stop_at, and
  // the script would wait for it forever.
  if (solver_.done()) {
    drive.running = false;
    state.steps = 0;
    state.stop_at = 0;
  }

  const auto now = clock::now();
  const double seconds = std::chrono::duration<double>(now - last_advance_).count();
  last_advance_ = now;
  shot += std::exchange(shots_between_frames_, 0);
  if (shot > 0 && seconds > 0.0) {  // per second of the viewer's time, frames included
    const double rate = shot / seconds;
    shots_per_second_ = shots_per_second_ > 0.0 ? 0.8 * shots_per_second_ + 0.2 * rate : rate;
  } else if (!drive.running) {
    shots_per_second_ = 0.0;
  }
  if (shot > 0) colours_stale_ = true;

  // Step 3: what every patch shows, uploaded again after the shots (or a change of display).
  const bool display_changed = heat_map != heat_map_shown_ ||
                               o.flat_patches != shown_with_.flat_patches ||
                               o.ambient_estimate != shown_with_.ambient_estimate ||
                               (heat_map && exposure != exposure_shown_);
  if (colours_stale_ || display_changed) {
    RadianceField field = heat_map ? app::unshot_heat_map(solver_) : RadianceField::of(solver_);
    if (heat_map) {
      // The display pass multiplies by 2^exposure: divide it out here so the ramp's colours are
      // those of heat_colour() whatever the scene's exposure.
      const float undo = std::exp2(-exposure);
      for (Rgb& c : field.patch) c *= undo;
      for (Rgb& c : field.corner) c *= undo;
    }
    renderer_.update(field, o, !heat_map);  // the heat map is no radiance for a texture to modulate
    colours_stale_ = false;
    heat_map_shown_ = heat_map;
    exposure_shown_ = exposure;
    shown_with_ = o;
  }
  // The overlay: the item buffer of the last patch that shot (lights shoot through their own cube).
  // With rays no hemicube is drawn for the shots: the window's is drawn over the whole scene for
  // it alone, so while the solver runs it is redrawn at most a fifth of the time (on a scene of
  // 100,000 patches it costs as much as a shot); paused, it shows the last shot at once.
  if (drive.show_item_buffer && solver_.last_shooter() >= 0 && item_view_shot_ != solver_.shots() &&
      (!drive.running || clock::now() >= item_view_due_)) {
    const auto began = clock::now();
    if (o.form_factors == FormFactorMethod::rays) {
      const ShootingPatch& p = solver_.mesh().shooters[size_t(solver_.last_shooter())];
      solver_.hemicube().row(p.centre, p.normal, p.clearance, 0.0f);
    }
    item_view_.update(solver_.hemicube());
    item_view_shot_ = solver_.shots();
    item_view_shooter_ = solver_.last_shooter();
    const auto drawn = clock::now();
    item_view_due_ = drawn + 4 * (drawn - began);
  }
  refresh_status(state, options);
}

bool RadiositySession::shoots_between_frames(const RadiosityState& state) const {
  return state.drive.running && !solver_.done() && (state.stop_at == 0 || solver_.shots() < state.stop_at);
}

void RadiositySession::shoot_between_frames(const RadiosityState& state) {
  using clock = std::chrono::steady_clock;
  const auto until = clock::now() + std::chrono::duration<double, std::milli>(std::max(state.drive.budget_ms, 0.0f));
  int shot = 0;
  while (shoots_between_frames(state) && solver_.step()) {
    ++shot;
    if (clock::now() >= until) break;
  }
  shots_between_frames_ += shot;
  if (shot > 0) colours_stale_ = true;
}

std::string RadiositySession::shooter_name(int shooter, int shots) const {
  if (shooter >= 0) {
    const Patch& p = mesh_.patches[mesh_.members[mesh_.shooters[size_t(shooter)].first]];
    return trf("patch {} ({})", shooter, scene_.meshes[size_t(p.mesh)].name);
  }
  if (shooter < -1 || (shooter == -1 && shots > 0)) {
    const int k = -1 - shooter;
    return trf("light {} ({})", k, scene_.lights[size_t(k)].name);
  }
  return {};
}

void RadiositySession::refresh_status(RadiosityState& state, const RadiosityOptions& options) const {
  RadiosityStatus& s = state.status;
  s.built = true;
  s.remesh_pending = !built_for(options);
  s.patches = mesh_.shooters.size();
  s.elements = mesh_.size();
  s.refined_elements = solver_.refined_elements();
  s.refinement_passes = solver_.refinement_passes();
  s.patch_size = mesh_.max_edge;
  s.hemicube_res = built_with_.hemicube_res;
  s.shots = solver_.shots();
  s.unshot_fraction = solver_.unshot_fraction();
  s.shots_per_second = shots_per_second_;
  s.done = solver_.done();
  s.last_shooter = solver_.last_shooter();
  s.shooter = shooter_name(s.last_shooter, s.shots);
  // Only new shots are appended: the history grows by a few entries a frame.
  const std::vector<ShotRecord>& history = solver_.history();
  if (s.plot.size() > history.size()) s.plot.clear();  // a reset
  for (size_t i = s.plot.size(); i < history.size(); ++i)
    s.plot.push_back(float(std::log10(std::max(history[i].fraction, 1e-12))));
  const bool shows_item_buffer = s.last_shooter >= 0 && item_view_shot_ >= 0;
  s.item_view_texture = shows_item_buffer ? item_view_.texture() : 0;
  s.item_view_size = shows_item_buffer ? item_view_.size() : 0;
  s.item_view_shooter = shows_item_buffer ? shooter_name(item_view_shooter_, item_view_shot_) : std::string();
}

// ---- [the heat map] ------------------------------------------------------------------------------
Rgb heat_colour(double relative) {
  if (!(relative > 0.0)) return Rgb(0.0f);
  const float t = float(std::clamp(std::log10(relative / kHeatMapLowest) / std::log10(kHeatMapHighest / kHeatMapLowest),
                                   0.0, 1.0));
  return t < 0.5f ? glm::mix(Rgb(0.0f, 0.0f, 0.3f), Rgb(0.9f, 0.0f, 0.0f), 2.0f * t)
                  : glm::mix(Rgb(0.9f, 0.0f, 0.0f), Rgb(1.0f, 1.0f, 0.0f), 2.0f * t - 1.0f);
}

RadianceField unshot_heat_map(const ProgressiveSolver& solver) {
  const PatchMesh& mesh = solver.mesh();
  double area = 0.0;
  for (const Patch& p : mesh.patches) area += double(p.area);
  // The mean emitted exitance, W/m^2, counted as the solver counts power (the channels' mean).
  const double mean_emitted = area > 0.0 ? solver.emitted_power() / area : 0.0;
  std::vector<Rgb> colours(mesh.size(), Rgb(0.0f));
  for (size_t i = 0; i < mesh.size(); ++i) {
    const Rgb& u = solver.unshot()[i];
    const double unshot = (double(u.r) + double(u.g) + double(u.b)) / 3.0;
    const double relative = mean_emitted > 0.0 ? unshot / mean_emitted : 0.0;
    colours[i] = heat_colour(relative) * std::numbers::pi_v<float>;  // from() divides by pi: show the ramp as is
  }
  return RadianceField::from(mesh, colours);
}

// ---- [drawing] ---------------------------------------------------------------------------------
void RadiositySession::draw(const Camera& camera, int width, int height, bool show_shooter) {
  // The shooter in magenta while there is one to see: not once converged, where the picture is
  // the solution `luz render --model radiosity` draws.
  const int shooter = show_shooter && !solver_.done() ? solver_.last_shooter() : -1;
  renderer_.draw(camera, width, height, solver_.options(), shooter);
}

// ---- [the clicked patch] -----------------------------------------------------------------------
PatchReading RadiositySession::read(const Pick& pick) const {
  const PatchMesh::Location where =
      mesh_.locate(pick.mesh, pick.triangle, glm::vec2(pick.barycentric[1], pick.barycentric[2]));
  const Patch& p = mesh_.patches[where.patch];
  PatchReading r;
  r.patch = where.patch;
  r.shooter = mesh_.shooter_of[where.patch];
  r.mesh = p.mesh;
  r.triangle = p.triangle;
  const int material = scene_.meshes[size_t(p.mesh)].material;
  r.material = material >= 0 && size_t(material) < scene_.materials.size() ? scene_.materials[size_t(material)].name
                                                                            : std::string("(default)");
  r.centre = p.centre;
  r.normal = p.normal;
  r.area = p.area;
  r.E = p.emission;
  r.rho = p.rho;
  r.radiosity = solver_.radiosity()[where.patch];
  r.unshot = solver_.unshot()[where.patch];
  r.B = r.radiosity + r.unshot;  // step 3
  r.radiance = r.B / std::numbers::pi_v<float>;
  r.shots = solver_.shots();
  return r;
}

// ---- [json] ------------------------------------------------------------------------------------
namespace {
nlohmann::json rgb(const Rgb& c) { return nlohmann::json::array({c.r, c.g, c.b}); }
}  // namespace

nlohmann::json to_json(const PatchReading& r) {
  return {{"patch", r.patch},       {"mesh", r.mesh},         {"triangle", r.triangle},
          {"material", r.material}, {"centre", {r.centre.x, r.centre.y, r.centre.z}},
          {"normal", {r.normal.x, r.normal.y, r.normal.z}},   {"area", r.area},
          {"E", rgb(r.E)},          {"rho", rgb(r.rho)},      {"radiosity", rgb(r.radiosity)},
          {"unshot", rgb(r.unshot)}, {"B", rgb(r.B)},         {"B_over_pi", rgb(r.radiance)},
          {"shots", r.shots}};
}

nlohmann::json to_json(const RadiosityState& state, const RadiosityOptions& options) {
  const RadiosityStatus& s = state.status;
  return {{"built", s.built},
          {"patches", s.patches},
          {"elements", s.elements},
          {"refined_elements", s.refined_elements},
          {"refinement_passes", s.refinement_passes},
          {"patch_size", s.patch_size},
          {"hemicube_res", s.hemicube_res},
          {"shots", s.shots},
          {"unshot_fraction", s.unshot_fraction},
          {"done", s.done},
          {"running", state.drive.running},
          {"last_shooter", s.last_shooter},
          {"shooter", s.shooter},
          {"plot_points", s.plot.size()},
          {"plot_rect", {s.plot_min.x, s.plot_min.y, s.plot_max.x, s.plot_max.y}},
          {"item_view_shown", s.item_view_texture != 0},
          {"item_view_shooter", s.item_view_shooter},
          {"item_view_rect", {s.item_view_min.x, s.item_view_min.y, s.item_view_max.x, s.item_view_max.y}},
          {"options", options.to_string()}};
}

}  // namespace luz::app
