#include "app/classroom/classroom.h"

#include <algorithm>
#include <utility>

#include "app/common/i18n.h"

namespace luz::app {

Classroom::Classroom(Lesson lesson) : player_(LessonPlayer(std::move(lesson))) { queue(player_->go_to(0)); }

void Classroom::queue(std::vector<ScriptCommand> commands) {
  Script script;
  script.file = player_->lesson().file;
  // Slide 36's window is closed unless the step opens it, as every other switch goes back to
  // its default: it would cover the next steps' picture.
  const bool opens_solvers = std::any_of(commands.begin(), commands.end(), [](const ScriptCommand& c) {
    return c.verb == "solvers" || c.verb == "wait-solver-rows";
  });
  if (!opens_solvers) script.commands.push_back({player_->step().line, "solvers", {"close"}});
  for (ScriptCommand& c : commands) script.commands.push_back(std::move(c));
  moves_.emplace_back(std::move(script));
}

void Classroom::move(LessonMove move) {
  if (!player_ || move == LessonMove::none) return;
  const size_t before = player_->index();
  std::vector<ScriptCommand> commands = move == LessonMove::next ? player_->next() : player_->previous();
  if (player_->index() != before) queue(std::move(commands));
}

bool Classroom::run_verb(const ScriptCommand& command, std::string& error) {
  if (command.verb == "lang") {
    i18n::set_language(*i18n::parse_language(command.args[0]));
    return true;
  }
  if (!player_) {
    error = tr("no lesson is open (luz --lesson [FILE])");
    return false;
  }
  if (command.verb == "caption") {
    const std::string& how = command.args[0];
    caption_collapsed_ = how == "toggle" ? !caption_collapsed_ : how == "collapse";
    return true;
  }
  std::vector<ScriptCommand> commands;
  if (!player_->run(command, commands, error)) return false;
  if (command.verb == "lesson") queue(std::move(commands));
  return true;
}

bool Classroom::step(ScriptTarget& viewer, std::string& error) {
  stepping_ = true;
  bool ok = true;
  // One move at a time, in the order asked; a finished one gives way to the next in this frame.
  while (!moves_.empty() && ok) {
    ok = moves_.front().step(viewer, error);
    if (!moves_.front().finished()) break;
    moves_.pop_front();
  }
  if (!ok) moves_.clear();
  stepping_ = false;
  return ok;
}

float Classroom::draw_caption(glm::vec2 origin, glm::vec2 size, float margin, float ui_scale, const char* hint) {
  if (!player_) return 0.0f;
  const float width = std::max(size.x - 2.0f * margin, 1.0f);
  const ImVec2 top_left(origin.x + margin, origin.y + margin);
  // 1.25 times the panel's text at a UI scale of 1; an interface already enlarged for the back
  // row (--ui-scale 1.25 and up) is read there as it is, and leaves the picture its room. A
  // dock too small for the whole text (a large interface beside the panel) gets it smaller
  // rather than cut, down to 0.7 times the panel's text at a UI scale of 1 (11 pixels).
  CaptionText text;
  text.scale = std::max(1.25f / ui_scale, 1.0f);
  text.least_scale = std::min(0.7f / ui_scale, text.scale);
  text.collapsed = caption_collapsed_;
  text.hint = hint;
  const CaptionResult result =
      draw_lesson_caption(*player_, i18n::language(), top_left, width, size.y - 2.0f * margin, text);
  move(result.move);
  if (result.toggle_collapsed) toggle_caption();
  return result.wanted_height + 2.0f * margin;
}

}  // namespace luz::app
