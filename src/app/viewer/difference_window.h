#pragma once
// The difference view: what the model shown misses, against the path tracer's reference of the
// same camera (slide 14's equation solved by Monte Carlo). Where the picture would be, the
// signed relative difference (Y(model) - Y(reference)) / Y(reference) of every lit pixel as a
// diverging heat map (blue: the model is darker, white: equal, red: brighter, grey: unlit);
// beside it a legend with the scale and the figures `luz compare` prints for the same two
// pictures (core/image_compare.h: mean error, mean relative error over the lit pixels).
//
// Each frame, after the model's view drew its radiance into the picture:
//   - the path model (the registry's "path" view, which refines in the background) advances on
//     the same camera and viewport, so the reference is always of the view on screen;
//   - the picture is read back and compared with the reference's latest whole pass;
//   - the heat map replaces the picture's radiance, divided by 2^exposure so that the display
//     pass shows its colours as they are (a screenshot is then `luz compare --heatmap`'s map).
// It draws into whatever picture and viewport it is given: the whole picture, or the active pane
// of the side-by-side view (beside the model's neighbours, or beside the reference itself when
// the path model is another pane).
#include <span>
#include <string>

#include "app/viewer/model_view.h"
#include "core/image.h"
#include "core/image_compare.h"
#include "core/color.h"

namespace luz::app {

struct ModelEntry;

// One comparison of the picture shown against the path tracer's reference of the same view:
// image_compare.h's figures, which `luz compare A.exr B.exr` prints for the same two pictures.
struct DifferenceFigures {
  std::string model;               // the model compared
  int width = 0, height = 0;
  Rgb mean_error{0.0f};            // A - B per channel
  Rgb mean_absolute_error{0.0f};
  double rel_rmse = 0.0;
  double mean_relative_error = 0.0;  // over the lit pixels
  int lit_pixels = 0;
  float range = 1.0f;              // the heat map saturates at +-range (relative)
  int reference_spp = 0;
  double reference_noise = 0.0;    // the reference's own relative standard error
};

struct DifferenceState {
  bool on = false;         // the panel's checkbox, `difference on|off`
  bool valid = false;      // figures holds this frame's comparison (the reference has a pass)
  DifferenceFigures figures;
  std::string why;         // what shows instead when there is no comparison
  // Kept by the view each frame: the reference is still refining (the viewer keeps drawing),
  // the script waits for it (`wait-path` with the difference on), the reference runs for it.
  bool refining = false;
  bool waiting = false;
  bool running = false;
};


// The difference view owns its switch and figures: the panel's checkbox, the path model's verbs
// and the viewer's frame reach them through the viewer (ViewerServices::difference()), never
// through the ViewerState every model's view can write.
class DifferenceView {
public:
  const DifferenceState& state() const { return state_; }
  bool on() const { return state_.on; }
  void set_on(bool on) { state_.on = on; }
  // `wait-path` with the difference on: the script waits for the reference's target.
  void wait_for_reference() { state_.waiting = state_.on; }
  // Its reference still refines (the viewer keeps drawing), or a script waits for it.
  bool refining() const { return state_.on && state_.refining; }
  bool waiting() const { return state_.on && state_.waiting; }

  // After `compared` (the model whose view drew into `picture`) was drawn: does nothing while
  // the difference is off (and stops the reference when it was just turned off, unless the path
  // model is shown in a pane of its own: `reference_in_a_pane`).
  void draw(ViewerServices& viewer, const ModelEntry& compared, const Camera& camera, const Viewport& viewport,
            gl::Framebuffer& picture, bool reference_in_a_pane);
  // The legend over the picture: the colour bar with its scale, and the figures.
  void windows(const Viewport& viewport, WindowCorners& corners) const;
  // The panel's switch (under the model's radio buttons) and the mean relative error.
  void panel();

private:
  DifferenceState state_;
};

// The figures of a comparison (image_compare.h) of two width x height pictures, with the heat
// map's range (kHeatmapRange, as `luz compare` draws it) and without the model's name and the reference's samples.
DifferenceFigures difference_figures(const ImageComparison& comparison, int width, int height);

// The script's `difference on|off` and `dump-difference FILE.json` (the path model's registry
// entry lists them).
std::string check_difference(const ScriptCommand& command);
bool run_difference(ViewerServices& viewer, const ScriptCommand& command, std::string& error);
bool run_dump_difference(ViewerServices& viewer, const ScriptCommand& command, std::string& error);

}  // namespace luz::app
