#include "app/viewer/viewer_settings.h"

#include <fmt/format.h>

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

template <class Options>
std::string check_row(const OptionRow<Options>& row, const std::string& value) {
  return parse_value(row, value) ? "" : fmt::format("`set {}` takes {}", row.name, accepted_text(row));
}

std::string all_names() {
  std::string names = "exposure, ui-scale, panel, inspector, help";
  for (const LocalRow& row : local_rows()) names += fmt::format(", {}", row.name);
  for (const WhittedRow& row : whitted_rows()) names += fmt::format(", {}", row.name);
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
  if (const LocalRow* row = find_row(local_rows(), name)) return check_row(*row, value);
  if (const WhittedRow* row = find_row(whitted_rows(), name)) return check_row(*row, value);
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
  if (const LocalRow* row = find_row(local_rows(), name)) row->set(state.local, *parse_value(*row, value));
  if (const WhittedRow* row = find_row(whitted_rows(), name)) row->set(state.whitted, *parse_value(*row, value));
  return true;
}

namespace {

template <class Options>
nlohmann::json rows_json(std::span<const OptionRow<Options>> rows, const Options& options) {
  nlohmann::json out = nlohmann::json::object();
  for (const OptionRow<Options>& row : rows) {
    const double v = row.get(options);
    if (row.kind == OptionKind::on_off) out[row.name] = v != 0.0;
    else if (row.kind == OptionKind::choice) out[row.name] = row.choices[size_t(v)];
    else out[row.name] = v;
  }
  return out;
}

}  // namespace

nlohmann::json settings_json(const ViewerState& state) {
  nlohmann::json viewer = nlohmann::json::object();
  for (const ViewerSetting& s : switches) viewer[s.name] = state.*s.field;
  return {{"local", rows_json(local_rows(), state.local)},
          {"whitted", rows_json(whitted_rows(), state.whitted)},
          {"radiosity", rows_json(radiosity_rows(), state.radiosity.options)},
          {"viewer", viewer}};
}

}  // namespace luz::app
