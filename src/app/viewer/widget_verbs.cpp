#include "app/viewer/widget_verbs.h"

#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "app/common/json_file.h"
#include "app/viewer/model_view.h"
#include "app/viewer/widget_registry.h"
#include "app/viewer/viewer_window.h"

namespace luz::app {

std::string check_click_widget(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return c.args[0].empty() ? "`click-widget` takes a widget's label" : "";
}

// The widget is looked up among those of the last frame drawn; one hidden by the panel's scroll
// cannot be clicked, as a user could not.
bool run_click_widget(Viewer& v, const ScriptCommand& c, std::string& error) {
  const std::optional<NamedWidget> widget = find_widget(c.args[0], error);
  if (!widget) return false;
  if (!widget->visible) {
    error = fmt::format("the widget \"{}\" is scrolled out of the panel's view", c.args[0]);
    return false;
  }
  v.click_at(widget->centre());
  return true;
}

bool run_dump_widgets(Viewer&, const ScriptCommand& c, std::string& error) {
  return write_json(c.args[0], widgets_json(), "the widgets' rectangles", error);
}

namespace {

// "55%" or "55.5%": a fraction of the picture in [0, 1), else nothing.
std::optional<float> percent_of(const std::string& arg) {
  if (arg.size() < 2 || arg.back() != '%') return std::nullopt;
  try {
    size_t used = 0;
    const float value = std::stof(arg.substr(0, arg.size() - 1), &used);
    if (used + 1 != arg.size() || !(value >= 0.0f && value < 100.0f)) return std::nullopt;
    return value / 100.0f;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

bool is_pixel(const std::string& arg) { return is_int(arg) && std::stoi(arg) >= 0; }

}  // namespace

std::string check_click_picture(const ScriptCommand& c) {
  if (auto e = check_count(c, 2, 2); !e.empty()) return e;
  if (is_pixel(c.args[0]) && is_pixel(c.args[1])) return "";
  if (percent_of(c.args[0]) && percent_of(c.args[1])) return "";
  return "`click-picture X Y` takes a pixel of the picture (whole numbers from 0) or `X% Y%`, fractions of it (0 to 100%)";
}

bool run_click_picture(Viewer& v, const ScriptCommand& c, std::string& error) {
  const Viewport view = v.layout().view;
  if (const auto x = percent_of(c.args[0]), y = percent_of(c.args[1]); x && y) {
    if (view.empty()) {
      error = "the picture has no pixels to click";
      return false;
    }
    // The camera spans the picture's height whatever its width (a fixed vertical field of
    // view): fractions of the square of that height, centred in the picture, name the same
    // direction, hence the same object, at any window size, panel width or UI scale.
    const float side = float(view.pixels.y);
    const glm::vec2 at(0.5f * float(view.pixels.x) + (*x - 0.5f) * side, *y * side);
    if (at.x < 0.0f || at.x >= float(view.pixels.x)) {
      error = fmt::format("the picture is {}x{} pixels: {} of its height from its centre is outside it", view.pixels.x,
                          view.pixels.y, c.args[0]);
      return false;
    }
    v.click_at(view.window_of(glm::ivec2(glm::floor(at))));
    return true;
  }
  const glm::ivec2 pixel(std::stoi(c.args[0]), std::stoi(c.args[1]));
  if (pixel.x >= view.pixels.x || pixel.y >= view.pixels.y) {
    error = fmt::format("the picture is {}x{} pixels: ({}, {}) is outside it", view.pixels.x, view.pixels.y, pixel.x,
                        pixel.y);
    return false;
  }
  v.click_at(view.window_of(pixel));
  return true;
}

// A state a script waits for instead of a number of frames, which a faster or slower machine
// would turn into another state.
std::string check_wait_until(const ScriptCommand& c) {
  if (auto e = check_count(c, 2, 2); !e.empty()) return e;
  if (c.args[0] != "trace-done" && c.args[0] != "radiosity-done")
    return fmt::format("unknown condition \"{}\" (trace-done, radiosity-done)", c.args[0]);
  return is_int(c.args[1]) && std::stoi(c.args[1]) >= 1 ? "" : "`wait-until CONDITION FRAMES` takes a number of frames >= 1";
}

bool condition_holds(Viewer& v, const std::string& condition) {
  if (condition == "trace-done") {  // every traced pane (`trace` traces them all)
    bool traced_pane = false;
    for (const ModelView* pane : v.pane_views())
      if (pane->trace_state()) {
        if (!pane->holds(condition)) return false;
        traced_pane = true;
      }
    return traced_pane;
  }
  // The solution models 5 and 6 show is the radiosity view's.
  return condition == "radiosity-done" && v.view("radiosity").holds(condition);
}

bool Viewer::holds(const std::string& condition) { return condition_holds(*this, condition); }

}  // namespace luz::app
