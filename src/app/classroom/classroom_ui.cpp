#include "app/classroom/classroom_ui.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/common/i18n.h"

namespace luz::app {

namespace {

// Whether `label`'s button fits on the current line, right of the last item.
bool fits_on_this_line(const char* label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * style.FramePadding.x;
  return ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
}

// `label`'s button on the current line when it fits there, else on the next (a narrow dock).
bool button_on_this_line(const char* label) {
  if (fits_on_this_line(label)) ImGui::SameLine();
  return ImGui::Button(label);
}

// The whole caption's lines above its buttons, each wrapped to the box: the hint, where the
// class is (both dim), the title (larger still) and the text.
struct CaptionLine {
  std::string text;
  float scale;  // of the caption's text scale
  bool dim;
};

std::vector<CaptionLine> whole_caption_lines(const LessonPlayer& player, i18n::Language language, const char* hint) {
  const LessonStep& step = player.step();
  std::vector<CaptionLine> lines;
  if (hint) lines.push_back({hint, 1.0f, true});
  lines.push_back({trf("slide {} · step {} / {}", step.slide, player.index() + 1, player.size()), 1.0f, true});
  lines.push_back({step.title.in(language), 1.4f, false});
  lines.push_back({step.text.in(language), 1.0f, false});
  return lines;
}

// The height of the whole caption's content at `text_scale`, measured in the current window
// before anything is drawn, as ImGui lays it out: its lines wrapped as TextWrapped wraps them,
// the spacing, and the buttons' row (two rows when "next" does not fit beside "previous"), each
// item moving the cursor down its height and the item spacing, to a whole unit. The window's
// font scale is left at `text_scale`.
float whole_caption_height(const std::vector<CaptionLine>& lines, float text_scale) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float wrap = ImGui::GetContentRegionAvail().x;
  float y = 0.0f;
  const auto item = [&](float height) { y = std::floor(y + height + style.ItemSpacing.y); };
  for (const CaptionLine& line : lines) {
    ImGui::SetWindowFontScale(line.scale * text_scale);
    item(ImGui::CalcTextSize(line.text.c_str(), nullptr, false, wrap).y);
  }
  ImGui::SetWindowFontScale(text_scale);
  item(0.0f);  // ImGui::Spacing
  const auto width = [&](const char* label) { return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * style.FramePadding.x; };
  const float button = ImGui::GetFontSize() + 2.0f * style.FramePadding.y;
  item(button);
  if (width(tr("previous  [F7]")) + style.ItemSpacing.x + width(tr("next  [F8]")) > wrap) item(button);
  return y - style.ItemSpacing.y;
}

// The largest text scale, from `text_scale` down to `least_scale`, at which the whole caption
// fits `room` (the window's content height): the text is read whole rather than cut, smaller
// when the box is small (a large interface beside the panel). At least_scale it may still not fit.
float fitting_scale(const std::vector<CaptionLine>& lines, float text_scale, float least_scale, float room) {
  float scale = text_scale;
  while (scale > least_scale && whole_caption_height(lines, scale) > room) scale = std::max(0.95f * scale, least_scale);
  return scale;
}

// `room`: the window's content height at most.
void draw_whole_caption(const LessonPlayer& player, i18n::Language language, const CaptionText& text, float room,
                        CaptionResult& result) {
  const std::vector<CaptionLine> lines = whole_caption_lines(player, language, text.hint);
  result.wanted_height = whole_caption_height(lines, text.scale) + 2.0f * ImGui::GetStyle().WindowPadding.y;
  result.text_scale = fitting_scale(lines, text.scale, text.least_scale, room);
  for (const CaptionLine& line : lines) {
    ImGui::SetWindowFontScale(line.scale * result.text_scale);
    if (line.dim) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", line.text.c_str());
    if (line.dim) ImGui::PopStyleColor();
  }
  ImGui::SetWindowFontScale(result.text_scale);
  ImGui::Spacing();
  ImGui::BeginDisabled(player.index() == 0);
  if (ImGui::Button(tr("previous  [F7]"))) result.move = LessonMove::previous;
  ImGui::EndDisabled();
  ImGui::BeginDisabled(player.index() + 1 >= player.size());
  if (button_on_this_line(tr("next  [F8]"))) result.move = LessonMove::next;
  ImGui::EndDisabled();
  // Where it fits beside them: a line of its own would take the picture's windows' room in a
  // narrow dock, and F9 is there anyway.
  if (fits_on_this_line(tr("hide the text  [F9]"))) {
    ImGui::SameLine();
    if (ImGui::Button(tr("hide the text  [F9]"))) result.toggle_collapsed = true;
  }
}

// One line: the button first, so that a long title is what the box's edge cuts.
void draw_collapsed_caption(const LessonPlayer& player, i18n::Language language, float text_scale, const char* hint,
                            CaptionResult& result) {
  const LessonStep& step = player.step();
  ImGui::SetWindowFontScale(text_scale);
  if (ImGui::Button(tr("show the text  [F9]"))) result.toggle_collapsed = true;
  ImGui::SameLine();
  ImGui::AlignTextToFramePadding();
  if (hint) {
    ImGui::TextDisabled("%s", hint);
    ImGui::SameLine();
  }
  const std::string where = trf("slide {} · step {} / {}", step.slide, player.index() + 1, player.size());
  ImGui::TextDisabled("%s", where.c_str());
  ImGui::SameLine();
  ImGui::TextUnformatted(step.title.in(language).c_str());
}

}  // namespace

CaptionResult draw_lesson_caption(const LessonPlayer& player, i18n::Language language, ImVec2 top_left,
                                  float width, float max_height, const CaptionText& text) {
  CaptionResult result;
  ImGui::SetNextWindowPos(top_left, ImGuiCond_Always);
  // As wide as asked, as high as the text needs up to `max_height` (beyond it the wheel scrolls
  // it): the text wraps, however long the translation.
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, std::max(max_height, 1.0f)));
  ImGui::SetNextWindowBgAlpha(0.85f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("##lesson caption", nullptr, flags)) {
    const ImGuiStyle& style = ImGui::GetStyle();
    if (text.collapsed) {
      draw_collapsed_caption(player, language, text.scale, text.hint, result);
      // The cursor stands below the line, inside the padding's top: the padding's bottom added.
      result.wanted_height = ImGui::GetCursorPosY() - style.ItemSpacing.y + style.WindowPadding.y;
      result.text_scale = text.scale;
    } else {
      draw_whole_caption(player, language, text, std::max(max_height, 1.0f) - 2.0f * style.WindowPadding.y, result);
    }
    result.size = ImGui::GetWindowSize();
  }
  ImGui::End();
  return result;
}

void draw_language_switch() {
  const i18n::Language now = i18n::language();
  if (ImGui::RadioButton("Español", now == i18n::Language::es)) i18n::set_language(i18n::Language::es);
  ImGui::SameLine();
  if (ImGui::RadioButton("English", now == i18n::Language::en)) i18n::set_language(i18n::Language::en);
}

}  // namespace luz::app
