#include "app/script/script.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "app/common/model_registry.h"
#include "core/error.h"

namespace luz::app {

std::optional<WaitLength> parse_wait(const std::string& text) {
  if (is_int(text)) {
    if (std::stoi(text) < 0) return std::nullopt;
    return WaitLength{std::stoi(text), std::nullopt};
  }
  if (text.ends_with("ms")) {
    const std::string number = text.substr(0, text.size() - 2);
    if (!is_int(number) || std::stoi(number) < 0) return std::nullopt;
    return WaitLength{0, std::chrono::milliseconds(std::stoi(number))};
  }
  if (text.ends_with("s")) {
    const std::string number = text.substr(0, text.size() - 1);
    if (!is_number(number) || std::stof(number) < 0.0f || std::stof(number) > 3600.0f) return std::nullopt;
    return WaitLength{0, std::chrono::milliseconds(std::lround(1000.0 * std::stod(number)))};
  }
  return std::nullopt;
}

std::string check_count(const ScriptCommand& c, size_t low, size_t high) {
  if (c.args.size() >= low && c.args.size() <= high) return "";
  if (low == high) return fmt::format("`{}` takes {} argument{}", c.verb, low, low == 1 ? "" : "s");
  return fmt::format("`{}` takes {} to {} arguments", c.verb, low, high);
}

std::string check_json_file(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return c.args[0].ends_with(".json") ? "" : fmt::format("`{}` writes a .json file", c.verb);
}

const ScriptVerb* find_verb(std::string_view name) {
  for (const ScriptVerb& v : common_verbs())
    if (name == v.name) return &v;
  for (const ModelEntry& m : models())
    for (const ScriptVerb& v : m.verbs)
      if (name == v.name) return &v;
  return nullptr;
}

namespace {

// The words of a line: split at spaces, a word in double quotes kept whole (without them);
// a word starting with # ends the line.
std::vector<std::string> words_of(const std::string& line) {
  std::vector<std::string> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i >= line.size() || line[i] == '#') break;
    if (line[i] == '"') {
      const size_t close = line.find('"', i + 1);
      const size_t end = close == std::string::npos ? line.size() : close;
      words.push_back(line.substr(i + 1, end - i - 1));
      i = end + 1;
      continue;
    }
    const size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    words.push_back(line.substr(start, i - start));
  }
  return words;
}

}  // namespace

Script parse_script_text(const std::string& text, const std::filesystem::path& name) {
  Script script;
  script.file = name;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::vector<std::string> words = words_of(line);
    if (words.empty()) continue;
    ScriptCommand command;
    command.line = number;
    command.verb = words[0];
    command.args.assign(words.begin() + 1, words.end());
    const ScriptVerb* verb = find_verb(command.verb);
    const std::string problem = verb ? verb->check(command) : fmt::format("unknown command \"{}\"", command.verb);
    if (!problem.empty())
      throw Error(ErrorKind::usage, fmt::format("{}:{}: {}", name.string(), number, problem));
    script.commands.push_back(std::move(command));
  }
  return script;
}

Script parse_script(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw Error(ErrorKind::usage, fmt::format("{}: cannot read the script", file.string()));
  std::stringstream text;
  text << in.rdbuf();
  return parse_script_text(text.str(), file);
}

std::string ScriptRunner::position() const {
  const std::string file = script_.file.string();
  if (next_ == 0) return fmt::format("{}: before the first command", file);
  const ScriptCommand& c = script_.commands[next_ - 1];
  std::string words = c.verb;
  for (const std::string& a : c.args) words += " " + a;
  return fmt::format("{}:{} `{}`{}", file, c.line, words, next_ >= script_.commands.size() ? " (the last)" : "");
}

bool ScriptRunner::step(ScriptTarget& target, std::string& error) {
  if (waiting_ > 0) {
    --waiting_;
    return true;
  }
  if (wait_until_) {
    if (now_() < *wait_until_) return true;
    wait_until_.reset();
  }
  if (target.busy()) return true;
  if (until_) {
    if (!target.holds(until_->args[0])) {
      if (--until_frames_left_ > 0) return true;
      error = fmt::format("{}:{}: `wait-until {}` did not hold within {} frames", script_.file.string(), until_->line,
                          until_->args[0], until_->args[1]);
      return false;
    }
    until_ = nullptr;
  }
  while (next_ < script_.commands.size()) {
    const ScriptCommand& command = script_.commands[next_++];
    if (command.verb == "wait") {
      const WaitLength length = *parse_wait(command.args[0]);  // checked when the script was read
      if (length.time) {
        wait_until_ = now_() + *length.time;
        return true;
      }
      waiting_ = length.frames;
      if (waiting_ > 0) --waiting_;  // this frame is the first of them
      return true;
    }
    if (command.verb == "wait-until") {
      until_ = &command;
      until_frames_left_ = std::stoi(command.args[1]);
      return true;  // checked from the next frame on, after the frame drawn now
    }
    std::string problem;
    if (!target.run(command, problem)) {
      error = fmt::format("{}:{}: {}", script_.file.string(), command.line, problem);
      return false;
    }
    const ScriptVerb* verb = find_verb(command.verb);
    if (verb && verb->ends_frame) return true;
  }
  return true;
}

}  // namespace luz::app
