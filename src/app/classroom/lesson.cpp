// The lesson file of lesson.h. Sections: [where in the file] [reading a step] [commands] [player]
#include "app/classroom/lesson.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "app/common/json_file.h"
#include "app/common/model_registry.h"
#include "app/common/options_tables.h"
#include "app/common/radiosity_drive.h"
#include "app/cli/render_command.h"
#include "core/error.h"
#include "core/resources.h"
#include "local/local_options.h"
#include "radiosity/radiosity_options.h"
#include "raytracing/whitted_options.h"

namespace luz::app {
namespace {

using nlohmann::json;
constexpr int kLectureSlides = 44;  // "Síntesis realista de imágenes" ends at slide 44

// ---- [where in the file] ------------------------------------------------------------------
// nlohmann::json keeps no positions, so a second pass through its SAX interface notes the line
// of every value by its JSON pointer ("/steps/3/model"), reading the text through an iterator
// that counts the characters the parser has taken.

struct CountingIterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;
  const char* at = nullptr;
  const char** furthest = nullptr;  // shared with the line recorder
  reference operator*() const { return *at; }
  CountingIterator& operator++() {
    *furthest = ++at;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountingIterator& other) const { return at == other.at; }
};

class LineRecorder : public nlohmann::json_sax<json> {
public:
  LineRecorder(const std::string& text, const char** furthest) : text_(text), furthest_(furthest) {}
  std::map<std::string, int> lines;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool key(string_t& name) override {
    frames_.back().key = name;
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

private:
  struct Frame {
    std::string pointer;
    bool array = false;
    size_t index = 0;
    std::string key;
  };
  // The line of the last character the parser took, not counting the white space it read ahead.
  int line_now() const {
    size_t end = size_t(*furthest_ - text_.data());
    while (end > 0 && std::isspace(static_cast<unsigned char>(text_[end - 1]))) --end;
    return 1 + int(std::count(text_.begin(), text_.begin() + std::ptrdiff_t(end), '\n'));
  }
  std::string here() {
    if (frames_.empty()) return "";
    Frame& f = frames_.back();
    return f.pointer + "/" + (f.array ? std::to_string(f.index++) : f.key);
  }
  bool value() {
    lines[here()] = line_now();
    return true;
  }
  bool open(bool array) {
    const std::string pointer = here();
    lines[pointer] = line_now();
    frames_.push_back({pointer, array, 0, {}});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return true;
  }
  const std::string& text_;
  const char** furthest_;
  std::vector<Frame> frames_;
};

int line_of_byte(const std::string& text, size_t byte) {
  byte = std::min(byte, text.size());
  return 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(byte), '\n'));
}

// ---- [reading a step] ---------------------------------------------------------------------

class Reader {
public:
  Reader(const std::filesystem::path& name, std::map<std::string, int> lines)
      : name_(name.string()), lines_(std::move(lines)) {}

  int line(const std::string& pointer) const {
    const auto it = lines_.find(pointer);
    return it == lines_.end() ? 1 : it->second;
  }

  // "FILE:LINE: what": the line of the value at `pointer`.
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw Error(ErrorKind::usage, fmt::format("{}:{}: {}", name_, line(pointer), what));
  }

  void only_keys(const json& object, const std::string& pointer, const std::string& what,
                 const std::vector<std::string>& allowed) const {
    if (!object.is_object()) fail(pointer, trf("{} must be an object", what));
    for (const auto& [key, value] : object.items())
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
        fail(pointer + "/" + key, trf("{}: unknown key \"{}\" (known: {})", what, key, fmt::join(allowed, ", ")));
  }

  LessonText text(const json& object, const std::string& pointer, const std::string& what) const {
    if (!object.is_object()) fail(pointer, trf("{} must be an object with \"es\" and \"en\"", what));
    only_keys(object, pointer, what, {"es", "en"});
    LessonText out;
    for (const char* language : {"es", "en"}) {
      if (!object.contains(language)) fail(pointer, trf("{}: the \"{}\" text is missing", what, language));
      const json& value = object[language];
      if (!value.is_string() || value.get<std::string>().empty())
        fail(pointer + "/" + language, trf("{}: \"{}\" must be a text that is not empty", what, language));
      (std::string(language) == "es" ? out.es : out.en) = value.get<std::string>();
    }
    return out;
  }

  bool boolean(const json& value, const std::string& pointer, const std::string& what) const {
    if (!value.is_boolean()) fail(pointer, trf("{} must be true or false", what));
    return value.get<bool>();
  }

  long integer(const json& value, const std::string& pointer, const std::string& what, long low, long high) const {
    if (!value.is_number_integer() || value.get<long>() < low || value.get<long>() > high)
      fail(pointer, trf("{} must be a whole number in {} .. {}", what, low, high));
    return value.get<long>();
  }

  double number(const json& value, const std::string& pointer, const std::string& what, double low, double high,
                bool low_open = false) const {
    const bool fits = value.is_number() && std::isfinite(value.get<double>()) &&
                      (low_open ? value.get<double>() > low : value.get<double>() >= low) && value.get<double>() <= high;
    if (!fits) fail(pointer, trf("{} must be a number in {}{} .. {}]", what, low_open ? "(" : "[", low, high));
    return value.get<double>();
  }

  std::string one_of(const json& value, const std::string& pointer, const std::string& what,
                     const std::vector<std::string>& names) const {
    if (!value.is_string() || std::find(names.begin(), names.end(), value.get<std::string>()) == names.end())
      fail(pointer, trf("{} must be one of {}{}", what, fmt::join(names, ", "),
                                value.is_string() ? trf(" (not \"{}\")", value.get<std::string>()) : ""));
    return value.get<std::string>();
  }

private:
  std::string name_;
  std::map<std::string, int> lines_;
};

// The models a lesson can show: every model of the registry.
const std::vector<std::string>& viewer_models() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const ModelEntry& m : models()) list.push_back(m.name);
    return list;
  }();
  return names;
}

// A pane may also show a headless model (luz render draws the panes).
const std::vector<std::string>& all_models() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const ModelEntry& m : models()) list.push_back(m.name);
    return list;
  }();
  return names;
}

std::string on_off(bool on) { return on ? "on" : "off"; }

// A step's value for an options row, in the words `set` takes, checked by the row (the check the
// flags and `set` make): true or false for a switch, a name for a choice, a number else.
std::string row_value(const Reader& r, const OptionRow& row, const json& value, const std::string& pointer,
                      const std::string& what) {
  if (row.kind == OptionKind::on_off) return on_off(r.boolean(value, pointer, what));
  std::string text;
  if (row.kind == OptionKind::choice && value.is_string()) text = value.get<std::string>();
  if (row.kind == OptionKind::integer && value.is_number_integer()) text = std::to_string(value.get<long long>());
  if (row.kind == OptionKind::real && value.is_number()) text = fmt::format("{}", value.get<double>());
  if (text.empty() || !parse_value(row, text, false))
    r.fail(pointer, trf("{} must be {}", what, accepted_text(row, Wording::translated)));
  if (!parse_value(row, text)) r.fail(pointer, trf("{} must be {}", what, tr(row.rule_text)));
  return text;
}

// The options tables a lesson's step names by their own key ("path": {"seed": 3}): the models'
// own tables. The shared ones have the lecture's groups below (terms, effects, whitted, radiosity).
bool shared_table(const OptionTable& table) {
  return &table == &local_table() || &table == &whitted_table() || &table == &radiosity_table();
}

ScriptCommand command(int line, std::string verb, std::vector<std::string> args) {
  return {line, std::move(verb), std::move(args)};
}

// ---- [commands] ----------------------------------------------------------------------------
// Each group emits every one of its switches: the step's value, else the options' default.

// A lesson's group of switches over a shared options table: the rows it takes are the table's, by
// a rule on the row, so a row added to the table is a lesson's key with nothing else to write.
struct SwitchGroup {
  const char* key;                 // the step's key: "terms", "effects", "whitted"
  const OptionTable& (*table)();
  bool (*takes)(const OptionRow&);
};

constexpr SwitchGroup switch_groups[] = {
    // I = I_A + I_D + I_S (+ Le), the kd texture and Blinn: the local table's rows that the tracers
    // and the hybrid take too (their flag groups are not the local models' own "local").
    {"terms", local_table, [](const OptionRow& row) { return std::string_view(row.group) != "local"; }},
    // Slide 19's other possibilities, switched or chosen (their distances, biases and map sizes are
    // the panel's to tune).
    {"effects", local_table,
     [](const OptionRow& row) {
       return std::string_view(row.group) == "local" && (row.kind == OptionKind::on_off || row.kind == OptionKind::choice);
     }},
    // The Whitted tracer's flags (the rows without one are the panel's to tune).
    {"whitted", whitted_table, [](const OptionRow& row) { return row.flag != nullptr && in_viewer(row); }},
};

// `set NAME VALUE`'s name of a row: NAME, or TABLE.NAME when an earlier table has a row of that name.
std::string set_name(const OptionTable& table, const OptionRow& row) {
  return find_option(row.name)->row == &row ? std::string(row.name) : std::string(table.name) + "." + row.name;
}

void switch_group(const Reader& r, const json& step, const std::string& at, int line, const SwitchGroup& group,
                  std::vector<ScriptCommand>& out) {
  const OptionTable& table = group.table();
  const json given = step.value(group.key, json::object());
  const std::string p = at + "/" + group.key;
  std::vector<std::string> names;
  for (const OptionRow& row : table.rows)
    if (group.takes(row)) names.push_back(row.name);
  r.only_keys(given, p, group.key, names);
  for (const OptionRow& row : table.rows) {
    if (!group.takes(row)) continue;
    const std::string value = given.contains(row.name)
                                  ? row_value(r, row, given[row.name], p + "/" + row.name,
                                              std::string(group.key) + ": " + row.name)
                                  : default_text(table, row);
    out.push_back(command(line, "set", {set_name(table, row), value}));
  }
}

// The `radiosity` verb's switches (the display's, the drive's) and the settings of the mesh and
// its form factors (slide 40), from the lists the verb runs on: a switch or mesh setting added
// there is a lesson's key with nothing else to write. The time budget is written only when given.
void radiosity(const Reader& r, const json& step, const std::string& at, int line, std::vector<ScriptCommand>& out) {
  const RadiosityOptions options;
  const RadiosityDrive drive;
  const json given = step.value("radiosity", json::object());
  const std::string p = at + "/radiosity";
  std::vector<std::string> keys;
  for (const RadiositySwitch& sw : radiosity_switches()) keys.push_back(sw.name);
  for (const char* name : radiosity_mesh_settings()) keys.push_back(name);
  keys.push_back("budget");
  r.only_keys(given, p, "radiosity", keys);
  for (const RadiositySwitch& sw : radiosity_switches()) {
    const bool on = sw.drive ? drive.*sw.drive : options.*sw.option;
    const bool value = given.contains(sw.name) ? r.boolean(given[sw.name], p + "/" + sw.name, std::string("radiosity: ") + sw.name) : on;
    out.push_back(command(line, "radiosity", {sw.name, on_off(value)}));
  }
  for (const char* name : radiosity_mesh_settings()) {
    const OptionRow& row = *find_row(radiosity_table(), name);
    const std::string value = given.contains(name)
                                  ? row_value(r, row, given[name], p + "/" + name, std::string("radiosity: ") + name)
                                  : default_text(radiosity_table(), row);
    out.push_back(command(line, "radiosity", {name, value}));
  }
  if (given.contains("budget"))
    out.push_back(command(line, "radiosity", {"budget", fmt::format("{}", float(r.number(given["budget"], p + "/budget",
                                                                                         "radiosity: budget (ms)", 0.0, 1000.0, true)))}));
}

// A model's own table: `set TABLE.NAME VALUE` for each row the step gives (the others are left
// as they are: such a table's viewer start may differ from its defaults, as the path tracer's).
void model_options(const Reader& r, const json& step, const std::string& at, int line, std::vector<ScriptCommand>& out) {
  for (const OptionTable* table : option_tables()) {
    if (shared_table(*table) || !step.contains(table->name)) continue;
    const json& given = step[table->name];
    const std::string p = at + "/" + table->name;
    std::vector<std::string> names;
    for (const OptionRow& row : table->rows)
      if (in_viewer(row)) names.push_back(row.name);
    r.only_keys(given, p, table->name, names);
    for (const auto& [name, value] : given.items()) {
      const OptionRow& row = *find_row(*table, name);
      const std::string text = row_value(r, row, value, p + "/" + name, std::string(table->name) + ": " + name);
      out.push_back(command(line, "set", {std::string(table->name) + "." + name, text}));
    }
  }
}

// What a step may ask of its models: solving needs radiosity or the hybrid shown, tracing a
// traced model shown or in one of its panes (`trace` traces every traced pane).
void actions(const Reader& r, const json& step, const std::string& at, int line, const std::string& model,
             const std::vector<std::string>& panes, std::vector<ScriptCommand>& out) {
  if (!step.contains("actions")) return;
  const json& list = step["actions"];
  if (!list.is_array()) r.fail(at + "/actions", tr("actions must be a list"));
  const bool solves = model == "radiosity" || model == "hybrid";
  const auto traced = [](const std::string& m) { return m == "whitted" || m == "hybrid"; };
  const bool traces = traced(model) || std::any_of(panes.begin(), panes.end(), traced);
  auto need = [&](bool ok, const std::string& pointer, const std::string& action, const char* models) {
    if (!ok) r.fail(pointer, trf("action \"{}\" needs the model {} (this step shows {})", action, models, model));
  };
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string a = fmt::format("{}/actions/{}", at, i);
    const json& action = list[i];
    if (action.is_string()) {
      const std::string name = r.one_of(action, a, tr("an action"),
                                        {"run-solver", "pause-solver", "reset-solver", "trace", "open-solvers", "run-solvers"});
      if (name.ends_with("-solver")) {
        need(solves, a, name, tr("radiosity or hybrid"));
        out.push_back(command(line, "radiosity", {name.substr(0, name.find('-'))}));
      } else if (name == "trace") {
        need(traces, a, name, tr("whitted or hybrid"));
        out.push_back(command(line, "trace", {"--no-wait"}));  // the class watches the tiles come
      } else {
        out.push_back(command(line, "solvers", {name.substr(0, name.find('-'))}));
      }
      continue;
    }
    if (!action.is_object() || action.size() != 1)
      r.fail(a, tr("an action is a name (run-solver, trace, ...) or one of {\"shots\": N}, {\"solver-steps\": N}, {\"click\": [X, Y]}"));
    const std::string key = action.begin().key();
    const json& value = action.begin().value();
    if (key == "shots" || key == "solver-steps") {
      need(solves, a, key, tr("radiosity or hybrid"));
      const long n = r.integer(value, a + "/" + key, key, 1, 1000000);
      out.push_back(key == "shots" ? command(line, "wait-shots", {std::to_string(n)})
                                   : command(line, "radiosity", {"step", std::to_string(n)}));
    } else if (key == "click") {
      // A point of the picture as fractions of the square as high as the picture, centred in it:
      // the same object under the click whatever the window's size, the panel's width or the UI
      // scale (click-picture X% Y%).
      if (!value.is_array() || value.size() != 2)
        r.fail(a + "/click", tr("click takes [X, Y], fractions of the picture's height, X from the left of its centred square"));
      const double x = r.number(value[0], a + "/click/0", "click X", 0.0, 0.999);
      const double y = r.number(value[1], a + "/click/1", "click Y", 0.0, 0.999);
      out.push_back(command(line, "click-picture", {fmt::format("{:g}%", 100.0 * x), fmt::format("{:g}%", 100.0 * y)}));
    } else {
      r.fail(a + "/" + key, trf("unknown action \"{}\" (shots, solver-steps, click)", key));
    }
  }
}

LessonStep read_step(const Reader& r, const json& step, size_t index, const std::filesystem::path& folder,
                     const LessonStep* before) {
  const std::string at = fmt::format("/steps/{}", index);
  std::vector<std::string> keys = {"slide", "title", "text", "scene", "camera", "model", "exposure", "radiosity",
                                   "panes", "actions"};
  for (const SwitchGroup& group : switch_groups) keys.push_back(group.key);
  for (const OptionTable* table : option_tables())
    if (!shared_table(*table)) keys.push_back(table->name);
  r.only_keys(step, at, trf("step {}", index + 1), keys);
  LessonStep out;
  if (!step.contains("slide")) r.fail(at, trf("step {}: \"slide\" is missing", index + 1));
  out.slide = int(r.integer(step["slide"], at + "/slide", "slide", 1, kLectureSlides));
  for (const char* key : {"title", "text"})
    if (!step.contains(key)) r.fail(at, trf("step {}: \"{}\" is missing", index + 1, key));
  out.title = r.text(step["title"], at + "/title", "title");
  out.text = r.text(step["text"], at + "/text", "text");

  if (step.contains("scene")) {
    if (!step["scene"].is_string()) r.fail(at + "/scene", tr("scene must be a file name"));
    const std::filesystem::path scene = (folder / step["scene"].get<std::string>()).lexically_normal();
    if (!std::filesystem::is_regular_file(scene))
      r.fail(at + "/scene", trf("scene {} does not exist", scene.string()));
    out.scene = scene.string();
  } else if (before) {
    out.scene = before->scene;
  } else {
    r.fail(at, tr("the first step must name a \"scene\""));
  }
  if (step.contains("camera")) {
    const json& camera = step["camera"];
    if (camera.is_number_integer()) out.camera = std::to_string(r.integer(camera, at + "/camera", "camera", 0, 1000));
    else if (camera.is_string() && !camera.get<std::string>().empty() &&
             camera.get<std::string>().find_first_of(" \t") == std::string::npos) out.camera = camera.get<std::string>();
    else r.fail(at + "/camera", tr("camera is an index or a name without spaces"));
  } else if (before && before->scene == out.scene) {
    out.camera = before->camera;
  }
  if (step.contains("model")) out.model = r.one_of(step["model"], at + "/model", "model", viewer_models());
  else if (before) out.model = before->model;
  else r.fail(at, tr("the first step must name a \"model\""));

  const int line = out.line = r.line(at);
  std::vector<ScriptCommand>& c = out.commands;
  c.push_back(command(line, "load", {out.scene}));
  c.push_back(command(line, "camera", {out.camera.empty() ? "0" : out.camera}));
  c.push_back(command(line, "model", {out.model}));
  if (step.contains("exposure"))
    c.push_back(command(line, "set", {"exposure", fmt::format("{}", float(r.number(step["exposure"], at + "/exposure",
                                                                                    "exposure (EV)", -20.0, 20.0)))}));
  for (const SwitchGroup& group : switch_groups) switch_group(r, step, at, line, group, c);
  radiosity(r, step, at, line, c);
  model_options(r, step, at, line, c);
  if (step.contains("panes")) {
    const json& panes = step["panes"];
    if (!panes.is_array() || (panes.size() != 2 && panes.size() != 4))
      r.fail(at + "/panes", tr("panes lists 2 or 4 models"));
    for (size_t i = 0; i < panes.size(); ++i)
      out.panes.push_back(r.one_of(panes[i], fmt::format("{}/panes/{}", at, i), tr("a pane's model"), all_models()));
  }
  c.push_back(command(line, "panes", {out.panes.empty() ? out.model : fmt::format("{}", fmt::join(out.panes, ","))}));
  actions(r, step, at, line, out.model, out.panes, c);
  return out;
}

}  // namespace

Lesson parse_lesson_text(const std::string& text, const std::filesystem::path& name) {
  json document;
  try {
    document = json::parse(text);
  } catch (const json::parse_error& error) {
    // nlohmann counts bytes; the message's own position text is dropped for our FILE:LINE.
    std::string what = error.what();
    if (const size_t colon = what.find("syntax error"); colon != std::string::npos) what = what.substr(colon);
    throw Error(ErrorKind::usage, trf("{}:{}: not JSON: {}", name.string(), line_of_byte(text, error.byte), what));
  }
  const char* furthest = text.data();
  LineRecorder recorder(text, &furthest);
  const CountingIterator first{text.data(), &furthest}, last{text.data() + text.size(), &furthest};
  json::sax_parse(first, last, &recorder);
  const Reader r(name, std::move(recorder.lines));

  Lesson lesson;
  lesson.file = name;
  r.only_keys(document, "", tr("the lesson"), {"title", "steps"});
  if (!document.contains("title")) r.fail("", tr("the lesson's \"title\" is missing"));
  lesson.title = r.text(document["title"], "/title", tr("the lesson's title"));
  if (!document.contains("steps") || !document["steps"].is_array() || document["steps"].empty())
    r.fail(document.contains("steps") ? "/steps" : "", tr("the lesson needs \"steps\", a list of at least one step"));
  const std::filesystem::path folder = name.parent_path();
  const json& steps = document["steps"];
  for (size_t i = 0; i < steps.size(); ++i)
    lesson.steps.push_back(read_step(r, steps[i], i, folder, i ? &lesson.steps.back() : nullptr));
  return lesson;
}

Lesson parse_lesson(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ErrorKind::usage, trf("{}: cannot read the lesson", file.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_lesson_text(text.str(), file);
}

std::filesystem::path default_lesson() { return lesson_dir() / "sintesis.json"; }

std::optional<std::string> lesson_verb_problem(const ScriptCommand& c) {
  const auto& a = c.args;
  if (c.verb == "lesson") {
    if (a.size() == 1 && (a[0] == "next" || a[0] == "prev")) return "";
    if (a.size() == 2 && a[0] == "goto") {
      int n = 0;
      const auto [end, ec] = std::from_chars(a[1].data(), a[1].data() + a[1].size(), n);
      if (ec == std::errc() && end == a[1].data() + a[1].size() && n >= 1) return "";
      return "`lesson goto N` takes a step number >= 1";
    }
    return "`lesson` takes next, prev or goto N";
  }
  if (c.verb == "lang")
    return a.size() == 1 && i18n::parse_language(a[0]) ? "" : "`lang` takes es or en";
  if (c.verb == "dump-lesson")
    return a.size() == 1 && a[0].ends_with(".json") ? "" : "`dump-lesson` writes a .json file";
  if (c.verb == "caption")
    return a.size() == 1 && (a[0] == "collapse" || a[0] == "expand" || a[0] == "toggle")
               ? "" : "`caption` takes collapse, expand or toggle";
  return std::nullopt;
}

// ---- [player] --------------------------------------------------------------------------------

LessonPlayer::LessonPlayer(Lesson lesson) : lesson_(std::move(lesson)) {
  // The viewer starts on the options' defaults: its mesh needs no rebuild for a step that keeps them.
  const RadiosityOptions defaults;
  mesh_settings_ = fmt::format("{} {} {} {}", defaults.patch_size, defaults.hemicube_res,
                               to_string(defaults.meshing), to_string(defaults.form_factors));
}

namespace {

// The settings whose change rebuilds the radiosity mesh (and restarts the solution).
bool is_mesh_setting(const ScriptCommand& c) { return c.verb == "radiosity" && is_radiosity_mesh_setting(c.args[0]); }

}  // namespace

std::vector<ScriptCommand> LessonPlayer::go_to(size_t index) {
  index_ = std::min(index, size() - 1);
  const LessonStep& s = step();
  std::string mesh;  // the step's mesh settings, in the order it gives them
  for (const ScriptCommand& c : s.commands)
    if (is_mesh_setting(c)) mesh += (mesh.empty() ? "" : " ") + c.args[1];
  std::vector<ScriptCommand> out;
  for (const ScriptCommand& c : s.commands) {
    if (c.verb == "load" && c.args[0] == loaded_scene_) continue;
    if (is_mesh_setting(c) && mesh == mesh_settings_) continue;
    if (c.verb == "panes" && s.panes.empty() && !showing_panes_) continue;
    out.push_back(c);
  }
  loaded_scene_ = s.scene;
  mesh_settings_ = mesh;
  showing_panes_ = !s.panes.empty();
  return out;
}

nlohmann::json LessonPlayer::to_json(i18n::Language language) const {
  const LessonStep& s = step();
  json j;
  j["lesson"] = lesson_.title.in(language);
  j["step"] = index_ + 1;
  j["steps"] = size();
  j["slide"] = s.slide;
  j["title"] = s.title.in(language);
  j["text"] = s.text.in(language);
  j["language"] = i18n::language_name(language);
  j["model"] = s.model;
  j["panes"] = s.panes;
  j["scene"] = s.scene;
  return j;
}

bool LessonPlayer::run(const ScriptCommand& c, std::vector<ScriptCommand>& to_run, std::string& error) {
  const auto& a = c.args;
  if (c.verb == "lesson") {
    if (a[0] == "next") to_run = next();
    if (a[0] == "prev") to_run = previous();
    if (a[0] == "goto") {
      const size_t n = size_t(std::stoul(a[1]));
      if (n < 1 || n > size()) {
        error = trf("the lesson has steps 1 .. {}, not {}", size(), n);
        return false;
      }
      to_run = go_to(n - 1);
    }
  } else if (c.verb == "lang") {
    i18n::set_language(*i18n::parse_language(a[0]));
  } else if (c.verb == "dump-lesson") {
    if (!write_json(a[0], to_json(i18n::language()))) {
      error = trf("{}: cannot write the lesson's step", a[0]);
      return false;
    }
  }
  return true;
}

}  // namespace luz::app
