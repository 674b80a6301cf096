#include "app/classroom/classroom_ui.h"

#include <algorithm>
#include <string>

#include "app/common/i18n.h"

namespace luz::app {

CaptionResult draw_lesson_caption(const LessonPlayer& player, i18n::Language language, ImVec2 top_left,
                                  float width, float max_height, float text_scale) {
  CaptionResult result;
  const LessonStep& step = player.step();
  ImGui::SetNextWindowPos(top_left, ImGuiCond_Always);
  // As wide as asked, as high as the text needs up to `max_height` (beyond it the wheel scrolls
  // it): the text wraps, however long the translation.
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, std::max(max_height, 1.0f)));
  ImGui::SetNextWindowBgAlpha(0.85f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("##lesson caption", nullptr, flags)) {
    ImGui::SetWindowFontScale(text_scale);
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
    // Beside it where it fits, else under it (a narrow dock).
    const float next_width = ImGui::CalcTextSize(tr("next  [F8]")).x + 2.0f * ImGui::GetStyle().FramePadding.x;
    if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + next_width <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x)
      ImGui::SameLine();
    ImGui::BeginDisabled(player.index() + 1 >= player.size());
    if (ImGui::Button(tr("next  [F8]"))) result.move = LessonMove::next;
    ImGui::EndDisabled();
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
