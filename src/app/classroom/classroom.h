#pragma once
// The lesson in the viewer's window: where the class is in it, the moves asked for (F8 / F7,
// the caption's buttons, the script's `lesson next|prev|goto N`), and the commands that take the
// viewer to a step. Those are script commands (lesson.h), played a few per frame exactly as a
// prepared script's are: a scene load or a trace ends the frame, a click waits for its release.
// The viewer's own script waits while a move is still playing, so `lesson next` followed by
// `screenshot` sees the step.
#include <deque>
#include <optional>
#include <string>

#include "app/classroom/classroom_ui.h"
#include "app/classroom/lesson.h"
#include <glm/vec2.hpp>
#include "app/script/script.h"

namespace luz::app {

class Classroom {
public:
  Classroom() = default;
  // Opens a lesson at its first step: that step's commands are the first to play.
  explicit Classroom(Lesson lesson);

  bool has_lesson() const { return player_.has_value(); }
  const LessonPlayer* player() const { return player_ ? &*player_ : nullptr; }

  // A key's or a button's move; nothing without a lesson.
  void move(LessonMove move);

  // The caption folded to one line (the step and its title), so that the picture has the room;
  // `caption collapse|expand|toggle` and its key.
  bool caption_collapsed() const { return caption_collapsed_; }
  void toggle_caption() { caption_collapsed_ = !caption_collapsed_; }

  // `lesson next|prev|goto N`, `lang es|en`, `dump-lesson FILE`, `caption collapse|expand|toggle`
  // (checked by lesson_verb_problem).
  // False with `error` set when there is no lesson, N is not a step or the file cannot be written.
  bool run_verb(const ScriptCommand& command, std::string& error);

  // Plays this frame's share of the moves' commands on `viewer`; false with `error`
  // ("LESSON:LINE: ...") when one fails.
  bool step(ScriptTarget& viewer, std::string& error);
  // Commands of a move still to play (the viewer is busy for its script meanwhile). While the
  // classroom itself plays them the answer is false, so its runner waits only for what the
  // viewer does, not for itself.
  bool moving() const { return !stepping_ && !moves_.empty(); }

  // The step's caption box at the top of the dock beside or below the picture (origin and size:
  // the dock's), `margin` from its edges, its text 1.25 times the panel's at `ui_scale` 1 (the
  // UI scale is in the font already; a larger one is not enlarged further): the back row reads
  // it, and it covers nothing of the picture. Moves asked by its buttons are queued. Returns the
  // height the whole caption asks for (window units, margins included, however much of it the
  // dock shows), 0 without a lesson: the next frame's dock below the picture is made that high.
  // `hint`, when given, is draw_lesson_caption's.
  float draw_caption(glm::vec2 origin, glm::vec2 size, float margin, float ui_scale, const char* hint = nullptr);

private:
  void queue(std::vector<ScriptCommand> commands);

  std::optional<LessonPlayer> player_;
  std::deque<ScriptRunner> moves_;
  bool stepping_ = false;
  bool caption_collapsed_ = false;
};

}  // namespace luz::app
