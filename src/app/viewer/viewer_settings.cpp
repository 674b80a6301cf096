#include "app/viewer/viewer_settings.h"

#include <fmt/format.h>

#include "app/common/model_registry.h"
#include "app/common/options_tables.h"
#include "app/script/script.h"

namespace luz::app {
namespace {

// The viewer's own settings beside the options tables' rows.
struct ViewerSetting {
  const char* name;
  bool ViewerState::*field;
};
constexpr ViewerSetting switches[] = {
    {"panel", &ViewerState::show_panel},
    {"inspector", &ViewerState::show_inspector},
    {"help", &ViewerState::show_help},
};

std::string all_names() {
  std::string names = "exposure, ui-scale, panel, inspector, help";
  for (const OptionTable* table : option_tables())
    for (const OptionRow& row : table->rows) {
      if (!in_viewer(row)) continue;
      if (find_option(row.name)->row == &row) names += fmt::format(", {}", row.name);
      else names += fmt::format(", {}.{}", table->name, row.name);  // another table's comes first
    }
  return names;
}

}  // namespace

std::string check_setting(const std::string& name, const std::string& value) {
  if (name == "exposure")
    return is_number(value) || value == "auto" ? "" : "`set exposure EV` takes a finite number or auto";
  if (name == "ui-scale")
    return is_number(value) && std::stof(value) >= kMinUiScale && std::stof(value) <= kMaxUiScale
               ? "" : fmt::format("`set ui-scale S` takes {} .. {}", kMinUiScale, kMaxUiScale);
  for (const ViewerSetting& s : switches)
    if (name == s.name) return value == "on" || value == "off" ? "" : fmt::format("`set {}` takes on or off", name);
  if (const std::optional<FoundOption> option = find_option(name)) {
    if (!in_viewer(*option->row))
      return fmt::format("\"{}\" is a file `luz render {}` writes; the viewer writes none", name, option->row->flag);
    return parse_value(*option->row, value) ? "" : fmt::format("`set {}` takes {}", name, accepted_text(*option->row));
  }
  return fmt::format("cannot set \"{}\" ({})", name, all_names());
}

bool apply_setting(ViewerState& state, const std::string& name, const std::string& value, std::string& error) {
  if (const std::string problem = check_setting(name, value); !problem.empty()) {
    error = problem;
    return false;
  }
  if (name == "exposure") {
    if (value == "auto") state.exposure_fit = true;  // on the next picture (the viewer reads it)
    else state.exposure = std::stof(value);
    return true;
  }
  for (const ViewerSetting& s : switches)
    if (name == s.name) state.*s.field = value == "on";
  if (const std::optional<FoundOption> option = find_option(name))
    option->row->set(options_of(state, *option->table), *parse_value(*option->row, value));
  return true;
}

void* options_of(ViewerState& state, const OptionTable& table) {
  if (&table == &local_table()) return &state.local;
  if (&table == &whitted_table()) return &state.whitted;
  if (&table == &radiosity_table()) return &state.radiosity;
  return state.model_options.of(table);
}

const void* options_of(const ViewerState& state, const OptionTable& table) {
  return options_of(const_cast<ViewerState&>(state), table);  // the same field, read only
}

nlohmann::json settings_json(const ViewerState& state) {
  nlohmann::json out = nlohmann::json::object();
  for (const OptionTable* table : option_tables()) {
    nlohmann::json& rows = out[table->name] = nlohmann::json::object();
    const void* options = options_of(state, *table);
    for (const OptionRow& row : table->rows) {
      if (!in_viewer(row)) continue;
      const double v = row.get(options);
      if (row.kind == OptionKind::on_off) rows[row.name] = v != 0.0;
      else if (row.kind == OptionKind::choice) rows[row.name] = row.choices[size_t(v)];
      else rows[row.name] = v;
    }
  }
  nlohmann::json& viewer = out["viewer"] = nlohmann::json::object();
  for (const ViewerSetting& s : switches) viewer[s.name] = state.*s.field;
  return out;
}

}  // namespace luz::app
