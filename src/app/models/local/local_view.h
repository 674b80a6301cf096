#pragma once
// Flat, Gouraud and Phong (slides 15-19) in the viewer: the scene through the LocalRenderer with
// the panel's LocalOptions, and the inspector on the clicked point: each term's value computed on
// the CPU beside the pixel GL drew.
#include <memory>
#include <optional>

#include "app/viewer/inspector.h"
#include "app/viewer/model_view.h"
#include "local/local_options.h"

namespace luz::app {

class LocalView final : public ModelView {
public:
  LocalView(ViewerServices& viewer, Shading shading) : viewer_(viewer), shading_(shading) {}

  void scene_changed() override { reading_.reset(); }
  void draw(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) override;
  bool drew_display() const override { return drew_display_; }
  bool draw_into_window(const Camera& camera, const Viewport& viewport, bool window_unseen) override;
  void click(const Camera& camera, const Viewport& viewport, glm::ivec2 pixel) override;
  void panel() override;
  void windows(const Viewport& viewport, WindowCorners& corners) override;

  const std::optional<InspectorReading>& reading() const { return reading_; }
  const InspectorReading* inspector_reading() const override { return reading_ ? &*reading_ : nullptr; }

private:
  ViewerServices& viewer_;
  Shading shading_;
  std::optional<InspectorReading> reading_;
  bool drew_display_ = false;
};

// Re-picks the inspected pixel when the camera or the picture's size changed since it was
// picked (the pixel now shows another point), and keeps the panel's Material section on the
// object the inspector shows. False when nothing is inspected (any more).
bool refresh_inspection(ViewerServices& viewer, const Camera& camera, const Viewport& viewport);

// Picks the surface under `pixel` into the viewer's inspection; false for the background.
bool inspect(ViewerServices& viewer, const Camera& camera, const Viewport& viewport, glm::ivec2 pixel);

// A cross on the inspected pixel, over the picture (never into it).
void draw_pick_cross(glm::vec2 at, float ui_scale);

}  // namespace luz::app
