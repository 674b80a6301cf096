#pragma once
// The classroom's pieces of the viewer's interface, drawn with Dear ImGui wherever the viewer
// places them: the lesson's caption box (readable from the back of the room) with its previous /
// next buttons, and the language switch. Each draws inside the current ImGui frame.
#include <imgui.h>

#include "app/classroom/lesson.h"

namespace luz::app {

enum class LessonMove { none, previous, next };

struct CaptionResult {
  LessonMove move = LessonMove::none;  // the button pressed this frame
  bool toggle_collapsed = false;       // its fold / unfold button pressed this frame
  ImVec2 size{0.0f, 0.0f};             // the box as drawn (its width is the one asked for)
  float wanted_height = 0.0f;          // the box's height with all of its text, cut or not
};

// The current step: "slide N · step i / n", its title and its text in `language`, wrapped to
// `width`, scaled by `text_scale` (the class's enlargement over the UI's font), in a box whose
// top-left corner is `top_left` (window coordinates), at most `max_height` high. Collapsed: one
// line, the step and its title, cut at the box's edge, and the button that unfolds it.
CaptionResult draw_lesson_caption(const LessonPlayer& player, i18n::Language language, ImVec2 top_left,
                                  float width, float max_height, float text_scale, bool collapsed = false);

// "Español | English" radio buttons; switches the language at once (i18n::set_language).
void draw_language_switch();

}  // namespace luz::app
