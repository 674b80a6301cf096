#pragma once
// The Dear ImGui panel: the model and its formula (disabled terms greyed), its switches, the
// lights, the material of the clicked object and the scene-wide settings. It edits the
// ViewerState in place. Each model draws its own section (see `models` in panel.cpp): a new
// model adds one function.
#include "app/viewer_state.h"

namespace luz::app {

// Draws the panel as a fixed window at the left of the window, `width` x `height` window units.
void draw_panel(ViewerState& state, float width, float height);

// Whitted's section (panel_whitted.cpp): Render, progress, counters, the tracer's switches and
// the clicked pixel's ray tree.
void whitted_section(ViewerState& state);

// The hybrid's section (panel_whitted.cpp): the radiosity solution it reads, then Whitted's.
void hybrid_section(ViewerState& state);

// Radiosity's section (radiosity_panel.cpp): run, pause, one shot, reset; counters and the plot
// of unshot power against shots; the time budget, stopping rule, mesh, hemicube and display.
void radiosity_section(ViewerState& state);

// The formula of the local models with each term coloured, or greyed when it is off.
void draw_local_formula(const LocalOptions& options, const Scene& scene);

}  // namespace luz::app
