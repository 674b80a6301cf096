#include "app/classroom/classroom_ui.h"

#include <algorithm>
#include <string>

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

void draw_whole_caption(const LessonPlayer& player, i18n::Language language, float text_scale, CaptionResult& result) {
  const LessonStep& step = player.step();
  const std::string where = trf("slide {} · step {} / {}", step.slide, player.index() + 1, player.size());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", where.c_str());
  ImGui::PopStyleColor();
  ImGui::SetWindowFontScale(1.4f * text_scale);  // the title, larger still
  ImGui::TextWrapped("%s", step.title.in(language).c_str());
  ImGui::SetWindowFontScale(text_scale);
  ImGui::TextWrapped("%s", step.text.in(language).c_str());
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
void draw_collapsed_caption(const LessonPlayer& player, i18n::Language language, float text_scale, CaptionResult& result) {
  const LessonStep& step = player.step();
  ImGui::SetWindowFontScale(text_scale);
  if (ImGui::Button(tr("show the text  [F9]"))) result.toggle_collapsed = true;
  ImGui::SameLine();
  ImGui::AlignTextToFramePadding();
  const std::string where = trf("slide {} · step {} / {}", step.slide, player.index() + 1, player.size());
  ImGui::TextDisabled("%s", where.c_str());
  ImGui::SameLine();
  ImGui::TextUnformatted(step.title.in(language).c_str());
}

}  // namespace

CaptionResult draw_lesson_caption(const LessonPlayer& player, i18n::Language language, ImVec2 top_left,
                                  float width, float max_height, float text_scale, bool collapsed) {
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
    if (collapsed)
      draw_collapsed_caption(player, language, text_scale, result);
    else
      draw_whole_caption(player, language, text_scale, result);
    result.size = ImGui::GetWindowSize();
    // The cursor stands below the last line, inside the padding's top: the padding's bottom added.
    result.wanted_height = ImGui::GetCursorPosY() - ImGui::GetStyle().ItemSpacing.y + ImGui::GetStyle().WindowPadding.y;
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
