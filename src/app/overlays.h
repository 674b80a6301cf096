#pragma once
// The small windows of the viewer besides the panel and the inspector: the status line, the
// list of keys (F1), Whitted's hint and progress, and the error of a scene that did not load.
#include "app/viewer_state.h"

namespace luz::app {

// Model, frame time, triangles, lights, camera and the latest message, in one line at `top`.
void draw_status_line(const ViewerState& state, float top, float width, float height);

// The shortcut table (shortcuts.h) and the mouse gestures, centred on (x, y).
void draw_help(bool& open, float x, float y);

// Whitted's model until its trace is done, at the top centre (x, y) of the picture: the hint to
// trace the raster view, or the progress bar of the trace running.
void draw_trace_hint(const ViewerState& state, float x, float y);

// Radiosity: the last shooter's hemicube (its five item-buffer faces, unfolded, a false colour
// per patch ID), `side` window units across, in a window whose top-right corner is (right, top)
// (radiosity_panel.cpp).
void draw_item_buffer_window(ViewerState& state, float right, float top, float side);

// state.error in a red-titled window centred on (x, y); its OK button clears the error.
void draw_load_error(ViewerState& state, float x, float y, float max_width);

}  // namespace luz::app
