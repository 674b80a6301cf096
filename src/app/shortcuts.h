#pragma once
// The classroom's keyboard: one table, read by the key handler, by F1's help window, by the
// script's `key` command and copied into the README.
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace luz::app {

enum class Action {
  none,  // listed for help only (held keys: flying)
  model_1, model_2, model_3, model_4, model_5, model_6,
  toggle_ambient, toggle_diffuse, toggle_specular, toggle_emission, toggle_textures, toggle_blinn,
  cycle_attenuation,
  cycle_fog, toggle_shadows, toggle_transparency, toggle_reflection_map,
  exposure_up, exposure_down,
  scene_camera, next_camera,
  reload, screenshot, screenshot_with_panel,
  toggle_panel, toggle_inspector, help, quit,
  trace_view, cancel_trace, clear_ray_tree,
  radiosity_run, radiosity_step, radiosity_reset,
  toggle_heat_map, toggle_patches, toggle_ambient_estimate,
  toggle_solvers,
};

struct Shortcut {
  int key;            // GLFW_KEY_*
  int mods;           // GLFW_MOD_* that must be held (0: none)
  const char* keys;   // as shown to people: "Shift+P"
  Action action;
  const char* what;
};

std::span<const Shortcut> shortcuts();

// The action of a key press with these modifiers; nullopt when the key does nothing.
std::optional<Action> action_for(int key, int mods);

// "A", "1", "F1", "Esc", "Left", "PageUp", "Shift+P" -> GLFW key and modifiers.
// False when the name is not a key the viewer knows.
bool parse_key(std::string_view text, int& key, int& mods);

}  // namespace luz::app
