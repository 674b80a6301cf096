// The script's common verbs, one table: name, usage, argument check, what the viewer does, and
// whether the next command must see it drawn. A model's own verbs (radiosity's, the tracer's)
// come with its registry entry.

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/common/json_file.h"
#include "app/common/i18n.h"
#include "app/classroom/lesson.h"
#include "app/viewer/inspector.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include "app/common/model_registry.h"
#include "app/viewer/panes.h"
#include "app/script/script.h"
#include "app/viewer/shortcuts.h"
#include "app/viewer/solvers_window.h"
#include "app/viewer/viewer_settings.h"
#include "app/viewer/viewer_window.h"
#include "app/viewer/switch_verbs.h"
#include "app/viewer/widget_verbs.h"
#include "app/viewer/screenshot.h"

namespace luz::app {
namespace {

std::string check_none(const ScriptCommand& c) { return check_count(c, 0, 0); }

std::string check_key(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  int key = 0, mods = 0;
  return parse_key(c.args[0], key, mods) ? "" : fmt::format("unknown key \"{}\"", c.args[0]);
}

std::string check_point(const ScriptCommand& c) {
  if (auto e = check_count(c, 2, 2); !e.empty()) return e;
  return is_int(c.args[0]) && is_int(c.args[1]) ? "" : "`click X Y` takes whole window coordinates";
}

std::string check_drag(const ScriptCommand& c) {
  if (auto e = check_count(c, 4, 5); !e.empty()) return e;
  for (size_t i = 0; i < 4; ++i)
    if (!is_int(c.args[i])) return "`drag X0 Y0 X1 Y1 [left|right]` takes whole window coordinates";
  if (c.args.size() == 5 && c.args[4] != "left" && c.args[4] != "right") return "the drag button is left or right";
  return "";
}

std::string check_number(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return is_number(c.args[0]) ? "" : fmt::format("`{}` takes a number", c.verb);
}

std::string check_wait(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return parse_wait(c.args[0]) ? "" : "`wait` takes frames (30), seconds (2s) or milliseconds (500ms)";
}

// `screenshot` and `screenshot --with-panel` alone: P's and Shift+P's, a new luz-SCENE-N.png.
std::string check_screenshot(const ScriptCommand& c) {
  if (auto e = check_count(c, 0, 2); !e.empty()) return e;
  if (c.args.empty() || (c.args.size() == 1 && c.args[0] == "--with-panel")) return "";
  if (c.args.size() == 2 && c.args[1] != "--with-panel" && c.args[1] != "--shown" && c.args[1] != "--quiet")
    return fmt::format("unknown option \"{}\"", c.args[1]);
  return c.args[0].ends_with(".png") ? "" : "screenshots are .png files";
}

std::string check_one(const ScriptCommand& c) { return check_count(c, 1, 1); }

// `camera` alone: back to the scene camera shown (C); `camera next`: the scene's next (N).
std::string check_camera(const ScriptCommand& c) { return check_count(c, 0, 1); }

std::string check_quit(const ScriptCommand& c) {
  if (auto e = check_count(c, 0, 1); !e.empty()) return e;
  return c.args.empty() || c.args[0] == "--ask" ? "" : fmt::format("unknown option \"{}\" (--ask)", c.args[0]);
}

std::string check_model(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return find_model(c.args[0]) ? "" : fmt::format("unknown model \"{}\" ({})", c.args[0], model_names());
}

std::string check_set(const ScriptCommand& c) {
  if (auto e = check_count(c, 2, 2); !e.empty()) return e;
  return check_setting(c.args[0], c.args[1]);
}

std::string check_resize(const ScriptCommand& c) {
  if (auto e = check_count(c, 2, 2); !e.empty()) return e;
  return is_int(c.args[0]) && is_int(c.args[1]) && std::stoi(c.args[0]) > 0 && std::stoi(c.args[1]) > 0
             ? "" : "`resize W H` takes a positive window size";
}

std::string check_solvers(const ScriptCommand& c) {
  const auto& a = c.args;
  if (a.empty()) return "`solvers` takes open, close, toggle, run, pause, reset, budget MS or patches N";
  const std::string& what = a[0];
  if (what == "open" || what == "close" || what == "toggle" || what == "run" || what == "pause" || what == "reset")
    return a.size() == 1 ? "" : fmt::format("`solvers {}` takes no value", what);
  if (a.size() != 2) return fmt::format("`solvers {}` takes one value", what);
  if (what == "budget") return is_number(a[1]) && std::stof(a[1]) > 0.0f ? "" : "`solvers budget MS` takes milliseconds > 0";
  if (what == "patches") return is_int(a[1]) && std::stoi(a[1]) >= 10 ? "" : "`solvers patches N` takes N >= 10";
  return fmt::format("unknown solvers setting \"{}\" (open, close, toggle, run, pause, reset, budget, patches)", what);
}

std::string check_rows(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return is_int(c.args[0]) && std::stoi(c.args[0]) >= 1 ? "" : "`wait-solver-rows N` takes a number of rows >= 1";
}

// ---- what the viewer does --------------------------------------------------------------------
bool run_key(Viewer& v, const ScriptCommand& c, std::string&) {
  int key = 0, mods = 0;
  unsigned character = 0;
  parse_key(c.args[0], key, mods, character);
  if (key != 0) v.press_key(key, mods);
  // A character's key, or the keypad's + and -, types its character too, as GLFW reports it.
  if (key == GLFW_KEY_KP_ADD) character = '+';
  if (key == GLFW_KEY_KP_SUBTRACT) character = '-';
  if (character != 0) v.typed(character);
  return true;
}

bool run_type(Viewer& v, const ScriptCommand& c, std::string&) {
  for (size_t i = 0; i < c.args.size(); ++i) {
    if (i > 0) v.typed(' ');
    for (const char ch : c.args[i]) v.typed(static_cast<unsigned char>(ch));
  }
  return true;
}

bool run_click(Viewer& v, const ScriptCommand& c, std::string&) {
  v.click_at(glm::vec2(std::stof(c.args[0]), std::stof(c.args[1])));
  return true;
}

bool run_idle(Viewer& v, const ScriptCommand& c, std::string&) {
  v.idle(std::stod(c.args[0]));
  return true;
}

std::string check_idle(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return is_number(c.args[0]) && std::stod(c.args[0]) > 0.0 ? "" : "`idle SECONDS` takes seconds > 0";
}

bool run_drag(Viewer& v, const ScriptCommand& c, std::string&) {
  const auto& a = c.args;
  const glm::vec2 from(std::stof(a[0]), std::stof(a[1])), to(std::stof(a[2]), std::stof(a[3]));
  v.drag(a.size() == 5 && a[4] == "right" ? DragButton::right : DragButton::left, to - from);
  return true;
}

bool run_scroll(Viewer& v, const ScriptCommand& c, std::string&) {
  v.zoom(std::stof(c.args[0]));
  return true;
}

bool run_screenshot(Viewer& v, const ScriptCommand& c, std::string&) {
  if (c.args.empty() || c.args[0] == "--with-panel") {  // named as P names it; a failure is said, not fatal
    const bool with_panel = !c.args.empty();
    v.state().note.clear();
    v.screenshot({next_screenshot_name(v.state().scene_path, with_panel), with_panel, false, ""});
    return true;
  }
  const std::string option = c.args.size() == 2 ? c.args[1] : "";
  v.screenshot({c.args[0], option == "--with-panel" || option == "--shown", option == "--shown",
                fmt::format("{}:{}", c.line, c.args[0]), option == "--quiet"});
  return true;
}

bool run_camera(Viewer& v, const ScriptCommand& c, std::string& error) {
  if (c.args.empty()) {
    v.state().note.clear();
    v.to_scene_camera();
    return true;
  }
  if (c.args[0] == "next") {
    v.next_camera();
    return true;
  }
  return v.choose_camera(c.args[0], error);
}

bool run_model(Viewer& v, const ScriptCommand& c, std::string&) {
  v.set_model(*find_model(c.args[0]));
  return true;
}

bool run_set(Viewer& v, const ScriptCommand& c, std::string& error) {
  if (c.args[0] == "ui-scale") {
    v.set_ui_scale(std::stof(c.args[1]));
    return true;
  }
  return apply_setting(v.state(), c.args[0], c.args[1], error);
}

bool run_resize(Viewer& v, const ScriptCommand& c, std::string&) {
  v.resize(std::stoi(c.args[0]), std::stoi(c.args[1]));
  return true;
}

bool run_load(Viewer& v, const ScriptCommand& c, std::string&) {
  v.load(c.args[0]);
  return true;
}

bool run_reload(Viewer& v, const ScriptCommand&, std::string&) {
  v.load(v.state().scene_path);
  return true;
}

bool run_dump_inspector(Viewer& v, const ScriptCommand& c, std::string& error) {
  const InspectorReading* reading = v.shown().inspector_reading();
  if (!reading) {
    error = "the inspector shows nothing: click an object in the picture first";
    return false;
  }
  return write_json(c.args[0], to_json(*v.state().scene, *reading), "the inspector's values", error);
}

bool run_dump_state(Viewer& v, const ScriptCommand& c, std::string& error) {
  const ViewerState& s = v.state();
  nlohmann::json j = {{"model", s.model}, {"exposure", s.exposure}, {"ui_scale", v.ui_scale()}, {"note", s.note}, {"load_error", s.error},
                      {"user_scale", v.user_scale()}, {"warnings", v.warnings()},
                      {"selected_material", s.selected_material}, {"idle_cpu_fraction", v.idle_cpu_fraction()},
                      {"show_help", s.show_help}, {"free_camera", s.free_camera},
                      {"language", i18n::language_name(i18n::language())}, {"settings", settings_json(s)},
                      {"frame_ms", s.frame_ms}, {"status_line", v.status_line()}, {"frames_drawn", v.frames_drawn()},
                      {"asking_to_quit", v.asking_to_quit()},
                      {"frame_phases_ms", {{"models", s.frame_phases.models_ms},
                                           {"exposure", s.frame_phases.exposure_ms},
                                           {"panel", s.frame_phases.panel_ms},
                                           {"panel_building", s.frame_phases.panel_building_ms},
                                           {"present", s.frame_phases.present_ms}}},
                      {"display_copy", {{"on", s.display_copy}, {"copied_panes", v.copied_panes()},
                                        {"direct", s.display_direct}, {"direct_panes", v.direct_panes()}}},
                      {"panel_cache", {{"on", v.panel_cache().enabled},
                                       {"hits", v.panel_cache().hits},
                                       {"redraws", v.panel_cache().redraws},
                                       {"kept", v.panel_cache().kept}}},
                      {"present_parts", {{"on", s.present_parts}, {"window_keeps_back_buffer", v.window_keeps_back_buffer()}}}};
  if (s.selected_material >= 0) j["material"] = s.scene->materials[size_t(s.selected_material)].name;
  // What the keys change beyond the settings: the scene's camera, the lights' f_att, the panes
  // and their traces, model 5's loop, slide 36's window, the lesson's step.
  j["scene_camera"] = s.scene_camera;
  j["classroom_attenuation"] = nlohmann::json::array();
  for (const Light& light : s.scene->lights) j["classroom_attenuation"].push_back(light.attenuation.classroom);
  j["panes"] = nlohmann::json::array();
  for (ModelView* pane : v.pane_views()) {
    const char* trace = pane->trace_state();
    j["panes"].push_back({{"trace", trace ? nlohmann::json(trace) : nlohmann::json(nullptr)}});
  }
  v.view("radiosity").dump_state(j);
  j["solvers_open"] = v.solvers().state().open;
  const LessonPlayer* lesson = v.classroom().player();
  j["lesson_step"] = lesson ? nlohmann::json(lesson->index() + 1) : nlohmann::json(nullptr);
  j["show_panel"] = s.show_panel;
  const char* hint = v.panel_hint();
  j["panel_hint"] = hint ? nlohmann::json(hint) : nlohmann::json(nullptr);
  return write_json(c.args[0], j, "the viewer's state", error);
}

std::string check_on_off(const ScriptCommand& c) {
  const bool on_or_off = c.args.size() == 1 && (c.args[0] == "on" || c.args[0] == "off");
  return on_or_off ? "" : fmt::format("`{}` takes on or off", c.verb);
}

// `panel-cache off`: the panel drawn every frame, to hold the cached frames against.
bool run_panel_cache(Viewer& v, const ScriptCommand& c, std::string&) {
  v.panel_cache().enabled = c.args[0] == "on";
  return true;
}

// `display-copy off`: the display pass over the radiance, to hold the copied frames against.
bool run_display_copy(Viewer& v, const ScriptCommand& c, std::string&) {
  v.state().display_copy = c.args[0] == "on";
  return true;
}

// `display-direct off`: the local models draw into their pictures on every frame, to hold the
// frames drawn straight into the window against.
bool run_display_direct(Viewer& v, const ScriptCommand& c, std::string&) {
  v.state().display_direct = c.args[0] == "on";
  return true;
}

// `present-parts off`: the panel copied into the window and the whole window shown on every
// frame, to hold the frames that keep the panel's pixels against.
bool run_present_parts(Viewer& v, const ScriptCommand& c, std::string&) {
  v.state().present_parts = c.args[0] == "on";
  return true;
}

// `status-time off`: the status line's frame time and figures held where they are, so that two
// pictures of the window taken frames apart can be compared whole.
bool run_status_time(Viewer& v, const ScriptCommand& c, std::string&) {
  v.state().status_ms_live = c.args[0] == "on";
  return true;
}

bool run_dump_windows(Viewer& v, const ScriptCommand& c, std::string& error) {
  return write_json(c.args[0], v.windows_json(), "the windows' rectangles", error);
}

bool run_solvers(Viewer& v, const ScriptCommand& c, std::string&) {
  const auto& a = c.args;
  SolversWindow& s = v.solvers();
  if (a[0] == "open") s.set_open(true);
  if (a[0] == "close") s.set_open(false);
  if (a[0] == "toggle") {  // J
    s.set_open(!s.state().open);
    v.state().note.clear();
  }
  if (a[0] == "run") {
    s.set_open(true);
    s.set_running(true);
  }
  if (a[0] == "pause") s.set_running(false);
  if (a[0] == "reset") s.reset();
  if (a[0] == "budget") s.set_budget(std::stof(a[1]));
  if (a[0] == "patches") s.set_patches(std::stoi(a[1]));
  return true;
}

bool run_wait_solver_rows(Viewer& v, const ScriptCommand& c, std::string&) {
  v.solvers().run_to_rows(size_t(std::stoul(c.args[0])));
  return true;
}

bool run_dump_solvers(Viewer& v, const ScriptCommand& c, std::string& error) {
  return write_json(c.args[0], to_json(v.solvers()), "the solvers' curves", error);
}

// `quit --ask`: Esc's, which asks first with a lesson open or work running.
bool run_quit(Viewer& v, const ScriptCommand& c, std::string&) {
  if (c.args.empty()) v.quit();
  else v.ask_to_quit();
  return true;
}

// The lesson's verbs: the classroom (classroom.h) moves and the viewer plays the step's commands.
std::string check_lesson_verb(const ScriptCommand& c) { return lesson_verb_problem(c).value_or(""); }

bool run_lesson_verb(Viewer& v, const ScriptCommand& c, std::string& error) {
  if (c.verb == "lesson") v.state().note.clear();  // the step says what it shows
  return v.classroom().run_verb(c, error);
}

// `wait` is the runner's own (it counts frames or time); it never reaches the viewer.
bool run_nothing(Viewer&, const ScriptCommand&, std::string&) { return true; }

// The common verbs act on the whole Viewer, the one ViewerServices there is; a model's verbs
// (its registry entry) get only the narrow interface.
template <bool (*run)(Viewer&, const ScriptCommand&, std::string&)>
bool on_viewer(ViewerServices& viewer, const ScriptCommand& command, std::string& error) {
  return run(static_cast<Viewer&>(viewer), command, error);
}

constexpr ScriptVerb verbs[] = {
    {"key", "key NAME", check_key, on_viewer<run_key>, false},
    {"type", "type TEXT", [](const ScriptCommand& c) { return c.args.empty() ? std::string("`type` takes the text to type") : std::string(); }, on_viewer<run_type>, true},
    {"click", "click X Y", check_point, on_viewer<run_click>, true},
    {"idle", "idle SECONDS", check_idle, on_viewer<run_idle>, true},
    {"drag", "drag X0 Y0 X1 Y1 [left|right]", check_drag, on_viewer<run_drag>, true},
    {"scroll", "scroll STEPS", check_number, on_viewer<run_scroll>, false},
    {"wait", "wait N|Ns|Nms", check_wait, on_viewer<run_nothing>, true},
    {"screenshot", "screenshot [FILE.png] [--with-panel|--shown|--quiet]", check_screenshot, on_viewer<run_screenshot>, true},
    {"camera", "camera [N|NAME|next]", check_camera, on_viewer<run_camera>, true},
    {"model", "model NAME", check_model, on_viewer<run_model>, false},
    {"set", "set NAME VALUE", check_set, on_viewer<run_set>, false},
    {"resize", "resize W H", check_resize, on_viewer<run_resize>, true},
    {"load", "load FILE", check_one, on_viewer<run_load>, true},
    {"reload", "reload", check_none, on_viewer<run_reload>, true},
    {"dump-inspector", "dump-inspector FILE.json", check_json_file, on_viewer<run_dump_inspector>, true},
    {"dump-state", "dump-state FILE.json", check_json_file, on_viewer<run_dump_state>, true},
    {"dump-windows", "dump-windows FILE.json", check_json_file, on_viewer<run_dump_windows>, true},
    {"panel-cache", "panel-cache on|off", check_on_off, on_viewer<run_panel_cache>, true},
    {"display-copy", "display-copy on|off", check_on_off, on_viewer<run_display_copy>, true},
    {"display-direct", "display-direct on|off", check_on_off, on_viewer<run_display_direct>, true},
    {"present-parts", "present-parts on|off", check_on_off, on_viewer<run_present_parts>, true},
    {"status-time", "status-time on|off", check_on_off, on_viewer<run_status_time>, true},
    {"solvers", "solvers open|close|toggle|run|pause|reset|budget MS|patches N", check_solvers, on_viewer<run_solvers>, true},
    {"wait-solver-rows", "wait-solver-rows N", check_rows, on_viewer<run_wait_solver_rows>, true},
    {"dump-solvers", "dump-solvers FILE.json", check_json_file, on_viewer<run_dump_solvers>, true},
    {"panes", "panes MODEL[,MODEL...]|off", check_panes, on_viewer<run_panes>, true},
    {"dump-panes", "dump-panes FILE.json", check_json_file, on_viewer<run_dump_panes>, true},
    {"lesson", "lesson next|prev|goto N", check_lesson_verb, on_viewer<run_lesson_verb>, true},
    {"lang", "lang es|en", check_lesson_verb, on_viewer<run_lesson_verb>, true},
    {"dump-lesson", "dump-lesson FILE.json", check_lesson_verb, on_viewer<run_lesson_verb>, true},
    {"caption", "caption collapse|expand|toggle", check_lesson_verb, on_viewer<run_lesson_verb>, true},
    {"quit", "quit [--ask]", check_quit, on_viewer<run_quit>, false},
    // The switches the keys flip (switch_verbs.h).
    {"toggle", "toggle NAME", check_toggle, on_viewer<run_toggle>, false},
    {"cycle", "cycle NAME", check_cycle, on_viewer<run_cycle>, false},
    {"attenuation", "attenuation toggle|inverse-square|classroom", check_attenuation, on_viewer<run_attenuation>, false},
    {"exposure", "exposure +EV|-EV", check_exposure_step, on_viewer<run_exposure_step>, false},
    {"interface", "interface larger|smaller", check_interface, on_viewer<run_interface>, false},
    // Widgets and pixels addressed by name, states waited for (widget_verbs.h).
    {"click-widget", "click-widget \"LABEL\"", check_click_widget, on_viewer<run_click_widget>, true},
    {"click-picture", "click-picture X Y", check_click_picture, on_viewer<run_click_picture>, true},
    {"dump-widgets", "dump-widgets FILE.json", check_json_file, on_viewer<run_dump_widgets>, true},
    {"wait-until", "wait-until trace-done|radiosity-done FRAMES", check_wait_until, on_viewer<run_nothing>, true},
};

}  // namespace

std::span<const ScriptVerb> common_verbs() { return verbs; }

}  // namespace luz::app
