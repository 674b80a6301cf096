#include "app/models/whitted/whitted_view.h"

#include <imgui.h>

#include "app/common/i18n.h"
#include "app/models/whitted/render_whitted.h"
#include "local/local_renderer.h"

namespace luz::app {

// The local model with the lecture's Phong shading, whatever flat / Gouraud was last used.
void WhittedView::draw_untraced(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) {
  LocalOptions raster = viewer_.state().local;
  raster.shading = Shading::phong;
  picture.bind();
  viewer_.local_renderer().draw(camera, viewport.pixels.x, viewport.pixels.y, raster);
}

rt::WhittedOptions WhittedView::current_options() const {
  const ViewerState& state = viewer_.state();
  return tracer_options(state.whitted, state.local);
}

void WhittedView::panel() {
  ImGui::TextDisabled("%s", tr("rays from the eye, traced on the CPU (Embree, TBB)"));
  ImGui::TextWrapped("%s", tr("I = Ia·ka + Σᵢ Sᵢ ILᵢ·[kd·cos θ + ks·cosⁿ α] + kr·Ir + kt·It"));
  traced_section(viewer_.state(), *this);
}

}  // namespace luz::app
