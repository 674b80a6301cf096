#include "app/viewer/switch_verbs.h"

#include <algorithm>
#include <optional>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/common/i18n.h"
#include "app/common/model_registry.h"
#include "app/common/option_row.h"
#include "app/viewer/viewer_settings.h"
#include "app/viewer/viewer_window.h"

namespace luz::app {
namespace {

// What a switch's key has always said, "ambient I_A" + on / off (message ids); a switch with no
// words here clears the status line instead.
struct SwitchNote {
  const char* name;
  const char* note;
};
constexpr SwitchNote notes[] = {
    {"ambient", N_("ambient I_A")},       {"diffuse", N_("diffuse I_D")},
    {"specular", N_("specular I_S")},     {"emission", N_("emission Le")},
    {"textures", N_("kd texture")},       {"shadows", N_("shadows S_i")},
    {"transparency", N_("transparency kt")}, {"reflection-map", N_("reflection map kr Ir")},
};

// The setting's value as dump-state's "settings" holds it: the viewer's own, else its row's.
nlohmann::json current(const ViewerState& state, const std::string& name) {
  const nlohmann::json settings = settings_json(state);
  if (settings["viewer"].contains(name)) return settings["viewer"][name];
  if (const std::optional<FoundOption> option = find_option(name))
    return settings[option->table->name][option->row->name];
  return nullptr;
}

std::span<const char* const> choices_of(const std::string& name) {
  const std::optional<FoundOption> option = find_option(name);
  if (option && option->row->kind == OptionKind::choice) return option->row->choices;
  return {};
}

}  // namespace

// A switch is what `set NAME on` accepts.
std::string check_toggle(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return check_setting(c.args[0], "on").empty() ? "" : fmt::format("\"{}\" is not a switch to toggle", c.args[0]);
}

bool run_toggle(Viewer& v, const ScriptCommand& c, std::string& error) {
  ViewerState& state = v.state();
  const std::string& name = c.args[0];
  const bool on = !current(state, name).get<bool>();
  if (!apply_setting(state, name, on ? "on" : "off", error)) return false;
  state.note.clear();
  if (name == "blinn") state.note = on ? tr("Blinn's N·H") : tr("Phong's R·V");
  for (const SwitchNote& n : notes)
    if (name == n.name) state.note = fmt::format("{} {}", tr(n.note), on ? tr("on") : tr("off"));
  return true;
}

std::string check_cycle(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return choices_of(c.args[0]).empty() ? fmt::format("\"{}\" is not a choice to cycle", c.args[0]) : "";
}

bool run_cycle(Viewer& v, const ScriptCommand& c, std::string& error) {
  ViewerState& state = v.state();
  const std::string& name = c.args[0];
  const std::span<const char* const> choices = choices_of(name);
  const std::string now = current(state, name).get<std::string>();
  const auto at = std::find_if(choices.begin(), choices.end(), [&](const char* choice) { return now == choice; });
  const std::string next = at == choices.end() || at + 1 == choices.end() ? choices.front() : *(at + 1);
  if (!apply_setting(state, name, next, error)) return false;
  state.note = name == "fog" ? trf("fog {}", tr(next.c_str())) : "";
  return true;
}

std::string check_attenuation(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  const std::string& a = c.args[0];
  return a == "toggle" || a == "inverse-square" || a == "classroom"
             ? "" : "`attenuation` takes toggle, inverse-square or classroom";
}

// Every light at once: toggle goes to the classroom's f_att unless every light already has it.
bool run_attenuation(Viewer& v, const ScriptCommand& c, std::string&) {
  ViewerState& state = v.state();
  std::vector<Light>& lights = state.scene->lights;
  const bool all_classroom =
      std::all_of(lights.begin(), lights.end(), [](const Light& l) { return l.attenuation.classroom; });
  const bool classroom = c.args[0] == "toggle" ? !all_classroom : c.args[0] == "classroom";
  for (Light& light : lights) light.attenuation.classroom = classroom;
  state.note = classroom ? "f_att = 1/(c0 + c1·d + c2·d²)" : "f_att = 1/d²";
  return true;
}

std::string check_exposure_step(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  const std::string& a = c.args[0];
  return (a.starts_with('+') || a.starts_with('-')) && is_number(a.substr(1))
             ? "" : "`exposure` takes a signed number of stops (+0.5, -1)";
}

bool run_exposure_step(Viewer& v, const ScriptCommand& c, std::string&) {
  ViewerState& state = v.state();
  state.exposure += std::stof(c.args[0]);
  state.note = trf("exposure {:+.1f} EV", state.exposure);
  return true;
}

std::string check_interface(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return c.args[0] == "larger" || c.args[0] == "smaller" ? "" : "`interface` takes larger or smaller";
}

bool run_interface(Viewer& v, const ScriptCommand& c, std::string&) {
  v.set_ui_scale(c.args[0] == "larger" ? v.user_scale() * kUiScaleStep : v.user_scale() / kUiScaleStep);
  return true;
}

}  // namespace luz::app
