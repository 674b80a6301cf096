#pragma once
// What Whitted's model and the hybrid share in the viewer: the untraced picture until a trace is
// asked for (Enter, the Render button, `trace`), then the traced tiles over it as they come from
// the worker (WhittedWorker), back to the untraced picture when anything the trace depends on
// changes; the ray tree of a clicked pixel (slide 24) drawn over either. The view that traces
// owns its trace: it cancels it when it is hidden, when the view changes and when the scene goes.
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "app/viewer/model_view.h"
#include "app/models/whitted/ray_tree_drawing.h"
#include "app/models/whitted/whitted_worker.h"
#include "raytracing/ray_tree.h"
#include "raytracing/whitted_options.h"

namespace luz::app {

// The panel's buttons and the keys ask; the view does it at its next frame.
struct TraceRequests {
  bool trace = false;
  bool cancel = false;
  bool clear_tree = false;
  bool held = false;  // the trace asked for keeps its tiles back until cancelled (`trace --held`)
};

class TracedView : public ModelView {
public:
  explicit TracedView(ViewerServices& viewer) : viewer_(viewer) {}
  ~TracedView() override;  // cancels and joins the trace before what it reads goes

  void scene_changed() override;
  // A trace asked for and not started yet goes too: it would start by itself whenever the view
  // is shown again (a lesson's step later).
  void hidden() override {
    cancel_trace();
    requests = {};
  }
  void draw(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) override;
  void click(const Camera& camera, const Viewport& viewport, glm::ivec2 pixel) override;
  void windows(const Viewport& viewport, WindowCorners& corners) override;
  std::string status() const override;
  bool busy() const override { return waiting_ && (requests.trace || progress_.phase == TracePhase::tracing); }
  bool animating() const override { return requests.trace || progress_.phase == TracePhase::tracing; }
  bool paced() const override;

  // The script's `trace` (wait: until the last tile; held: no tile lands until it is
  // cancelled, so a test's cancel always finds it running) and `wait-trace`.
  void trace(bool wait, bool held = false) {
    requests.trace = true;
    requests.held = held;
    waiting_ = wait;
  }
  void wait_for_trace() { waiting_ = true; }
  // Back to the untraced picture; true when a trace was running.
  bool cancel_trace();

  TraceRequests requests;
  const TraceProgress& progress() const { return progress_; }
  bool holds(std::string_view condition) const override {
    return condition == "trace-done" && progress_.phase == TracePhase::done;
  }
  const char* trace_state() const override {
    return progress_.phase == TracePhase::raster ? "raster" : progress_.phase == TracePhase::tracing ? "tracing" : "done";
  }
  const std::optional<rt::RayTree>& ray_tree() const { return ray_tree_; }
  virtual bool hybrid() const = 0;

protected:
  // The picture a trace starts from and that shows until then, into the bound `picture`.
  virtual void draw_untraced(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) = 0;
  // The tracer's options for this frame; nullopt while a trace cannot start yet (the hybrid
  // waits for its radiosity solution), `why` saying so.
  virtual std::optional<rt::WhittedOptions> options_for_trace(std::string& why) = 0;
  // The options the picture on screen depends on (what a trace would use now).
  virtual rt::WhittedOptions current_options() const = 0;
  // The solution a running trace reads is about to change (the hybrid's remesh): cancel first.
  virtual bool must_cancel() const { return false; }
  // A short hint over the picture while it is not traced.
  virtual std::string hint() const = 0;
  // The hybrid's diffuse part for the traces to come (nullptr: Whitted's).
  void set_diffuse_source(std::shared_ptr<const rt::DiffuseSource> source);
  // No trace is running or ending (a cancelled one ends on its own): what it reads may change.
  bool tracer_idle() { return !tracer_ || tracer_->idle(); }
  bool tracing() const { return tracer_ && tracer_->phase() == TracePhase::tracing; }

  ViewerServices& viewer_;

private:
  Fingerprint fingerprint(const Camera& camera, glm::ivec2 size) const;
  // The traced picture shown is no longer this view's: back to the untraced one, traced again
  // at once when only the picture's size changed. False when it still is.
  bool drop_stale_trace(const Camera& camera, glm::ivec2 size);
  WhittedWorker& tracer();
  // The pixel's ray tree, traced with the options and the scene as they are now; false (`why`
  // saying why, or empty while the hybrid's solver runs) when no trace can start yet.
  bool pick_tree(const Camera& camera, glm::ivec2 size, glm::ivec2 pixel, std::string& why);

  std::unique_ptr<WhittedWorker> tracer_;  // made when first needed (it builds Embree's BVH)
  std::unique_ptr<RayTreeDrawing> tree_drawing_;
  std::optional<rt::RayTree> ray_tree_;
  // What the tree shown was traced from: a switch or an edit traces the same pixel's tree again,
  // so that the list never shows shadow rays switched off or a depth no longer set.
  struct PickedPixel {
    Camera camera;
    glm::ivec2 size{0}, pixel{0};
    rt::WhittedOptions options;
    std::vector<float> scene;
  };
  std::optional<PickedPixel> picked_;
  TraceProgress progress_;
  bool waiting_ = false;  // the script waits for the trace's end
};

// The panel's part shared by Whitted and the hybrid (panel_whitted.cpp): Render, progress,
// counters, the ray tree and the tracer's switches.
void traced_section(ViewerState& state, TracedView& view);

// The tracer's script verbs (Whitted's registry entry): trace, wait-trace, dump-ray-tree,
// dump-trace; they act on the traced model shown, or show Whitted's.
std::span<const ScriptVerb> traced_verbs();
// Its keys (key_binding.h): Enter, Backspace and X, bound to trace --no-wait, cancel-trace and
// clear-ray-tree.
std::span<const KeyBinding> traced_keys();

}  // namespace luz::app
