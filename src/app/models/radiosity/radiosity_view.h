#pragma once
// Progressive radiosity (slides 29-40) in the viewer: the solver (RadiositySession) stepped on the
// GL thread within a per-frame budget while the model is shown, the solution drawn as it
// spreads, the clicked patch in its inspector and the shooter's hemicube in a window. The
// hybrid (hybrid_view.h) reads this view's solution.
#include <functional>
#include <memory>
#include <span>
#include <optional>
#include <vector>

#include "app/viewer/model_view.h"
#include "app/models/radiosity/radiosity_session.h"

namespace luz::app {

class RadiosityView final : public ModelView {
public:
  explicit RadiosityView(ViewerServices& viewer) : viewer_(viewer) {}

  void scene_changed() override {
    drop();
    state_.patch.reset();
  }
  void emitters_changed() override { drop(); }  // the patches' E come from the scene's Le when meshed
  void hidden() override;  // the loop pauses where no pane shows its solution
  void draw(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) override;
  void click(const Camera& camera, const Viewport& viewport, glm::ivec2 pixel) override;
  void panel() override;
  void windows(const Viewport& viewport, WindowCorners& corners) override;
  std::string status() const override;
  bool busy() const override;
  bool animating() const override;
  bool paced() const override;
  void between_frames() override;  // the running loop's shots
  bool shows_the_light() const override { return solution_ && solution_->solver().shots() > 0; }
  bool holds(std::string_view condition) const override;  // radiosity-done
  void dump_state(nlohmann::json& out) const override;    // radiosity_drive: running, heat_map

  // The loop, its requests and what the panel shows of the solver: the keys, the script, the
  // panel and the hybrid change and read it here (the options are the viewer's settings).
  RadiosityState& state() { return state_; }
  const RadiosityState& state() const { return state_; }

  // What model 5 displays, and what the hybrid reads (B/pi only: no heat map, no shooter).
  struct Display {
    bool heat_map = false;
    bool shooter = false;
  };
  // This frame's shots, then the solution into the bound `picture`; meshes and starts the
  // solver first when there is none (or a remesh was asked for). False when the scene cannot
  // be meshed (the picture is then black and the note says why).
  bool step_and_draw(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture, Display display);

  // The solver of the solution shown; nullptr before the first step_and_draw (or after a drop).
  const RadiositySession* solution() const { return solution_.get(); }
  // Called before the solution goes (a remesh, an edited Le, a new scene): whoever reads it
  // (the hybrid's trace) lets go of it first.
  void on_drop(std::function<void()> listener) { drop_listeners_.push_back(std::move(listener)); }
  // `reader` shows this view's solution too (the hybrid): while a pane shows either, the loop
  // goes on.
  void shown_through(const ModelView& reader) { readers_.push_back(&reader); }
  // The solution goes now (the emitters were edited: the patches' E are read when meshing).
  void drop();

private:
  ViewerServices& viewer_;
  RadiosityState state_;
  std::unique_ptr<RadiositySession> solution_;
  std::vector<std::function<void()>> drop_listeners_;
  std::vector<const ModelView*> readers_;  // compared with the panes, never read
};

// Its script verbs: radiosity ..., wait-shots, dump-patch, dump-radiosity.
std::span<const ScriptVerb> radiosity_verbs();
// Its keys (key_binding.h): Space, '.', 0, U, L, Shift+A, each bound to a `radiosity` line.
std::span<const KeyBinding> radiosity_keys();

}  // namespace luz::app
