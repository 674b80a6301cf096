#pragma once
// The small windows of the viewer besides the panel and the inspector: the status line, the
// list of keys (F1), Whitted's hint and progress, and the error of a scene that did not load.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <imgui.h>

#include "app/viewer/model_view.h"
#include "app/viewer/viewer_state.h"

namespace luz::app {

// Floating windows over the picture go into its corners, one window per corner, each at most a
// little under half the picture's width and height: so none covers the picture's centre or
// another. A hint at the top centre pushes the top corners down below it.
class WindowCorners {
public:
  enum Corner { top_left, top_right, bottom_left, bottom_right };
  WindowCorners(const Viewport& viewport, float margin) : viewport_(viewport), margin_(margin) {}
  // The next window goes into the free corner farthest from `at` (the inspected point, which
  // stays in view); false when every corner is taken (it goes into the farthest anyway).
  bool place_away_from(glm::vec2 at);
  // The next window goes into `preferred`, or the next free corner.
  bool place(Corner preferred);
  // A window at the top centre ends at `bottom` (window units).
  void reserve_top(float bottom) { top_ = std::max(top_, bottom); }
  // Where the next window at the top centre starts: below those reserved (the lesson's caption).
  float top() const { return std::max(viewport_.origin.y, top_); }
  // The left half of the picture for one large window (slide 36's), below room for a two-line
  // hint at the top centre: x, y, width, height in window units. Its two corners are taken.
  // Docked: the dock's room below the windows already in it.
  glm::vec4 take_left_half();
  // A lesson's dock beside the picture (Layout::dock), or its windows' column right of the
  // caption in a dock below it: every window placed from now on, hints included, goes there
  // instead, one under the other below those already in it (the caption first, when it is
  // there), as wide as the dock. None covers the picture.
  void dock_in(const Viewport& dock) { dock_ = dock; }
  bool docked() const { return !dock_.empty(); }
  const Viewport& dock() const { return dock_; }
  // Where the next docked window starts: below every window drawn in the dock so far this frame.
  float docked_top() const;
  // Where the windows placed so far ended up (ImGui's rectangles), for the tests' dump-windows.
  const Viewport& viewport() const { return viewport_; }

private:
  void put(Corner corner);
  Viewport viewport_;
  Viewport dock_;
  float margin_;
  float top_ = 0.0f;
  bool taken_[4] = {false, false, false, false};
};

// A hint's content: a progress bar when `progress` is given (its fraction done), then the lines,
// each wrapped to the hint's width; the bar's label (the first line) beside it when it fits.
struct HintText {
  std::optional<float> progress;
  std::vector<std::string> lines;
};

// A hint over the picture: a window without decoration or input at the top centre of
// `viewport`, from `corners.top()` down, sized to its text, which wraps to the viewport's width
// (a pane of the side-by-side view is narrow); in the dock when `corners` is docked, as wide as
// the dock, its text drawn smaller when the room below the windows already there is short, so
// that it is read whole (down to 0.7 of the unscaled font). The top is reserved for it.
void draw_hint(const char* name, const Viewport& viewport, WindowCorners& corners, float ui_scale, const HintText& text);

// The panel and the status line frame the picture: fixed windows without ImGui's own border,
// whose anti-aliased edge reaches a pixel past the window, onto the picture (and into the
// panel cache's way, panel_cache.h). A line of the border's colour inside the window along
// `edge` takes its place. Ends with ImGui::End as any window.
enum class Edge { top, right };
void begin_frame_window(const char* name, glm::vec2 origin, glm::vec2 size, ImGuiWindowFlags flags, Edge edge);

// The status line's text: model, its state, frame time (`state.status_ms`), triangles, lights,
// camera and the latest message.
std::string status_line_text(const ViewerState& state, const std::string& model);
// `text` in one line at `top` (the status line), fitted to `width` by fit_status_line.
void draw_status_line(const std::string& text, float top, float width, float height);
// `text` (status_line_text's) without the figures that matter least until it is at most `width`
// wide in the current font.
std::string fit_status_line(const std::string& text, float width);

// The shortcut table (shortcuts.h), the models' keys and the mouse gestures, in a window of at
// most `max` window units centred on `centre`, scrolled when the list is longer; its close
// button (and F1 again) hides it.
void draw_help(bool& open, glm::vec2 centre, glm::vec2 max);

// The scene's warnings (the loader's and the renderers'), in a small window at the bottom of
// the picture until closed.
void draw_warnings(std::vector<std::string>& warnings, bool& open, const Viewport& viewport, float margin);


// state.error in a red-titled window centred on (x, y); its OK button clears the error.
void draw_load_error(ViewerState& state, float x, float y, float max_width);

// A table that keeps every column as wide as its text: it scrolls sideways inside its window
// where the window is narrower (ImGui squeezes a table's columns to the window otherwise). Such
// a table is a child window of its own, as high as this: `rows` one-line rows (its headings
// among them) and the scroll bar.
constexpr ImGuiTableFlags kTextWideTable = ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX;
float text_wide_table_height(int rows);

}  // namespace luz::app
