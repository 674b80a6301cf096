#pragma once
// `luz render SCENE --model flat,gouraud,phong,whitted --out grid.png`: slide 44's "Realismo:
// combinación de técnicas" on one sheet for a handout. 2 panes side by side or 4 in a 2x2 grid,
// each the picture `luz render --model M --size WxH` makes of the same scene and camera, with the
// model's name in the current language in a box at its top-left corner.
#include <string>
#include <vector>

#include "app/common/label_text.h"
#include "app/common/model_registry.h"  // model_label, each pane's label
#include "app/cli/render_command.h"
#include "core/camera.h"
#include "core/scene.h"
#include "core/image.h"

namespace luz::app {

// A comma in --model asks for the grid.
bool is_model_list(const std::string& text);

// --model's check: "" when the text is one model or a list parse_model_list takes, else why not.
std::string model_option_problem(const std::string& text);

// "flat,gouraud" -> {"flat", "gouraud"}: 2 or 4 models of the registry. Throws luz::Error (usage) naming the
// offending name or count.
std::vector<std::string> parse_model_list(const std::string& text);

// How panes tile the sheet: 2 -> 2 x 1, 4 -> 2 x 2.
struct GridLayout {
  int columns = 1;
  int rows = 1;
};
GridLayout grid_layout(size_t panes);

// The pane's size when --size is not given: 400 pixels high at the camera's aspect ratio, so that
// four panes make a sheet of about 1070 x 800.
inline constexpr int kDefaultPaneHeight = 400;

// Where a pane's label box lies (top-left corner; everything else is the untouched picture).
struct LabelBox {
  int x = 0, y = 0, width = 0, height = 0;
  bool contains(int px, int py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};
float label_pixel_height(int pane_height);
LabelBox label_box(const LabelFont& font, const std::string& label, int pane_height);

// Darkens the box and writes the label in white as the PNG will show it at `exposure` EV.
void draw_label(Image& pane, const LabelFont& font, const std::string& label, float exposure);

// The sheet of `models` (1, 2 or 4; one model: its picture alone, without a label). With
// --size (settings.width, height) the sheet is that size and each pane a column's and a row's
// share of it, the pixels a division leaves over black at the right and bottom edge, as the
// window's panes; without, each pane is kDefaultPaneHeight high at the camera's aspect. The
// radiosity and hybrid panes share one solve unless settings bring a solution already.
struct Sheet {
  Image image;
  float exposure = 0.0f;  // chosen_exposure's, the labels written for it
  int pane_width = 0, pane_height = 0;
  GridLayout layout;
};
Sheet render_sheet(const RenderSettings& settings, const Scene& scene, const Camera& camera,
                   const std::vector<std::string>& models);

// Renders every pane, assembles and writes the sheet; returns the exit code like run_render.
int run_render_grid(const RenderSettings& settings);

}  // namespace luz::app
