#pragma once
// The script's `set NAME VALUE`: the rows of the registry's options tables (option_row.h; NAME or
// TABLE.NAME, model_registry.h's find_option), and the viewer's own settings (exposure, UI
// scale, panel, inspector, help).
#include <string>

#include <nlohmann/json.hpp>

#include "app/viewer/viewer_state.h"

namespace luz::app {

// The interface's size (`--ui-scale`, `set ui-scale`, Ctrl+= / Ctrl+-): 1 is the default.
inline constexpr float kMinUiScale = 0.5f;
inline constexpr float kMaxUiScale = 4.0f;
inline constexpr float kUiScaleStep = 1.25f;  // `interface larger|smaller` (Ctrl+= / Ctrl+-)

// "" when NAME takes VALUE, else what is wrong (checked before any window opens).
std::string check_setting(const std::string& name, const std::string& value);
// Sets it; false (with `error`) when it cannot be set.
bool apply_setting(ViewerState& state, const std::string& name, const std::string& value, std::string& error);

// Where the viewer keeps an options table's struct: the shared tables' are ViewerState's fields
// (local, whitted, radiosity), a model's own is in model_options.
void* options_of(ViewerState& state, const OptionTable& table);
const void* options_of(const ViewerState& state, const OptionTable& table);

// Every row of the registry's tables as the viewer holds it now, by table and row name, and the
// viewer's own switches: {"local": {"ambient": true, "fog": "linear", ...}, "whitted": {...},
// "radiosity": {...}, "path": {...}, "viewer": {"panel": true, "inspector": true, "help": false}}
// (dump-state's "settings": what a lesson's step, a key or a panel edit really set).
nlohmann::json settings_json(const ViewerState& state);

}  // namespace luz::app
