#include "app/viewer/shortcuts.h"

#include <algorithm>
#include <cctype>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/common/i18n.h"

namespace luz::app {
namespace {

// Terms on the initials of their names (Ambient, Diffuse, Specular, Emission, Textures, Blinn);
// flying on the arrows so that A, D and S stay the terms. Slide 19's switches where a letter of
// their name is free: foG, sHadows, Opacity (transparency), Mirror (reflection map). Whitted's
// trace on Enter; Esc stays quit, so the trace is cancelled by Backspace (any camera move
// cancels it too), and X crosses out the ray tree. Radiosity's loop on Space (run / pause), '.'
// (one shot) and 0 (back to shot 0, slide 39 step 1); its display on U (Unshot heat map), L
// (patch outLines) and Shift+A (the Ambient estimate, beside A's ambient term). Slide 36's
// window of solvers on J, for Jacobi, the first of them. A lesson's steps on F8 (next) and F7
// (previous): PageUp / PageDown and the arrows fly, and a held key must not walk the lecture;
// its caption folded beside them, on F9.
constexpr Shortcut table[] = {
    // The digits show the models (model_registry.cpp says which is on which key).
    {GLFW_KEY_1, 0, 0, "1", Action::choose_model, ""}, {GLFW_KEY_2, 0, 0, "2", Action::choose_model, ""},
    {GLFW_KEY_3, 0, 0, "3", Action::choose_model, ""}, {GLFW_KEY_4, 0, 0, "4", Action::choose_model, ""},
    {GLFW_KEY_5, 0, 0, "5", Action::choose_model, ""}, {GLFW_KEY_6, 0, 0, "6", Action::choose_model, ""},
    {GLFW_KEY_7, 0, 0, "7", Action::choose_model, ""}, {GLFW_KEY_8, 0, 0, "8", Action::choose_model, ""},
    {GLFW_KEY_9, 0, 0, "9", Action::choose_model, ""},
    {GLFW_KEY_A, 0, 0, "A", Action::toggle_ambient, N_("ambient term I_A on / off")},
    {GLFW_KEY_D, 0, 0, "D", Action::toggle_diffuse, N_("diffuse term I_D on / off")},
    {GLFW_KEY_S, 0, 0, "S", Action::toggle_specular, N_("specular term I_S on / off")},
    {GLFW_KEY_E, 0, 0, "E", Action::toggle_emission, N_("emitted radiance Le on / off")},
    {GLFW_KEY_T, 0, 0, "T", Action::toggle_textures, N_("kd texture on / off")},
    {GLFW_KEY_B, 0, 0, "B", Action::toggle_blinn, N_("Phong's R·V / Blinn's N·H")},
    {GLFW_KEY_F, 0, 0, "F", Action::cycle_attenuation, N_("f_att of every light: 1/d² / 1/(c0 + c1·d + c2·d²)")},
    {GLFW_KEY_G, 0, 0, "G", Action::cycle_fog, N_("fog: off / linear / exponential")},
    {GLFW_KEY_H, 0, 0, "H", Action::toggle_shadows, N_("shadows (S_i, shadow maps) on / off")},
    {GLFW_KEY_O, 0, 0, "O", Action::toggle_transparency, N_("non-refractive transparency (kt) on / off")},
    {GLFW_KEY_M, 0, 0, "M", Action::toggle_reflection_map, N_("reflection map (kr Ir) on / off")},
    {GLFW_KEY_ENTER, 0, 0, N_("Enter"), Action::trace_view, N_("Whitted / hybrid: trace this view, tile by tile")},
    {GLFW_KEY_BACKSPACE, 0, 0, N_("Backspace"), Action::cancel_trace, N_("Whitted / hybrid: cancel the trace (back to the raster / radiosity view)")},
    {GLFW_KEY_X, 0, 0, "X", Action::clear_ray_tree, N_("Whitted / hybrid: clear the ray tree")},
    {GLFW_KEY_SPACE, 0, 0, N_("Space"), Action::radiosity_run, N_("radiosity: run / pause the shooting")},
    {GLFW_KEY_PERIOD, 0, 0, ".", Action::radiosity_step, N_("radiosity: one shot")},
    {GLFW_KEY_0, 0, 0, "0", Action::radiosity_reset, N_("radiosity: reset (shot 0: unshot = E)")},
    {GLFW_KEY_U, 0, 0, "U", Action::toggle_heat_map, N_("radiosity: heat map of the unshot power on / off")},
    {GLFW_KEY_L, 0, 0, "L", Action::toggle_patches, N_("radiosity: flat patches with outlines / Gouraud")},
    {GLFW_KEY_A, GLFW_MOD_SHIFT, 0, N_("Shift+A"), Action::toggle_ambient_estimate, N_("radiosity: ambient estimate on / off")},
    {GLFW_KEY_J, 0, 0, "J", Action::toggle_solvers, N_("slide 36: the system solved four ways, curves live (window)")},
    {0, 0, '+', "+", Action::exposure_up, N_("exposure +0.5 EV (any '+' key, the keypad's too)")},
    {0, 0, '-', "-", Action::exposure_down, N_("exposure -0.5 EV (any '-' key, the keypad's too)")},
    {GLFW_KEY_K, 0, 0, "K", Action::exposure_fit, N_("exposure fitted to the picture: its mid-tones middle grey (the Key)")},
    {GLFW_KEY_EQUAL, GLFW_MOD_CONTROL, 0, N_("Ctrl+="), Action::ui_larger, N_("larger interface (a projector); Ctrl+- smaller")},
    {GLFW_KEY_MINUS, GLFW_MOD_CONTROL, 0, N_("Ctrl+-"), Action::ui_smaller, N_("smaller interface")},
    {GLFW_KEY_C, 0, 0, "C", Action::scene_camera, N_("back to the scene camera")},
    {GLFW_KEY_N, 0, 0, "N", Action::next_camera, N_("next scene camera")},
    {GLFW_KEY_R, 0, 0, "R", Action::reload, N_("reload the scene file")},
    {GLFW_KEY_P, 0, 0, "P", Action::screenshot, N_("screenshot of the picture (PNG)")},
    {GLFW_KEY_P, GLFW_MOD_SHIFT, 0, N_("Shift+P"), Action::screenshot_with_panel, N_("screenshot with the panel")},
    {GLFW_KEY_TAB, 0, 0, N_("Tab"), Action::toggle_panel, N_("hide / show the panel")},
    {GLFW_KEY_I, 0, 0, "I", Action::toggle_inspector, N_("hide / show the inspector")},
    {GLFW_KEY_F1, 0, 0, "F1", Action::help, N_("this list")},
    {GLFW_KEY_F8, 0, 0, "F8", Action::lesson_next, N_("lesson: next step (luz --lesson)")},
    {GLFW_KEY_F7, 0, 0, "F7", Action::lesson_previous, N_("lesson: previous step")},
    {GLFW_KEY_F9, 0, 0, "F9", Action::lesson_caption, N_("lesson: the caption's text hidden (one line) / shown")},
    {GLFW_KEY_ESCAPE, 0, 0, N_("Esc"), Action::quit, N_("quit")},
    {GLFW_KEY_UP, 0, 0, N_("Up / Down"), Action::none, N_("fly forward / back (Shift: faster)")},
    {GLFW_KEY_LEFT, 0, 0, N_("Left / Right"), Action::none, N_("fly left / right")},
    {GLFW_KEY_PAGE_UP, 0, 0, N_("PageUp / PageDown"), Action::none, N_("fly up / down")},
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

}  // namespace

std::span<const Shortcut> shortcuts() { return table; }

std::optional<Action> action_for(int key, int mods) {
  // The entry with the most required modifiers that are all held wins (Shift+P over P).
  const Shortcut* best = nullptr;
  for (const Shortcut& s : table)
    if (s.key != 0 && s.key == key && s.action != Action::none && (mods & s.mods) == s.mods &&
        (!best || s.mods > best->mods))
      best = &s;
  if (!best) return std::nullopt;
  return best->action;
}

std::optional<Action> action_for_character(unsigned character) {
  for (const Shortcut& s : table)
    if (s.key == 0 && s.character == character) return s.action;
  return std::nullopt;
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
