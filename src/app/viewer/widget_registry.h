#pragma once
// The panel's widgets by name: each labelled widget is named right after it is drawn, with the
// rectangle Dear ImGui gave it, so that a script addresses it by its label
// (`click-widget "Blinn N·H [B]"`) instead of by window coordinates that move whenever a widget
// is added above it or the panel's width changes. Debian's libimgui is built without the test
// engine's hooks and keeps no list of its items, hence the explicit call:
//
//   ImGui::Checkbox("shadow rays S_i", &o.shadows);
//   name_widget("shadow rays S_i");
//
// The name is the label as the source writes it, in English, also where the label shown goes
// through tr(): a script then clicks the same widget in every language. The names of one frame
// are kept until the next frame starts (an ImGui context hook at NewFrame), so a script command
// between two frames sees the widgets that are on screen.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

namespace luz::app {

struct NamedWidget {
  std::string label;       // as given to ImGui, "##" suffix included
  glm::vec2 min{0.0f}, max{0.0f};  // window coordinates
  bool visible = false;    // not scrolled out of the panel, not clipped away
  glm::vec2 centre() const { return 0.5f * (min + max); }
};

// Names ImGui's last item (the widget just drawn) `label`, for this frame.
void name_widget(std::string_view label);

// The widgets named in the last frame drawn, in the order they were drawn.
const std::vector<NamedWidget>& named_widgets();

// The widget called `label` in the last frame: its whole label, or the part a user reads (before
// "##") when only one widget reads so; nullopt otherwise, `error` then naming the label and the
// nearest labels that are on screen.
std::optional<NamedWidget> find_widget(std::string_view label, std::string& error);

// The labels among `labels` nearest to `label` (case ignored; edit distance, or containing it),
// at most `count`: what an error suggests for a mistyped label.
std::vector<std::string> near_labels(std::string_view label, const std::vector<std::string>& labels, size_t count);

// {"widgets": [{"label", "rect": [x0, y0, x1, y1], "visible"}, ...]}: for `dump-widgets`.
nlohmann::json widgets_json();

}  // namespace luz::app
