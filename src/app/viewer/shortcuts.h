#pragma once
// The classroom's keyboard: every key bound to a line of the script language (key_binding.h).
// One list, read by the key handler, by F1's help window, by the script's `key` command and by
// the test that holds each key to its line; docs/viewer.md copies it.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/script/key_binding.h"

namespace luz::app {

// A key of the list, resolved: a key by its place (GLFW_KEY_*, named by the US layout: letters,
// Enter, F1) or, for the keys that are characters on every layout but sit elsewhere on some
// ('+', '-'), the character it types (GLFW's char callback): on a Spanish keyboard '+' is right
// of P, and the keypad's '+' types '+' too.
struct Shortcut {
  int key = 0;              // GLFW_KEY_*, or 0 for a character's shortcut
  int mods = 0;             // GLFW_MOD_* that must be held (0: none)
  unsigned character = 0;   // the character typed, for a character's shortcut (else 0)
  std::string name;         // as `key NAME` takes it
  std::string shown;        // as F1 shows it (a message id where it has words: "Space")
  std::string line;         // the script line it runs; empty: listed for help only
  const char* what = "";    // F1's description, a message id
};

// The digits of the registry's models ("model NAME"), the lecture's switches, each model's own
// keys (its registry entry's, in the registry's order), the window's keys: F1's order.
const std::vector<Shortcut>& shortcuts();

// The viewer's own bindings, without the digits and the models' (the first part comes before
// the models' keys in F1, the second after).
std::span<const KeyBinding> switch_keys();
std::span<const KeyBinding> window_keys();

// The shortcut of a key press with these modifiers (the one with the most held modifiers: Shift+P
// over P); nullptr when the key runs nothing.
const Shortcut* shortcut_for(int key, int mods);
// The shortcut of a typed character; nullptr when it runs nothing.
const Shortcut* shortcut_for_character(unsigned character);

// "A", "1", "F1", "Esc", "Left", "PageUp", "Shift+P", "KP_Add", "Ctrl+minus" -> GLFW key and
// modifiers; "+" and "-" -> the character (key 0). False when the name is not a key the viewer knows.
bool parse_key(std::string_view text, int& key, int& mods, unsigned& character);
inline bool parse_key(std::string_view text, int& key, int& mods) {
  unsigned character = 0;
  return parse_key(text, key, mods, character);
}

}  // namespace luz::app
