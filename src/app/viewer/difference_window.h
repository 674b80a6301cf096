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

#include "app/viewer/difference_state.h"
#include "app/viewer/model_view.h"
#include "core/image.h"
#include "core/image_compare.h"

namespace luz::app {

struct ModelEntry;

// After `compared` (the model whose view drew into `picture`) was drawn: does nothing while the
// difference is off (and stops the reference when it was just turned off, unless the path
// model is shown in a pane of its own: `reference_in_a_pane`).
void draw_difference(ViewerServices& viewer, const ModelEntry& compared, const Camera& camera,
                     const Viewport& viewport, gl::Framebuffer& picture, bool reference_in_a_pane);

// The figures of a comparison (image_compare.h) of two width x height pictures, with the heat
// map's range (kHeatmapRange, as `luz compare` draws it) and without the model's name and the reference's samples.
DifferenceFigures difference_figures(const ImageComparison& comparison, int width, int height);

// The legend over the picture: the colour bar with its scale, and the figures.
void difference_windows(const ViewerState& state, const Viewport& viewport, WindowCorners& corners);

// The panel's switch (under the model's radio buttons) and the mean relative error.
void difference_panel(ViewerState& state);

// The script's `difference on|off` and `dump-difference FILE.json` (the path model's registry
// entry lists them).
std::string check_difference(const ScriptCommand& command);
bool run_difference(ViewerServices& viewer, const ScriptCommand& command, std::string& error);
bool run_dump_difference(ViewerServices& viewer, const ScriptCommand& command, std::string& error);

}  // namespace luz::app
