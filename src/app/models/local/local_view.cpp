#include "app/models/local/local_view.h"

#include <cmath>

#include <fmt/format.h>
#include <imgui.h>

#include "app/common/i18n.h"
#include "app/viewer/overlays.h"
#include "app/viewer/panel.h"
#include "gl/functions.h"
#include "local/local_renderer.h"

namespace luz::app {

bool refresh_inspection(ViewerServices& viewer, const Camera& camera, const Viewport& viewport) {
  Inspection& in = viewer.inspection();
  if (!in.pick) return false;
  if (in.picked_size == viewport.pixels && in.picked_with.to_world == camera.to_world) return true;
  const glm::ivec2 pixel = glm::min(glm::ivec2(in.pick->x, in.pick->y), viewport.pixels - 1);
  return inspect(viewer, camera, viewport, pixel);
}

bool inspect(ViewerServices& viewer, const Camera& camera, const Viewport& viewport, glm::ivec2 pixel) {
  Inspection& in = viewer.inspection();
  ViewerState& state = viewer.state();
  in.pick = viewer.picker().pick(camera, viewport.pixels.x, viewport.pixels.y, pixel.x, pixel.y);
  in.picked_with = camera;
  in.picked_size = viewport.pixels;
  if (!in.pick) return false;
  // The panel's Material section follows the object the inspector shows.
  state.selected_material = state.scene->meshes[size_t(in.pick->mesh)].material;
  return true;
}

void draw_pick_cross(glm::vec2 at, float ui_scale) {
  const float r = 7.0f * ui_scale;
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  draw->AddLine(ImVec2(at.x - r, at.y), ImVec2(at.x + r, at.y), IM_COL32(255, 60, 200, 255), 2.0f);
  draw->AddLine(ImVec2(at.x, at.y - r), ImVec2(at.x, at.y + r), IM_COL32(255, 60, 200, 255), 2.0f);
}

void LocalView::draw(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) {
  ViewerState& state = viewer_.state();
  state.local.shading = shading_;
  LocalRenderer& renderer = viewer_.local_renderer();
  // The displayed values beside the radiance when the picture has room for them and the
  // window asks (display_copy: off to compare with the display pass).
  const bool display = picture.display_texture() != 0 && state.display_copy;
  if (display) picture.bind_with_display();
  else picture.bind();
  renderer.draw(camera, viewport.pixels.x, viewport.pixels.y, state.local,
                display ? std::optional<float>(std::exp2(state.exposure)) : std::nullopt);
  drew_display_ = display && renderer.drew_display();
  const bool inspected = refresh_inspection(viewer_, camera, viewport);
  picture.bind();  // the picker drew into its own framebuffer
  if (!inspected) {
    reading_.reset();
    return;
  }
  // The shadow maps and the reflection map the picture was drawn with, read texel by texel.
  const Pick& pick = *viewer_.inspection().pick;
  const std::optional<ShadowLookup> shadows = renderer.shadow_lookup();
  DrawnLookups lookups;
  lookups.shadows = shadows ? &*shadows : nullptr;
  lookups.reflection = renderer.reflection_lookup(pick.mesh);
  reading_ = read_terms(*state.scene, renderer.area_lights(), pick, state.local, lookups);
  float rgba[4] = {};
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(pick.x, viewport.pixels.y - 1 - pick.y, 1, 1, GL_RGBA, GL_FLOAT, rgba);
  reading_->gl_pixel = Rgb(rgba[0], rgba[1], rgba[2]);
}

// The inspector, when shown, reads the radiance GL drew at its pixel, and a transparent mesh
// blends over radiance: both need the picture.
bool LocalView::draw_into_window(const Camera& camera, const Viewport& viewport, bool window_unseen) {
  ViewerState& state = viewer_.state();
  LocalRenderer& renderer = viewer_.local_renderer();
  state.local.shading = shading_;
  if ((viewer_.inspection().pick && state.show_inspector) || renderer.blends(state.local)) return false;
  if (!gl::bind_window_for_display()) return false;
  renderer.draw_display(camera, viewport.gl_origin, viewport.pixels, state.local, std::exp2(state.exposure),
                        window_unseen);
  gl::bind_window();
  drew_display_ = false;
  reading_.reset();
  return true;
}

void LocalView::click(const Camera& camera, const Viewport& viewport, glm::ivec2 pixel) {
  ViewerState& state = viewer_.state();
  if (inspect(viewer_, camera, viewport, pixel)) {
    state.show_inspector = true;
    return;
  }
  reading_.reset();
  state.note = trf("pixel ({}, {}): background", pixel.x, pixel.y);
}

// Side by side, each local pane sets the shading as it draws: the panel speaks of this one's.
void LocalView::panel() {
  viewer_.state().local.shading = shading_;
  local_section(viewer_.state());
}

void LocalView::windows(const Viewport& viewport, WindowCorners& corners) {
  ViewerState& state = viewer_.state();
  const Inspection& in = viewer_.inspection();
  if (!in.pick || !reading_ || !state.show_inspector) return;
  const glm::vec2 at = viewport.window_of(glm::ivec2(in.pick->x, in.pick->y));
  corners.place_away_from(at);
  draw_inspector(*state.scene, *reading_, state.show_inspector);
  draw_pick_cross(at, viewer_.ui_scale());
}

}  // namespace luz::app
