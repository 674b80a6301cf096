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
  choose_model,  // the digit keys: the registry's model on that key (model_registry.h)
  toggle_ambient, toggle_diffuse, toggle_specular, toggle_emission, toggle_textures, toggle_blinn,
  cycle_attenuation,
  cycle_fog, toggle_shadows, toggle_transparency, toggle_reflection_map,
  exposure_up, exposure_down, exposure_fit,
  ui_larger, ui_smaller,
  scene_camera, next_camera,
  reload, screenshot, screenshot_with_panel,
  toggle_panel, toggle_inspector, help, quit,
  trace_view, cancel_trace, clear_ray_tree,
  radiosity_run, radiosity_step, radiosity_reset,
  toggle_heat_map, toggle_patches, toggle_ambient_estimate,
  toggle_solvers,
  lesson_next, lesson_previous, lesson_caption,
};

// A shortcut is a key by its place (GLFW_KEY_*, named by the US layout: letters, Enter, F1) or,
// for the keys that are characters on every layout but sit elsewhere on some ('+', '-'), the
// character it types (GLFW's char callback): on a Spanish keyboard '+' is right of P, and the
// keypad's '+' types '+' too.
struct Shortcut {
  int key;            // GLFW_KEY_*, or 0 for a character's shortcut
  int mods;           // GLFW_MOD_* that must be held (0: none)
  unsigned character; // the character typed, for a character's shortcut (else 0)
  const char* keys;   // as shown to people: "Shift+P" (a message id where it has words: N_("Space"))
  Action action;
  const char* what;
};

std::span<const Shortcut> shortcuts();

// The action of a key press with these modifiers; nullopt when the key does nothing.
std::optional<Action> action_for(int key, int mods);
// The action of a typed character; nullopt when it does nothing.
std::optional<Action> action_for_character(unsigned character);

// "A", "1", "F1", "Esc", "Left", "PageUp", "Shift+P", "KP_Add" -> GLFW key and modifiers; "+"
// and "-" -> the character (key 0). False when the name is not a key the viewer knows.
bool parse_key(std::string_view text, int& key, int& mods, unsigned& character);
inline bool parse_key(std::string_view text, int& key, int& mods) {
  unsigned character = 0;
  return parse_key(text, key, mods, character);
}

}  // namespace luz::app
