#pragma once
// Radiosity's part of the panel and its windows (radiosity_panel.cpp), drawn by its view from
// the state it owns and the viewer's radiosity options.
#include "app/models/radiosity/radiosity_state.h"
#include "app/viewer/model_view.h"
#include "radiosity/radiosity_options.h"

namespace luz::app {

// The panel's section: run, pause, one shot, reset; counters and the plot of unshot power
// against shots; the time budget, stopping rule, mesh, hemicube and display; the button of
// slide 36's window, which runs J's line.
void radiosity_section(ViewerServices& viewer, RadiosityState& r);

// The last shooter's hemicube (its five item-buffer faces, unfolded, a false colour per patch
// ID), `side` window units across, in a window placed by the caller (WindowCorners).
void draw_item_buffer_window(RadiosityState& r, const RadiosityOptions& options, float side);
// The heat map's fixed scale, `width` window units wide, in a window placed by the caller, while
// the heat map is shown: the class reads what its colours mean beside the picture.
void draw_heat_map_legend_window(float width);

}  // namespace luz::app
