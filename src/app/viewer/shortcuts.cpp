#include "app/viewer/shortcuts.h"

#include <algorithm>
#include <cctype>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/common/i18n.h"
#include "app/common/model_registry.h"

namespace luz::app {
namespace {

// Terms on the initials of their names (Ambient, Diffuse, Specular, Emission, Textures, Blinn);
// flying on the arrows so that A, D and S stay the terms. Slide 19's switches where a letter of
// their name is free: foG, sHadows, Opacity (transparency), Mirror (reflection map). The models'
// own keys come between these and the window's (their registry entries: Whitted's trace on
// Enter, radiosity's loop on Space). Slide 36's window of solvers on J, for Jacobi, the first of
// them. A lesson's steps on F8 (next) and F7 (previous): PageUp / PageDown and the arrows fly,
// and a held key must not walk the lecture; its caption folds beside them, on F9. Esc stays quit
// (it asks first in a class).
constexpr KeyBinding switches[] = {
    {"A", nullptr, "toggle ambient", N_("ambient term I_A on / off")},
    {"D", nullptr, "toggle diffuse", N_("diffuse term I_D on / off")},
    {"S", nullptr, "toggle specular", N_("specular term I_S on / off")},
    {"E", nullptr, "toggle emission", N_("emitted radiance Le on / off")},
    {"T", nullptr, "toggle textures", N_("kd texture on / off")},
    {"B", nullptr, "toggle blinn", N_("Phong's R·V / Blinn's N·H")},
    {"F", nullptr, "attenuation toggle", N_("f_att of every light: 1/d² / 1/(c0 + c1·d + c2·d²)")},
    {"G", nullptr, "cycle fog", N_("fog: off / linear / exponential")},
    {"H", nullptr, "toggle shadows", N_("shadows (S_i, shadow maps) on / off")},
    {"O", nullptr, "toggle transparency", N_("non-refractive transparency (kt) on / off")},
    {"M", nullptr, "toggle reflection-map", N_("reflection map (kr Ir) on / off")},
};

constexpr KeyBinding window[] = {
    {"J", nullptr, "solvers toggle", N_("slide 36: the system solved four ways, curves live (window)")},
    {"+", nullptr, "exposure +0.5", N_("exposure +0.5 EV (any '+' key, the keypad's too)")},
    {"-", nullptr, "exposure -0.5", N_("exposure -0.5 EV (any '-' key, the keypad's too)")},
    {"K", nullptr, "set exposure auto", N_("exposure fitted to the picture: its mid-tones middle grey (the Key)")},
    {"Ctrl+=", N_("Ctrl+="), "interface larger", N_("larger interface (a projector); Ctrl+- smaller")},
    {"Ctrl+minus", N_("Ctrl+-"), "interface smaller", N_("smaller interface")},
    {"C", nullptr, "camera", N_("back to the scene camera")},
    {"N", nullptr, "camera next", N_("next scene camera")},
    {"R", nullptr, "reload", N_("reload the scene file")},
    {"P", nullptr, "screenshot", N_("screenshot of the picture (PNG)")},
    {"Shift+P", N_("Shift+P"), "screenshot --with-panel", N_("screenshot with the panel")},
    {"Tab", N_("Tab"), "toggle panel", N_("hide / show the panel")},
    {"I", nullptr, "toggle inspector", N_("hide / show the inspector")},
    {"F1", nullptr, "toggle help", N_("this list")},
    {"F8", nullptr, "lesson next", N_("lesson: next step (luz --lesson)")},
    {"F7", nullptr, "lesson prev", N_("lesson: previous step")},
    {"F9", nullptr, "caption toggle", N_("lesson: the caption's text hidden (one line) / shown")},
#ifndef __EMSCRIPTEN__
    // In the page Esc is left to the browser (it leaves full screen): a page whose program ended
    // would be a dead picture until reloaded, and closing the tab is the browser's own key.
    {"Esc", N_("Esc"), "quit --ask", N_("quit")},
#endif
    {"Up", N_("Up / Down"), nullptr, N_("fly forward / back (Shift: faster)")},
    {"Left", N_("Left / Right"), nullptr, N_("fly left / right")},
    {"PageUp", N_("PageUp / PageDown"), nullptr, N_("fly up / down")},
};

struct NamedKey {
  const char* name;
  int key;
};

constexpr NamedKey named_keys[] = {
    {"esc", GLFW_KEY_ESCAPE},   {"escape", GLFW_KEY_ESCAPE}, {"tab", GLFW_KEY_TAB},
    {"enter", GLFW_KEY_ENTER},  {"space", GLFW_KEY_SPACE},   {"backspace", GLFW_KEY_BACKSPACE},   {"left", GLFW_KEY_LEFT},
    {"right", GLFW_KEY_RIGHT},  {"up", GLFW_KEY_UP},         {"down", GLFW_KEY_DOWN},
    {"pageup", GLFW_KEY_PAGE_UP}, {"pagedown", GLFW_KEY_PAGE_DOWN},
    {"=", GLFW_KEY_EQUAL},      {"minus", GLFW_KEY_MINUS},   {".", GLFW_KEY_PERIOD},
    {"kp_add", GLFW_KEY_KP_ADD}, {"kp_subtract", GLFW_KEY_KP_SUBTRACT},
};

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return out;
}

Shortcut resolved(const KeyBinding& binding) {
  Shortcut s;
  parse_key(binding.key, s.key, s.mods, s.character);
  s.name = binding.key;
  s.shown = binding.shown ? binding.shown : binding.key;
  s.line = binding.line ? binding.line : "";
  s.what = binding.what;
  return s;
}

std::vector<Shortcut> all_shortcuts() {
  std::vector<Shortcut> list;
  for (const ModelEntry& m : models()) {
    const std::string digit = std::to_string(m.key);
    const std::string line = std::string("model ") + m.name;
    list.push_back(resolved({digit.c_str(), nullptr, line.c_str(), m.help}));
  }
  for (const KeyBinding& b : switches) list.push_back(resolved(b));
  for (const ModelEntry& m : models())
    for (const KeyBinding& b : m.keys) list.push_back(resolved(b));
  for (const KeyBinding& b : window) list.push_back(resolved(b));
  return list;
}

}  // namespace

std::span<const KeyBinding> switch_keys() { return switches; }
std::span<const KeyBinding> window_keys() { return window; }

const std::vector<Shortcut>& shortcuts() {
  static const std::vector<Shortcut> list = all_shortcuts();
  return list;
}

const Shortcut* shortcut_for(int key, int mods) {
  const Shortcut* best = nullptr;
  for (const Shortcut& s : shortcuts())
    if (s.key != 0 && s.key == key && !s.line.empty() && (mods & s.mods) == s.mods && (!best || s.mods > best->mods))
      best = &s;
  return best;
}

const Shortcut* shortcut_for_character(unsigned character) {
  for (const Shortcut& s : shortcuts())
    if (s.key == 0 && s.character == character && !s.line.empty()) return &s;
  return nullptr;
}

bool parse_key(std::string_view text, int& key, int& mods, unsigned& character) {
  mods = 0;
  character = 0;
  std::string name = lower(text);
  for (const auto& [prefix, mod] : {std::pair{"shift+", GLFW_MOD_SHIFT}, std::pair{"ctrl+", GLFW_MOD_CONTROL}})
    if (name.starts_with(prefix) && name.size() > std::string_view(prefix).size()) {
      mods |= mod;
      name = name.substr(std::string_view(prefix).size());
    }
  if (name == "+" || name == "-") {  // a character's shortcut: typed, whatever key makes it
    key = 0;
    character = unsigned(name[0]);
    return true;
  }
  if (name.size() == 1 && std::isalnum(static_cast<unsigned char>(name[0]))) {
    // GLFW's key codes for letters and digits are their upper-case ASCII codes.
    key = std::toupper(static_cast<unsigned char>(name[0]));
    return true;
  }
  if (name.size() >= 2 && name[0] == 'f' && std::all_of(name.begin() + 1, name.end(), ::isdigit)) {
    const int n = std::stoi(name.substr(1));
    if (n < 1 || n > 12) return false;
    key = GLFW_KEY_F1 + n - 1;
    return true;
  }
  for (const NamedKey& named : named_keys)
    if (name == named.name) {
      key = named.key;
      return true;
    }
  return false;
}

}  // namespace luz::app
