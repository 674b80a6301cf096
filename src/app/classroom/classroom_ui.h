#pragma once
// The classroom's pieces of the viewer's interface, drawn with Dear ImGui wherever the viewer
// places them: the lesson's caption box (readable from the back of the room) with its previous /
// next buttons, and the language switch. Each draws inside the current ImGui frame.
#include <imgui.h>

#include "app/classroom/lesson.h"

namespace luz::app {

enum class LessonMove { none, previous, next };

struct CaptionText {
  float scale = 1.0f;         // the class's enlargement over the UI's font
  float least_scale = 1.0f;   // how far the whole text may shrink to fit its box (at most `scale`)
  bool collapsed = false;     // folded to one line
  const char* hint = nullptr; // the key that shows the hidden panel, or none
};

struct CaptionResult {
  LessonMove move = LessonMove::none;  // the button pressed this frame
  bool toggle_collapsed = false;       // its fold / unfold button pressed this frame
  ImVec2 size{0.0f, 0.0f};             // the box as drawn (its width is the one asked for)
  float wanted_height = 0.0f;          // the box's height with all of its text at text.scale, cut or not
  float text_scale = 1.0f;             // the scale the text was drawn at
};

// The current step: "slide N · step i / n", its title and its text in `language`, wrapped to
// `width`, in a box whose top-left corner is `top_left` (window coordinates), at most
// `max_height` high, at text.scale or, when the whole text does not fit the box, at the largest
// scale down to text.least_scale at which it does. Collapsed: one line, the step and its title,
// cut at the box's edge, and the button that unfolds it. A hint is a dim line of its own at the
// top, or the folded line's first words.
CaptionResult draw_lesson_caption(const LessonPlayer& player, i18n::Language language, ImVec2 top_left,
                                  float width, float max_height, const CaptionText& text);

// "Español | English" radio buttons; switches the language at once (i18n::set_language).
void draw_language_switch();

}  // namespace luz::app
