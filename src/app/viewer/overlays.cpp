#include "app/viewer/overlays.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_internal.h>  // the windows drawn in the dock so far this frame

#include "app/common/i18n.h"
#include "app/viewer/shortcuts.h"

namespace luz::app {

bool WindowCorners::place_away_from(glm::vec2 at) {
  const glm::vec2 centre = viewport_.centre();
  // The corner diagonally opposite the point first, then the one beside it across, ...
  const bool right = at.x > centre.x, low = at.y > centre.y;
  const Corner order[4] = {Corner(int(!low) * 2 + int(!right)), Corner(int(low) * 2 + int(!right)),
                           Corner(int(!low) * 2 + int(right)), Corner(int(low) * 2 + int(right))};
  for (Corner c : order)
    if (!taken_[c]) {
      put(c);
      return true;
    }
  put(order[0]);
  return false;
}

bool WindowCorners::place(Corner preferred) {
  for (int i = 0; i < 4; ++i) {
    const Corner c = Corner((int(preferred) + i) % 4);
    if (!taken_[c]) {
      put(c);
      return true;
    }
  }
  put(preferred);
  return false;
}

float WindowCorners::docked_top() const {
  float bottom = dock_.origin.y;
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  for (const ImGuiWindow* w : g.Windows) {
    const bool this_frame = w->LastFrameActive == g.FrameCount && !w->Hidden;
    const bool own = !(w->Flags & (ImGuiWindowFlags_ChildWindow | ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_Popup));
    const bool in_dock = w->Pos.x >= dock_.origin.x && w->Pos.x < dock_.origin.x + dock_.size.x &&
                         w->Pos.y >= dock_.origin.y && w->Pos.y < dock_.origin.y + dock_.size.y;
    if (this_frame && own && in_dock)
      bottom = std::max(bottom, w->Pos.y + w->Size.y);
  }
  return bottom;
}

void WindowCorners::put(Corner corner) {
  taken_[corner] = true;
  if (docked()) {
    const float top = docked_top() + margin_;
    ImGui::SetNextWindowPos(ImVec2(dock_.origin.x + margin_, top), ImGuiCond_Always);
    const float width = std::max(dock_.size.x - 2.0f * margin_, 1.0f);
    const float height = std::max(dock_.origin.y + dock_.size.y - margin_ - top, 1.0f);
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, height));
    return;
  }
  const bool right = corner == top_right || corner == bottom_right;
  const bool low = corner == bottom_left || corner == bottom_right;
  const glm::vec2 o = viewport_.origin, s = viewport_.size;
  const float top = std::max(o.y, top_) + margin_;
  const float x = right ? o.x + s.x - margin_ : o.x + margin_;
  const float y = low ? o.y + s.y - margin_ : top;
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always, ImVec2(right ? 1.0f : 0.0f, low ? 1.0f : 0.0f));
  // Each quarter less the margins: windows in different corners cannot meet, nor cover the centre.
  const float half_height = low ? 0.5f * s.y - 1.5f * margin_ : o.y + 0.5f * s.y - top - 0.5f * margin_;
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f),
                                      ImVec2(std::max(0.5f * s.x - 1.5f * margin_, 1.0f), std::max(half_height, 1.0f)));
}

glm::vec4 WindowCorners::take_left_half() {
  taken_[top_left] = taken_[bottom_left] = true;
  if (docked()) {
    const float top = docked_top() + margin_;
    return {dock_.origin.x + margin_, top, dock_.size.x - 2.0f * margin_, dock_.origin.y + dock_.size.y - margin_ - top};
  }
  const float hint = 2.0f * ImGui::GetTextLineHeightWithSpacing() + 2.0f * ImGui::GetStyle().WindowPadding.y;
  const glm::vec2 o = viewport_.origin, s = viewport_.size;
  const float top = std::max(o.y, top_) + margin_ + hint;
  return {o.x + margin_, top, 0.5f * s.x - 1.5f * margin_, o.y + s.y - margin_ - top};
}

namespace {

constexpr float hint_bar_ems = 5.0f;  // a hint's progress bar, in font heights

float hint_bar_width(float wrap) { return std::min(hint_bar_ems * ImGui::GetFontSize(), wrap); }

// Whether the bar's label fits on the bar's line, `wrap` wide, at the window's font.
bool label_beside_bar(const HintText& text, float wrap) {
  if (!text.progress || text.lines.empty()) return false;
  const float label = ImGui::CalcTextSize(text.lines.front().c_str()).x;
  return hint_bar_width(wrap) + ImGui::GetStyle().ItemSpacing.x + label <= wrap;
}

// The hint's content height at the window's font, its lines wrapped `wrap` wide, as
// draw_hint_content lays it out: each row moves the cursor down its height and the item spacing,
// to a whole unit (a label beside the bar is within the bar's frame height).
float hint_height(const HintText& text, float wrap) {
  const float spacing = ImGui::GetStyle().ItemSpacing.y;
  float y = 0.0f;
  const auto row = [&](float height) { y = std::floor(y + height + spacing); };
  if (text.progress) row(ImGui::GetFrameHeight());
  for (size_t i = label_beside_bar(text, wrap) ? 1 : 0; i < text.lines.size(); ++i)
    row(ImGui::CalcTextSize(text.lines[i].c_str(), nullptr, false, wrap).y);
  return y - spacing;
}

// The largest font scale, from 1 down to `least`, at which the hint's content fits `room` high;
// the window's font is left at it.
float fit_hint_font(const HintText& text, float wrap, float room, float least) {
  float scale = 1.0f;
  ImGui::SetWindowFontScale(scale);
  while (scale > least && hint_height(text, wrap) > room) {
    scale = std::max(0.95f * scale, least);
    ImGui::SetWindowFontScale(scale);
  }
  return scale;
}

void draw_hint_content(const HintText& text, float wrap) {
  const bool beside = label_beside_bar(text, wrap);
  if (text.progress) ImGui::ProgressBar(*text.progress, ImVec2(hint_bar_width(wrap), 0.0f), "");
  if (beside) ImGui::SameLine();
  for (const std::string& line : text.lines) ImGui::TextUnformatted(line.c_str());
}

}  // namespace

void draw_hint(const char* name, const Viewport& picture, WindowCorners& corners, float ui_scale, const HintText& text) {
  const float margin = 8.0f * ui_scale;
  const ImGuiStyle& style = ImGui::GetStyle();
  const Viewport& viewport = corners.docked() ? corners.dock() : picture;
  float room = std::numeric_limits<float>::max();
  if (corners.docked()) {
    const float top = corners.docked_top() + margin;
    const float height = std::max(viewport.origin.y + viewport.size.y - margin - top, 1.0f);
    ImGui::SetNextWindowPos(ImVec2(viewport.origin.x + margin, top), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(std::max(viewport.size.x - 2.0f * margin, 1.0f), height));
    room = height - 2.0f * style.WindowPadding.y;
  } else
    ImGui::SetNextWindowPos(ImVec2(viewport.centre().x, corners.top() + margin), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin(name, nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  // The text's width: the window's content at its widest (the wrap position is measured from the
  // window's left edge, the text starts after its padding).
  const float wrap = std::max(viewport.size.x - 2.0f * (margin + style.WindowPadding.x), 4.0f * ImGui::GetFontSize());
  fit_hint_font(text, wrap, room, std::min(0.7f / ui_scale, 1.0f));
  ImGui::PushTextWrapPos(style.WindowPadding.x + wrap);
  draw_hint_content(text, wrap);
  ImGui::PopTextWrapPos();
  ImGui::SetWindowFontScale(1.0f);
  corners.reserve_top(ImGui::GetWindowPos().y + ImGui::GetWindowSize().y);
  ImGui::End();
}

void begin_frame_window(const char* name, glm::vec2 origin, glm::vec2 size, ImGuiWindowFlags flags, Edge edge) {
  ImGui::SetNextWindowPos(ImVec2(origin.x, origin.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(size.x, size.y), ImGuiCond_Always);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::Begin(name, nullptr, flags);
  ImGui::PopStyleVar();
  const float t = std::max(ImGui::GetStyle().WindowBorderSize, 1.0f);
  const glm::vec2 end = origin + size;
  const ImVec2 a = edge == Edge::top ? ImVec2(origin.x, origin.y) : ImVec2(end.x - t, origin.y);
  const ImVec2 b = edge == Edge::top ? ImVec2(end.x, origin.y + t) : ImVec2(end.x, end.y);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(a, b);
  draw->AddRectFilled(a, b, ImGui::GetColorU32(ImGuiCol_Border));  // square corners: no anti-aliased fringe
  draw->PopClipRect();
}

std::string status_line_text(const ViewerState& state, const std::string& model) {
  const Scene& scene = *state.scene;
  const auto lights = std::count_if(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.enabled; });
  const std::string camera = state.free_camera ? tr("free camera (C: back)") : scene.cameras[size_t(state.scene_camera)].name;
  const size_t triangles = scene.triangle_count(), emitters = scene.area_lights.size();
  return fmt::format("{}  |  {:.1f} ms  |  {}  |  {}, {}  |  {}  |  {}", model, state.status_ms,
                     trnf("{} triangle", "{} triangles", triangles, triangles),
                     trnf("{} light", "{} lights", size_t(lights), lights),
                     trnf("{} emitter", "{} emitters", emitters, emitters), camera, state.note);
}

// A status line wider than the window (a large UI, a narrow window, a long note) leaves out its
// figures that matter least, in this order: the triangles, the camera, the lights, the frame
// time; the model and the note (what just happened) stay, the note's end cut if need be.
std::string fit_status_line(const std::string& text, float width) {
  constexpr std::string_view separator = "  |  ";
  std::vector<std::string> fields;
  for (size_t start = 0;;) {
    const size_t end = text.find(separator, start);
    fields.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + separator.size();
  }
  const auto joined = [&] {
    std::string line;
    for (const std::string& f : fields)
      if (!f.empty()) line += (line.empty() ? "" : std::string(separator)) + f;
    return line;
  };
  std::string line = joined();
  if (fields.size() != 6) return line;  // model, ms, triangles, lights, camera, note: status_line_text's
  for (const size_t drop : {2, 4, 3, 1}) {
    if (ImGui::CalcTextSize(line.c_str()).x <= width) break;
    fields[drop].clear();
    line = joined();
  }
  // Still too wide: the note's end gives way, marked by "...", a whole UTF-8 character at a time.
  std::string& note = fields[5];
  while (ImGui::CalcTextSize(line.c_str()).x > width && !note.empty()) {
    if (note.ends_with("...")) note.resize(note.size() - 3);
    while (!note.empty() && (static_cast<unsigned char>(note.back()) & 0xC0) == 0x80) note.pop_back();
    if (!note.empty()) note.pop_back();  // the last character's first byte
    if (!note.empty()) note += "...";
    line = joined();
  }
  return line;
}

void draw_status_line(const std::string& text, float top, float width, float height) {
  const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  begin_frame_window("status", glm::vec2(0.0f, top), glm::vec2(width, height), fixed, Edge::top);
  ImGui::TextUnformatted(fit_status_line(text, width - 2.0f * ImGui::GetStyle().WindowPadding.x).c_str());
  ImGui::End();
}

void draw_help(bool& open, glm::vec2 centre, glm::vec2 max) {
  ImGui::SetNextWindowPos(ImVec2(centre.x, centre.y), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(max.x, max.y));
  // Auto-sized up to `max`; beyond it the list scrolls (wheel, scrollbar), the title bar's
  // close button and F1 hide it.
  ImGui::Begin(tr("Keys (F1)"), &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                                       ImGuiWindowFlags_AlwaysVerticalScrollbar);
  // As wide as `max` allows, the descriptions wrapped in their column: a longer translation
  // takes another line instead of running past the window's edge.
  const float width = max.x - 2.0f * ImGui::GetStyle().WindowPadding.x - ImGui::GetStyle().ScrollbarSize;
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg, ImVec2(width, 0.0f))) {
    ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
    auto row = [](const std::string& keys, const char* what) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(keys.c_str());
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", what);
    };
    for (const Shortcut& s : shortcuts()) row(tr(s.shown.c_str()), tr(s.what));
    row(tr("left drag"), tr("orbit around the scene"));
    row(tr("right drag"), tr("pan"));
    row(tr("wheel"), tr("zoom"));
    row(tr("left click"), tr("inspect the pixel: each term's value (Whitted: its ray tree; radiosity: the patch)"));
    row(tr("drop a file"), tr("load a .gltf / .glb scene"));
    ImGui::EndTable();
  }
  if (ImGui::Button(tr("close  [F1]"))) open = false;
  ImGui::End();
}

void draw_warnings(std::vector<std::string>& warnings, bool& open, const Viewport& viewport, float margin) {
  if (warnings.empty() || !open) return;
  ImGui::SetNextWindowPos(ImVec2(viewport.centre().x, viewport.origin.y + viewport.size.y - margin), ImGuiCond_Always,
                          ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(0.9f * viewport.size.x, 0.3f * viewport.size.y));
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::PushStyleColor(ImGuiCol_TitleBgActive, ImVec4(0.55f, 0.4f, 0.05f, 1.0f));
  ImGui::PushStyleColor(ImGuiCol_TitleBg, ImVec4(0.55f, 0.4f, 0.05f, 1.0f));
  const std::string title = (warnings.size() == 1 ? std::string(tr("1 warning")) : trf("{} warnings", warnings.size())) + "###warnings";
  ImGui::Begin(title.c_str(), &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                                         ImGuiWindowFlags_NoFocusOnAppearing);
  // BulletText does not wrap: a bullet, then the text on its line, wrapped at the window's width.
  ImGui::PushTextWrapPos(0.85f * viewport.size.x);
  for (const std::string& w : warnings) {
    ImGui::Bullet();
    ImGui::TextUnformatted(w.c_str());
  }
  ImGui::PopTextWrapPos();
  ImGui::End();
  ImGui::PopStyleColor(2);
}

void draw_load_error(ViewerState& state, float x, float y, float max_width) {
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(0.9f * max_width, 1e6f));
  // A red title: the tests find the window by it (tests/test_viewer.cpp).
  ImGui::PushStyleColor(ImGuiCol_TitleBgActive, ImVec4(0.6f, 0.1f, 0.1f, 1.0f));
  ImGui::PushStyleColor(ImGuiCol_TitleBg, ImVec4(0.6f, 0.1f, 0.1f, 1.0f));
  ImGui::Begin(tr("The scene did not load"), nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::PushTextWrapPos(0.85f * max_width);
  ImGui::TextUnformatted(state.error.c_str());
  ImGui::PopTextWrapPos();
  ImGui::TextDisabled(tr("Still showing %s. Fix the file and press R, or drop another."),
                      state.scene_path.filename().string().c_str());
  if (ImGui::Button(tr("OK"))) state.error.clear();
  ImGui::End();
  ImGui::PopStyleColor(2);
}

float text_wide_table_height(int rows) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float row = ImGui::GetTextLineHeight() + 2.0f * style.CellPadding.y + 1.0f;  // 1: a border
  return float(rows) * row + style.ScrollbarSize + 2.0f;
}

}  // namespace luz::app
