#pragma once
// The hybrid (slides 41-43) in the viewer: the radiosity view's solution as the picture until
// Enter, then the tracer with that solution as the diffuse part of every hit. It composes the
// radiosity view (the same solver model 5 steps, resets and remeshes) and a trace of its own.
#include <memory>

#include "app/models/radiosity/radiosity_view.h"
#include "app/models/whitted/traced_view.h"
#include "hybrid/radiosity_diffuse.h"

namespace luz::app {

class HybridView final : public TracedView {
public:
  HybridView(ViewerServices& viewer, RadiosityView& radiosity);
  ~HybridView() override;

  void scene_changed() override;
  void hidden() override;  // its trace stops; radiosity's loop too where no pane shows it
  void panel() override;
  std::string status() const override;
  bool hybrid() const override { return true; }
  bool animating() const override { return TracedView::animating() || radiosity_.animating(); }
  bool paced() const override { return TracedView::paced() && !radiosity_.animating(); }
  bool busy() const override { return TracedView::busy() || radiosity_.busy(); }
  bool shows_the_light() const override { return radiosity_.shows_the_light(); }

protected:
  void draw_untraced(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) override;
  std::optional<rt::WhittedOptions> options_for_trace(std::string& why) override;
  rt::WhittedOptions current_options() const override;
  bool must_cancel() const override { return radiosity_.state().remesh; }
  std::string hint() const override;

private:
  RadiosityView& radiosity_;
  // radiosity_'s solution as the tracer reads it (it refers to radiosity_'s mesh); refreshed
  // only while no trace runs, and let go (after the trace is cancelled) when the solution goes.
  std::shared_ptr<hybrid::RadiosityDiffuse> diffuse_;  // shared with the trace that reads it
};

}  // namespace luz::app
