#include "app/models/whitted/traced_view.h"

#include "app/script/key_binding.h"

#include <cmath>

#include <fmt/format.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/common/json_file.h"
#include "app/common/i18n.h"
#include "app/common/model_registry.h"
#include "app/viewer/overlays.h"
#include "gl/functions.h"

namespace luz::app {

TracedView::~TracedView() { tracer_.reset(); }

WhittedWorker& TracedView::tracer() {
  if (!tracer_) tracer_ = std::make_unique<WhittedWorker>(*viewer_.state().scene);
  return *tracer_;
}

void TracedView::set_diffuse_source(std::shared_ptr<const rt::DiffuseSource> source) {
  if (tracer_ || source) tracer().set_diffuse_source(std::move(source));
}

void TracedView::scene_changed() {
  tracer_.reset();  // cancels a trace; the tree below belongs to the old scene too
  ray_tree_.reset();
  picked_.reset();
  if (tree_drawing_) tree_drawing_->clear();
  progress_ = TraceProgress{};
}

bool TracedView::cancel_trace() { return tracer_ && tracer_->cancel(); }

// Its tiles can wait for the next paced frame; a request, or the trace's end, cannot.
bool TracedView::paced() const {
  return !requests.trace && !requests.cancel && !requests.clear_tree && tracer_ && tracer_->tracing_on_its_thread();
}

Fingerprint TracedView::fingerprint(const Camera& camera, glm::ivec2 size) const {
  return {camera.to_world, camera.yfov, size.x, size.y, current_options(), editable_values(*viewer_.state().scene)};
}

// A trace asked for (Enter, `trace`, a lesson's step) is of the view, whatever the room the
// window gives its picture: a resize, the panel shown or hidden, or a lesson's caption settling
// over the first frames of a step (in the page, the canvas fitted to the page too) traces it
// again at the new size, as a path tracer's passes start again. Anything else the picture
// depends on (the camera, an option, the scene) is the user's move: back to the untraced view.
bool TracedView::drop_stale_trace(const Camera& camera, glm::ivec2 size) {
  if (!tracer_ || !tracer_->showing()) return false;
  const Fingerprint now = fingerprint(camera, size);
  if (tracer_->fingerprint() == now) return false;
  ViewerState& state = viewer_.state();
  const bool running = tracer_->cancel();
  if (now.resized_from(tracer_->fingerprint())) {
    requests.trace = true;  // started by this frame's draw, over the untraced picture at the new size
  } else {
    state.note = running ? tr("the view changed: trace cancelled, back to the untraced view")
                         : tr("the view changed: back to the untraced view (Enter traces it)");
  }
  return true;
}

void TracedView::draw(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) {
  ViewerState& state = viewer_.state();
  const glm::ivec2 size = viewport.pixels;
  if (requests.cancel) {
    requests.cancel = false;
    if (cancel_trace()) state.note = tr("trace cancelled: back to the untraced view");
  }
  if (requests.clear_tree) {
    requests.clear_tree = false;
    ray_tree_.reset();
    picked_.reset();
    if (tree_drawing_) tree_drawing_->clear();
  }
  if (requests.trace) cancel_trace();  // a fresh untraced picture under the new trace
  if (must_cancel()) cancel_trace();
  drop_stale_trace(camera, size);

  if (!tracer_ || !tracer_->showing()) draw_untraced(camera, viewport, picture);
  if (requests.trace) {
    std::string why;
    if (const std::optional<rt::WhittedOptions> options = options_for_trace(why)) {
      requests.trace = false;
      tracer().start(*state.scene, camera, size.x, size.y, *options, picture, requests.held);
      requests.held = false;
      state.note = trf("tracing {}x{}", size.x, size.y);
    } else if (!why.empty()) {  // it cannot start at all
      requests.trace = false;
      state.note = why;
    }
  }
  if (tracer_ && tracer_->showing()) {
    const TracePhase before = tracer_->phase();
    tracer_->update();
    if (before == TracePhase::tracing && tracer_->phase() == TracePhase::done)
      state.note = trf("traced in {:.2f} s", tracer_->seconds());
    // The traced picture's colour over the picture; its depth stays the untraced one's of this
    // very view (the trace is cancelled when the view changes), which the ray tree is tested against.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, tracer_->picture().id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, picture.id());
    glBlitFramebuffer(0, 0, size.x, size.y, 0, 0, size.x, size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    picture.bind();
  }
  if (ray_tree_ && picked_ &&
      (picked_->options != current_options() || picked_->scene != editable_values(*state.scene))) {
    const PickedPixel picked = *picked_;
    std::string why;
    pick_tree(picked.camera, picked.size, picked.pixel, why);  // else again on the next frame
    picture.bind();
  }
  if (ray_tree_ && tree_drawing_)
    tree_drawing_->draw(camera, *state.scene, size.x, size.y, std::exp2(state.exposure),
                        viewport.scale.y);

  TraceProgress& t = progress_;
  if (tracer_) {
    t.phase = tracer_->phase();
    t.cancelled = tracer_->cancelled();
    t.done = tracer_->tiles_done();
    t.total = tracer_->tiles_total();
    t.seconds = tracer_->seconds();
    t.counters = tracer_->counters();
  } else {
    t = TraceProgress{};
  }
}

// Slide 24: the clicked pixel's ray tree, traced here on the GL thread (a few dozen rays), listed
// in the panel and drawn over the picture until another click, X, or a new scene.
void TracedView::click(const Camera& camera, const Viewport& viewport, glm::ivec2 pixel) {
  viewer_.inspection().pick.reset();  // the local model's inspector is not Whitted's
  // An edit not seen yet by the frame: the trace must not read the old scene.
  drop_stale_trace(camera, viewport.pixels);
  ViewerState& state = viewer_.state();
  std::string why;
  if (!pick_tree(camera, viewport.pixels, pixel, why)) {
    state.note = why;
    return;
  }
  const rt::RayTree& tree = *ray_tree_;
  if (!tree.nodes.empty() && tree.nodes[0].hit)
    for (const Mesh& mesh : state.scene->meshes)
      if (mesh.name == tree.nodes[0].mesh) state.selected_material = mesh.material;
  state.note = trnf("ray tree of pixel ({}, {}): {} ray", "ray tree of pixel ({}, {}): {} rays", tree.nodes.size(),
                    pixel.x, pixel.y, tree.nodes.size());
}

bool TracedView::pick_tree(const Camera& camera, glm::ivec2 size, glm::ivec2 pixel, std::string& why) {
  const ViewerState& state = viewer_.state();
  const std::optional<rt::WhittedOptions> options = options_for_trace(why);
  if (!options) return false;
  rt::RayTree tree = tracer().trace_pixel(*state.scene, camera, size.x, size.y, pixel.x, pixel.y, *options);
  if (!tree_drawing_) tree_drawing_ = std::make_unique<RayTreeDrawing>();
  tree_drawing_->set(tree, *state.scene);
  ray_tree_ = std::move(tree);
  picked_ = PickedPixel{camera, size, pixel, current_options(), editable_values(*state.scene)};
  return true;
}

std::string TracedView::status() const {
  const TraceProgress& t = progress_;
  if (t.phase == TracePhase::raster) return hybrid() ? tr("(radiosity picture)") : tr("(raster view)");
  if (t.phase == TracePhase::tracing) return trf("tracing {}%", t.total > 0 ? 100 * t.done / t.total : 0);
  return trf("traced: {:.2f} s, {:.2f} Mrays/s", t.counters.seconds, t.counters.rays_per_second() / 1e6);
}

void TracedView::windows(const Viewport& viewport, WindowCorners& corners) {
  const TraceProgress& t = progress_;
  if (t.phase == TracePhase::done) return;
  HintText text;
  if (t.phase == TracePhase::tracing) {
    text.progress = t.total > 0 ? float(t.done) / float(t.total) : 0.0f;
    text.lines.push_back(trf("tracing {}/{} tiles, {:.1f} s  (Backspace or moving cancels)", t.done, t.total, t.seconds));
  } else {
    text.lines.push_back(hint());
  }
  draw_hint("trace hint", viewport, corners, viewer_.ui_scale(), text);
}

}  // namespace luz::app

// ---- the tracer's script verbs -------------------------------------------------------------------
namespace luz::app {
namespace {

// The traced panes shown (side by side, every one of them), or Whitted's, shown first in the
// active pane as Enter shows it.
std::vector<TracedView*> traced(ViewerServices& viewer) {
  std::vector<TracedView*> panes;
  for (ModelView* pane : viewer.pane_views())
    if (auto* t = dynamic_cast<TracedView*>(pane)) panes.push_back(t);
  if (panes.empty()) {
    viewer.set_model(*find_model("whitted"));
    panes.push_back(&static_cast<TracedView&>(viewer.shown()));
  }
  return panes;
}

std::string check_trace(const ScriptCommand& c) {
  if (auto e = check_count(c, 0, 1); !e.empty()) return e;
  return c.args.empty() || c.args[0] == "--no-wait" || c.args[0] == "--held"
             ? "" : fmt::format("unknown option \"{}\" (--no-wait, --held)", c.args[0]);
}

// Enter's, with --no-wait; without it the script waits for the end.
bool run_trace(ViewerServices& viewer, const ScriptCommand& c, std::string&) {
  viewer.state().note.clear();
  for (TracedView* pane : traced(viewer)) pane->trace(c.args.empty(), !c.args.empty() && c.args[0] == "--held");
  return true;
}

// Backspace and X: every traced pane shown cancels its trace, or lets go of its ray tree; no
// other model is shown for them.
bool run_cancel_trace(ViewerServices& viewer, const ScriptCommand&, std::string&) {
  viewer.state().note.clear();
  for (ModelView* pane : viewer.pane_views())
    if (auto* t = dynamic_cast<TracedView*>(pane)) t->requests.cancel = true;
  return true;
}

bool run_clear_ray_tree(ViewerServices& viewer, const ScriptCommand&, std::string&) {
  viewer.state().note.clear();
  for (ModelView* pane : viewer.pane_views())
    if (auto* t = dynamic_cast<TracedView*>(pane)) t->requests.clear_tree = true;
  return true;
}

std::string check_none(const ScriptCommand& c) { return check_count(c, 0, 0); }

bool run_wait_trace(ViewerServices& viewer, const ScriptCommand&, std::string&) {
  for (ModelView* pane : viewer.pane_views())
    if (auto* t = dynamic_cast<TracedView*>(pane)) t->wait_for_trace();
  return true;
}

bool run_dump_ray_tree(ViewerServices& viewer, const ScriptCommand& c, std::string& error) {
  auto* shown = dynamic_cast<TracedView*>(&viewer.shown());
  if (!shown || !shown->ray_tree()) {
    error = "there is no ray tree: click a pixel in the Whitted model first";
    return false;
  }
  return write_text(c.args[0], shown->ray_tree()->to_json() + '\n', "the ray tree", error);
}

bool run_dump_trace(ViewerServices& viewer, const ScriptCommand& c, std::string& error) {
  auto* shown = dynamic_cast<TracedView*>(&viewer.shown());
  const TraceProgress t = shown ? shown->progress() : TraceProgress{};
  nlohmann::json j;
  j["phase"] = t.phase == TracePhase::raster ? "raster" : t.phase == TracePhase::tracing ? "tracing" : "done";
  j["cancelled"] = t.cancelled;
  j["tiles"] = {t.done, t.total};
  j["seconds"] = t.seconds;
  for (int k = 0; k < rt::kRayKinds; ++k) j["rays"][rt::to_string(rt::RayKind(k))] = t.counters.rays[size_t(k)];
  j["intersection_tests"] = t.counters.intersection_tests;
  return write_json(c.args[0], j, "the trace's state", error);
}

constexpr ScriptVerb verbs[] = {
    {"trace", "trace [--no-wait|--held]", check_trace, run_trace, true},
    {"wait-trace", "wait-trace", check_none, run_wait_trace, true},
    {"cancel-trace", "cancel-trace", check_none, run_cancel_trace, false},
    {"clear-ray-tree", "clear-ray-tree", check_none, run_clear_ray_tree, false},
    {"dump-ray-tree", "dump-ray-tree FILE.json", check_json_file, run_dump_ray_tree, true},
    {"dump-trace", "dump-trace FILE.json", check_json_file, run_dump_trace, true},
};

// Enter traces (Esc stays quit, so Backspace cancels; any camera move cancels too), X crosses
// out the ray tree.
constexpr KeyBinding keys[] = {
    {"enter", N_("Enter"), "trace --no-wait", N_("Whitted / hybrid: trace this view, tile by tile")},
    {"backspace", N_("Backspace"), "cancel-trace",
     N_("Whitted / hybrid: cancel the trace (back to the raster / radiosity view)")},
    {"X", nullptr, "clear-ray-tree", N_("Whitted / hybrid: clear the ray tree")},
};

}  // namespace

std::span<const ScriptVerb> traced_verbs() { return verbs; }
std::span<const KeyBinding> traced_keys() { return keys; }

}  // namespace luz::app
