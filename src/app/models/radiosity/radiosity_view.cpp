#include "app/models/radiosity/radiosity_view.h"

#include <algorithm>
#include <iterator>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <imgui.h>


#include "app/common/json_file.h"
#include "app/common/i18n.h"
#include "app/common/model_registry.h"
#include "app/viewer/inspector.h"
#include "app/models/local/local_view.h"
#include "app/common/options_tables.h"
#include "app/viewer/overlays.h"
#include "app/viewer/panel.h"
#include "app/models/radiosity/radiosity_panel.h"
#include "app/script/key_binding.h"
#include "core/error.h"
#include "gl/functions.h"
#include "radiosity/texture_detail.h"

namespace luz::app {

void RadiosityView::drop() {
  for (const auto& listener : drop_listeners_) listener();
  solution_.reset();
}

bool RadiosityView::step_and_draw(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture,
                                   Display display) {
  ViewerState& state = viewer_.state();
  RadiosityState& r = state_;
  RadiosityOptions& options = state.radiosity;
  // The kd texture follows T, as in every model. It is the patches' reflectance, so switching
  // it starts the solution over, where the scene shows a texture at all.
  options.textures = state.local.terms.textures;
  if (solution_ && solution_->mesh().detail.textures() != options.textures && TextureDetail::any_shown(*state.scene))
    r.remesh = true;
  if (!solution_ || r.remesh) {
    r.remesh = false;
    drop();  // the old solver's GL objects go before the new ones are made
    r.status = RadiosityStatus{};
    r.patch.reset();
    try {
      solution_ = std::make_unique<RadiositySession>(*state.scene, options);
      const PatchMesh& mesh = solution_->mesh();
      state.note = trf("radiosity: {} patches of {} elements, hemicube {}", mesh.shooters.size(), mesh.size(),
                       options.hemicube_res);
      for (const std::string& warning : solution_->solver().warnings()) viewer_.warn(warning);
    } catch (const Error& error) {
      state.note = error.what();
      fmt::print(stderr, "luz: {}\n", error.what());
      r.drive.running = false;
      r.steps = r.stop_at = 0;
      picture.bind();
      const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
      glClearBufferfv(GL_COLOR, 0, black);
      return false;
    }
  }
  const bool was_running = r.drive.running;
  solution_->advance(r, options, state.exposure, display.heat_map);
  if (was_running && !r.drive.running && r.status.done)
    // xgettext:no-c-format (a fmt string, where "% u" is not a printf directive)
    state.note = trf("radiosity: done after {} shots, {:.2f} % unshot", r.status.shots,
                             100.0 * r.status.unshot_fraction);
  picture.bind();
  solution_->draw(camera, viewport.pixels.x, viewport.pixels.y, display.shooter);
  return true;
}

// The solver steps here, on the GL thread, within the frame's budget; the picture is the
// solution so far (vertex colours uploaded after the shots), the shooter highlighted.
void RadiosityView::draw(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) {
  RadiosityState& r = state_;
  step_and_draw(camera, viewport, picture, {r.drive.heat_map, r.drive.show_shooter});
  // The clicked patch's values, live as the shots go on.
  const bool inspected = refresh_inspection(viewer_, camera, viewport);
  picture.bind();
  if (inspected && solution_) r.patch = solution_->read(*viewer_.inspection().pick);
  else r.patch.reset();
}

void RadiosityView::click(const Camera& camera, const Viewport& viewport, glm::ivec2 pixel) {
  ViewerState& state = viewer_.state();
  if (inspect(viewer_, camera, viewport, pixel)) {
    state.show_inspector = true;
    if (solution_) state_.patch = solution_->read(*viewer_.inspection().pick);
    return;
  }
  state_.patch.reset();
  state.note = trf("pixel ({}, {}): background", pixel.x, pixel.y);
}

void RadiosityView::panel() { radiosity_section(viewer_, state_); }

// The patch inspector in the corner away from the clicked point, the heat map's legend and the
// shooter's hemicube in others, and at shot 0 a hint saying how to start.
void RadiosityView::windows(const Viewport& viewport, WindowCorners& corners) {
  ViewerState& state = viewer_.state();
  RadiosityState& r = state_;
  if (r.status.built && r.status.shots == 0 && !r.drive.running && r.steps == 0) {
    draw_hint("radiosity hint", viewport, corners, viewer_.ui_scale(),
              {std::nullopt,
               {tr("radiosity at shot 0: only the emitters have light (slide 39 step 1)."),
                tr("Press Space to run the shooting, '.' for one shot.")}});
  }
  const Inspection& in = viewer_.inspection();
  if (in.pick && r.patch && state.show_inspector) {
    const glm::vec2 at = viewport.window_of(glm::ivec2(in.pick->x, in.pick->y));
    corners.place_away_from(at);
    draw_patch_inspector(*state.scene, *r.patch, state.show_inspector);
    draw_pick_cross(at, viewer_.ui_scale());
  }
  if (r.drive.heat_map) {
    corners.place(WindowCorners::bottom_left);
    draw_heat_map_legend_window(180.0f * viewer_.ui_scale());
  }
  r.status.item_view_min = r.status.item_view_max = glm::vec2(0.0f);
  if (r.drive.show_item_buffer) {
    corners.place(WindowCorners::top_right);
    draw_item_buffer_window(r, state.radiosity, 200.0f * viewer_.ui_scale());
  }
}

std::string RadiosityView::status() const {
  const RadiosityState& r = state_;
  if (!r.status.built) return {};
  // xgettext:no-c-format (a fmt string, where "% u" is not a printf directive)
  return trf("shot {}, {:.2f}% unshot{}", r.status.shots, 100.0 * r.status.unshot_fraction,
                     r.drive.running ? tr(", running") : r.status.done ? tr(", done") : tr(", paused"));
}

bool RadiosityView::busy() const {
  const RadiosityState& r = state_;
  return r.steps > 0 || r.stop_at > 0 || r.remesh;
}

bool RadiosityView::animating() const {
  const RadiosityState& r = state_;
  return r.drive.running || busy() || r.reset;
}

// Its frames may be paced while the loop runs at the default budget (a chosen budget or a
// number of shots a frame is what each frame shoots), with no single shots or rebuild asked for.
bool RadiosityView::paced() const {
  const RadiosityState& r = state_;
  return solution_ && r.drive.by_time && !r.drive.budget_chosen && r.steps == 0 && !r.reset && !r.remesh &&
         solution_->shoots_between_frames(r);
}

void RadiosityView::between_frames() {
  if (paced()) solution_->shoot_between_frames(state_);
}

// Left with no pane showing the solution, the loop pauses and its requests go: it shoots only
// when drawn, so it would say "running" while nothing shoots, and run on when shown again.
void RadiosityView::hidden() {
  for (const ModelView* pane : viewer_.pane_views())
    if (pane == this || std::find(readers_.begin(), readers_.end(), pane) != readers_.end()) return;
  state_.drive.running = false;
  state_.steps = state_.stop_at = 0;
}

bool RadiosityView::holds(std::string_view condition) const {
  return condition == "radiosity-done" && state_.status.built && state_.status.done;
}

void RadiosityView::dump_state(nlohmann::json& out) const {
  out["radiosity_drive"] = {{"running", state_.drive.running}, {"heat_map", state_.drive.heat_map}};
}

}  // namespace luz::app

// ---- its script verbs ----------------------------------------------------------------------------
namespace luz::app {
namespace {

RadiosityView& radiosity_of(ViewerServices& viewer) { return static_cast<RadiosityView&>(viewer.view("radiosity")); }

// A switch's field in the view's drive or in the options.
bool& field(const RadiositySwitch& sw, RadiosityState& r, RadiosityOptions& o) {
  return sw.drive ? r.drive.*sw.drive : o.*sw.option;
}

// Whether a pane shows model 5 itself (the hybrid's radiosity is not its loop's keys' place).
bool radiosity_shown(ViewerServices& viewer) {
  for (ModelView* pane : viewer.pane_views())
    if (dynamic_cast<RadiosityView*>(pane)) return true;
  return false;
}

// `radiosity WHAT [VALUE]`: the loop's controls, the mesh and the display switches of model 5.
std::string check_radiosity(const ScriptCommand& c) {
  const auto& a = c.args;
  if (a.empty())
    return "`radiosity` takes run, pause, reset, step N, patch-size M, hemicube N, meshing M, form-factors F, "
           "budget MS or a switch";
  const std::string& what = a[0];
  if (what == "run" || what == "pause" || what == "run-pause" || what == "shot" || what == "reset")
    return a.size() == 1 ? "" : fmt::format("`radiosity {}` takes no value", what);
  if (a.size() != 2) return fmt::format("`radiosity {}` takes one value", what);
  const std::string& value = a[1];
  if (what == "step") return is_int(value) && std::stoi(value) >= 1 ? "" : "`radiosity step N` takes N >= 1";
  if (what == "budget") return is_number(value) && std::stof(value) > 0.0f ? "" : "`radiosity budget MS` takes milliseconds > 0";
  // The options table's rows of the mesh and its form factors (slide 40): the row's check, as
  // --patch-size, --meshing, ... have it.
  if (is_radiosity_mesh_setting(what))
    return parse_value(*find_row(radiosity_table(), what), value)
               ? ""
               : fmt::format("`radiosity {}` takes {}", what, accepted_text(*find_row(radiosity_table(), what)));
  if (what == "patches")
    return value == "outlined" || value == "gouraud" || value == "toggle"
               ? "" : "`radiosity patches` takes outlined, gouraud or toggle";
  if (const RadiositySwitch* sw = find_radiosity_switch(what))
    return value == "on" || value == "off" || value == "toggle" ? "" : fmt::format("`radiosity {}` takes on, off or toggle", sw->name);
  return fmt::format("unknown radiosity setting \"{}\" (run, pause, run-pause, shot, reset, step, patch-size, hemicube, "
                     "meshing, form-factors, budget, patches, heat-map, outlines, flat-patches, ambient-estimate, "
                     "shooter, item-buffer, rotation)", what);
}

bool run_radiosity(ViewerServices& viewer, const ScriptCommand& c, std::string&) {
  const auto& a = c.args;
  ViewerState& state = viewer.state();
  RadiosityState& r = radiosity_of(viewer).state();
  RadiosityOptions& options = state.radiosity;
  if (a[0] == "run") {
    r.drive.running = true;
  } else if (a[0] == "pause") {
    r.drive.running = false;
  } else if (a[0] == "run-pause" || a[0] == "shot") {
    // Space and '.': the loop's keys, which show model 5 where no pane shows it.
    if (a[0] == "run-pause") {
      r.drive.running = !r.drive.running;
      state.note = r.drive.running ? tr("radiosity: running") : tr("radiosity: paused");
    } else {
      r.drive.running = false;
      r.steps += 1;
      state.note = tr("radiosity: one shot");
    }
    if (!radiosity_shown(viewer)) viewer.set_model(*find_model("radiosity"));
  } else if (a[0] == "reset") {
    r.reset = true;
    state.note = tr("radiosity: reset (step 1: unshot = E)");
  } else if (a[0] == "step") {
    r.drive.running = false;
    r.steps += std::stoi(a[1]);
  } else if (is_radiosity_mesh_setting(a[0])) {
    const OptionRow& row = *find_row(radiosity_table(), a[0]);
    row.set(&options, *parse_value(row, a[1]));
    r.remesh = true;  // a solution on another mesh, or by other form factors, starts over
  } else if (a[0] == "budget") {
    r.drive.by_time = true;
    r.drive.budget_ms = std::stof(a[1]);
    r.drive.budget_chosen = true;
  } else if (a[0] == "patches") {  // L: flat patches with their outlines, or Gouraud
    RadiosityOptions& o = options;
    o.flat_patches = o.outlines = a[1] == "toggle" ? !(o.flat_patches && o.outlines) : a[1] == "outlined";
    state.note = o.outlines ? tr("radiosity: flat patches, outlined") : tr("radiosity: Gouraud");
  } else {
    const RadiositySwitch& sw = *find_radiosity_switch(a[0]);  // checked when the script was read
    bool& on = field(sw, r, options);
    on = a[1] == "toggle" ? !on : a[1] == "on";
    if (sw.note) state.note = fmt::format("{} {}", tr(sw.note), on ? tr("on") : tr("off"));
  }
  return true;
}

std::string check_shots(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return is_int(c.args[0]) && std::stoi(c.args[0]) >= 1 ? "" : "`wait-shots N` takes a number of shots >= 1";
}

bool run_wait_shots(ViewerServices& viewer, const ScriptCommand& c, std::string& error) {
  const std::string& model = viewer.model().name;
  if (model != std::string("radiosity") && model != std::string("hybrid")) {
    error = "`wait-shots` runs the radiosity solver: choose it first (`model radiosity` or `model hybrid`)";
    return false;
  }
  RadiosityState& r = radiosity_of(viewer).state();
  r.stop_at = std::stoi(c.args[0]);
  r.drive.running = true;
  return true;
}

bool dump(const std::string& path, const nlohmann::json& json, std::string& error) {
  return write_json(path, json, "the radiosity values", error);
}

bool run_dump_patch(ViewerServices& viewer, const ScriptCommand& c, std::string& error) {
  const RadiosityState& r = radiosity_of(viewer).state();
  if (!r.patch) {
    error = "no patch is inspected: click a surface in the radiosity model first";
    return false;
  }
  return dump(c.args[0], to_json(*r.patch), error);
}

bool run_dump_radiosity(ViewerServices& viewer, const ScriptCommand& c, std::string& error) {
  // The status is the view's, even before it is shown.
  return dump(c.args[0], to_json(radiosity_of(viewer).state(), viewer.state().radiosity), error);
}

constexpr ScriptVerb verbs[] = {
    {"radiosity", "radiosity run|pause|run-pause|shot|reset|step N|patch-size M|hemicube N|budget MS|patches outlined|gouraud|toggle|SWITCH on|off|toggle", check_radiosity,
     run_radiosity, true},
    {"wait-shots", "wait-shots N", check_shots, run_wait_shots, true},
    {"dump-patch", "dump-patch FILE.json", check_json_file, run_dump_patch, true},
    {"dump-radiosity", "dump-radiosity FILE.json", check_json_file, run_dump_radiosity, true},
};

// Space runs or pauses, '.' shoots once, 0 starts over (slide 39 step 1); U shows the Unshot
// heat map, L the patches' outLines, Shift+A the Ambient estimate (beside A's ambient term).
constexpr KeyBinding keys[] = {
    {"space", N_("Space"), "radiosity run-pause", N_("radiosity: run / pause the shooting")},
    {".", nullptr, "radiosity shot", N_("radiosity: one shot")},
    {"0", nullptr, "radiosity reset", N_("radiosity: reset (shot 0: unshot = E)")},
    {"U", nullptr, "radiosity heat-map toggle", N_("radiosity: heat map of the unshot power on / off")},
    {"L", nullptr, "radiosity patches toggle", N_("radiosity: flat patches with outlines / Gouraud")},
    {"Shift+A", N_("Shift+A"), "radiosity ambient-estimate toggle", N_("radiosity: ambient estimate on / off")},
};

}  // namespace

std::span<const ScriptVerb> radiosity_verbs() { return verbs; }
std::span<const KeyBinding> radiosity_keys() { return keys; }

}  // namespace luz::app
