#pragma once
// Slide 44, "Realismo: combinación de técnicas", in the window: the picture split into panes,
// each a model's own view (model_view.h) of the same scene through the same camera, labelled
// with the model's name as `luz render --model a,b,c,d` labels its panes.
//
// - The panes tile the picture as the headless grid tiles its sheet (render_grid.h's
//   grid_layout): 2 side by side, 3 or 4 in a 2 x 2 grid. Three leave the bottom-right quarter
//   empty, so that every pane keeps the shape of the picture and the size four would have.
// - There is one camera: every pane draws with it, so an orbit, a pan, a zoom or a flight made
//   over any pane moves all of them.
// - One pane is the active one, the pane last clicked (at first the model that was shown): the
//   panel's model section, the status line's details and the floating windows (inspector,
//   hints) are its. Choosing a model (its key, its radio button, `model NAME`) makes its pane
//   active, or puts it in the active pane's place when no pane shows it.
// - A click on a pane is that pane's model's click: a traced pane's ray tree, a local pane's
//   inspector. Enter traces every traced pane (Whitted, the hybrid), Space runs radiosity in
//   every pane that shows it.
// Any model of the registry may be a pane.
#include <filesystem>
#include <string>
#include <vector>

#include "app/viewer/model_view.h"
#include "core/image.h"
#include "gl/framebuffer.h"

namespace luz::app {

struct ModelEntry;
struct ScriptVerb;
struct ViewerState;

inline constexpr size_t kMaxPanes = 4;

// "flat,gouraud" -> {"flat", "gouraud"}; every piece kept, empty ones too (the check names them).
std::vector<std::string> split_model_list(const std::string& text);

// "" when the window can show these models: 1 (one picture) to 4, each a model of the registry
// with a view, none twice. Otherwise why not, in the current language.
std::string pane_list_problem(const std::vector<std::string>& models);

// The panes' rectangles in `view`: equal, whole framebuffer pixels, from its top-left corner;
// the pixels a division leaves over stay background at the right and bottom edge. One model:
// the view itself.
std::vector<Viewport> pane_viewports(const Viewport& view, size_t count);

// The index of the pane holding window point `p`; -1 when none does.
int pane_at(const std::vector<Viewport>& panes, glm::vec2 p);

// A pane's label, in window units, as the window draws it: the box at the pane's top-left
// corner, sized as the headless grid sizes it for the pane's height in pixels.
struct PaneLabel {
  std::string text;
  glm::vec2 origin{0.0f}, size{0.0f};
  float text_size = 0.0f, pad = 0.0f;
};
PaneLabel pane_label(const std::string& model, const Viewport& pane);
// Over the picture, under every window (ImGui's background list); the active pane's box in the
// interface's accent colour.
void draw_pane_label(const PaneLabel& label, bool active);

// The screenshot of the panes: each pane's radiance at its place in the picture (the rest
// black), with the label `luz render --model a,b,...` writes, as a PNG at `exposure` EV.
// `pictures[i]` is pane i's, `panes[i]` its rectangle in `view`.
void save_panes(const std::vector<const gl::Framebuffer*>& pictures, const std::vector<Viewport>& panes,
                const std::vector<std::string>& models, const Viewport& view, const std::filesystem::path& path,
                float exposure);
// Where the screenshot's label covers pane `pane` (pixels of the pane's own picture).
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};
PixelRect screenshot_label_box(const std::string& model, glm::ivec2 pane_pixels);

// The panel's "Side by side" section, its last (the sections above keep their places): a
// checkbox per model, the lecture's two comparisons and "One picture"; each runs a `panes` line
// (state.panel_lines).
void panes_section(ViewerState& state);

// The script's `panes MODEL[,MODEL...]` / `panes off` and `dump-panes FILE.json`, rows of the
// common verbs' table (script_verbs.cpp).
std::string check_panes(const struct ScriptCommand& command);
bool run_panes(class Viewer& viewer, const ScriptCommand& command, std::string& error);
bool run_dump_panes(Viewer& viewer, const ScriptCommand& command, std::string& error);

}  // namespace luz::app
