#pragma once
// The Dear ImGui panel: the models' radio buttons and the shown model's own section (its
// ModelView's panel()), the lights, the material of the clicked object and the scene-wide
// settings. It edits the ViewerState in place.
#include <span>

#include <imgui.h>

#include "app/viewer/model_view.h"
#include "app/viewer/viewer_state.h"
#include "app/viewer/widget_registry.h"  // name_widget() after each labelled widget

namespace luz::app {

// Draws the panel as a fixed window at the left of the window, `width` x `height` window units.
// `difference`: its switch sits under the models' radio buttons.
void draw_panel(ViewerState& state, ModelView& shown, DifferenceView& difference, float width, float height);

// A button of the panel that a key has too: the line both run (shortcuts.cpp's, the key's), the
// widget's name (name_widget, in English: "reload [R]"). Pressed, a button queues its line in
// state.panel_lines; the model's radio buttons run `model NAME`, the camera list `camera N` and
// the side-by-side buttons `panes ...` the same way.
struct PanelButton {
  const char* widget;
  const char* line;
};
std::span<const PanelButton> panel_buttons();

// The local models' section: where the formula is evaluated, the formula, the term switches
// and slide 19's other possibilities.
void local_section(ViewerState& state);

// A remark in the disabled colour, wrapped at the panel's edge (never cut off).
void dim_text(const char* format, ...) IM_FMTARGS(1);

// The formula of the local models with each term coloured, or greyed when it is off.
void draw_local_formula(const LocalOptions& options, const Scene& scene);

}  // namespace luz::app
