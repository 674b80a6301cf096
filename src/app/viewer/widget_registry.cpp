#include "app/viewer/widget_registry.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <imgui.h>
#include <imgui_internal.h>  // the context hook that starts each frame's list

namespace luz::app {
namespace {

struct Registry {
  ImGuiContext* context = nullptr;  // the context the hook is installed in
  std::vector<NamedWidget> drawing;  // the frame being drawn
  std::vector<NamedWidget> shown;    // the last frame drawn
};

Registry& registry() {
  static Registry r;
  return r;
}

// At every NewFrame the list of the frame just drawn becomes the one scripts see.
void install_hook() {
  Registry& r = registry();
  ImGuiContext* context = ImGui::GetCurrentContext();
  if (r.context == context) return;
  r = Registry{};
  r.context = context;
  ImGuiContextHook hook;
  hook.Type = ImGuiContextHookType_NewFramePre;
  hook.Callback = [](ImGuiContext*, ImGuiContextHook*) {
    Registry& reg = registry();
    reg.shown = std::move(reg.drawing);
    reg.drawing.clear();
  };
  ImGui::AddContextHook(context, &hook);
}

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string_view shown_part(std::string_view label) { return label.substr(0, label.find("##")); }

// What a label says, for comparing: the part shown, without a trailing key hint "  [B]".
std::string gist(std::string_view label) {
  std::string_view text = shown_part(label);
  if (text.ends_with(']'))
    if (const size_t open = text.rfind('['); open != std::string_view::npos && open > 0) text = text.substr(0, open);
  while (text.ends_with(' ')) text.remove_suffix(1);
  return lower(text);
}

}  // namespace

void name_widget(std::string_view label) {
  install_hook();
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  // A click lands at the centre: the widget is in view when its centre is inside what the
  // window shows (not scrolled away, not under its edge).
  const ImVec2 centre((min.x + max.x) / 2.0f, (min.y + max.y) / 2.0f);
  const bool visible = ImGui::IsItemVisible() && ImGui::GetCurrentWindow()->ClipRect.Contains(centre);
  registry().drawing.push_back({std::string(label), {min.x, min.y}, {max.x, max.y}, visible});
}

const std::vector<NamedWidget>& named_widgets() { return registry().shown; }

std::vector<std::string> near_labels(std::string_view label, const std::vector<std::string>& labels, size_t count) {
  const std::string wanted = gist(label);
  std::vector<std::pair<size_t, std::string>> scored;
  for (const std::string& candidate : labels) {
    const std::string other = gist(candidate);
    const size_t distance = other.empty() ? wanted.size()
                            : other.find(wanted) != std::string::npos || wanted.find(other) != std::string::npos
                                ? 0 : edit_distance(wanted, other);
    if (distance <= std::max<size_t>(3, wanted.size() / 2)) scored.emplace_back(distance, candidate);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (const auto& [distance, candidate] : scored)
    if (out.size() < count && std::find(out.begin(), out.end(), candidate) == out.end()) out.push_back(candidate);
  return out;
}

std::optional<NamedWidget> find_widget(std::string_view label, std::string& error) {
  const std::vector<NamedWidget>& widgets = named_widgets();
  for (const NamedWidget& w : widgets)
    if (w.label == label) return w;
  const NamedWidget* only = nullptr;
  int reading_so = 0;
  for (const NamedWidget& w : widgets)
    if (shown_part(w.label) == label) {
      only = &w;
      ++reading_so;
    }
  if (reading_so == 1) return *only;
  if (reading_so > 1) {
    error = fmt::format("{} widgets read \"{}\": give the whole label (with its ##)", reading_so, label);
    return std::nullopt;
  }
  std::vector<std::string> labels;
  for (const NamedWidget& w : widgets) labels.push_back(w.label);
  const std::vector<std::string> near = near_labels(label, labels, 5);
  error = fmt::format("no widget \"{}\" in the panel", label);
  if (!near.empty()) error += fmt::format(" (near: \"{}\")", fmt::join(near, "\", \""));
  else error += " (dump-widgets lists those on screen)";
  return std::nullopt;
}

nlohmann::json widgets_json() {
  nlohmann::json list = nlohmann::json::array();
  for (const NamedWidget& w : named_widgets())
    list.push_back({{"label", w.label}, {"rect", {w.min.x, w.min.y, w.max.x, w.max.y}}, {"visible", w.visible}});
  return {{"widgets", list}};
}

}  // namespace luz::app
