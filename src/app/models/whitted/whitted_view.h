#pragma once
// Whitted's model (slides 20-27) in the viewer: the raster (Phong) view until Enter, then the
// trace of that view tile by tile (traced_view.h).
#include "app/models/whitted/traced_view.h"
#include "app/common/i18n.h"

namespace luz::app {

class WhittedView final : public TracedView {
public:
  using TracedView::TracedView;
  void panel() override;
  bool hybrid() const override { return false; }

protected:
  void draw_untraced(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) override;
  std::optional<rt::WhittedOptions> options_for_trace(std::string&) override { return current_options(); }
  rt::WhittedOptions current_options() const override;
  std::string hint() const override {
    return tr("Whitted: the raster (Phong) view. Press Enter / click Render to trace this view");
  }
};

}  // namespace luz::app
