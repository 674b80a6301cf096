#pragma once
// What the viewer shows and what the panel, the shortcuts and the script change: one struct, so
// that a key, a click on the panel and a script line do exactly the same thing. The local
// models read `local` (the same LocalOptions `luz render` fills from its flags) and the scene's
// lights and materials, which the panel edits in place.
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/scene.h"
#include "local/local_options.h"

namespace luz::app {

enum class Model { flat, gouraud, phong, whitted, radiosity, hybrid };

struct ModelInfo {
  Model model;
  const char* name;    // as `luz render --model` and the script spell it
  const char* label;   // as the panel shows it
  bool available;      // false: the model's issue has not landed yet
};

// The models on keys 1..6, in that order.
std::span<const ModelInfo> models();
const ModelInfo& info(Model model);

// The panel's split of a light's RGB intensity into a colour and a scalar intensity.
struct LightEdit {
  Rgb colour{1.0f};
  float intensity = 1.0f;
};

struct ViewerState {
  std::filesystem::path scene_path;
  std::unique_ptr<Scene> scene;         // a stable address: the renderers keep a reference
  std::vector<LightEdit> light_edits;   // one per scene light
  LocalOptions local;
  Model model = Model::phong;
  float exposure = 0.0f;                // EV, from the scene, then the panel's
  int scene_camera = 0;                 // the scene camera shown while !free_camera
  bool free_camera = false;             // the orbit camera moved away from it
  int selected_material = -1;           // the panel's material section (-1: none yet)

  bool show_panel = true;
  bool show_help = false;
  bool show_inspector = true;
  std::string error;   // the last scene that failed to load, shown until a load succeeds
  std::string note;    // the status line's latest message

  // Requests from the panel, done by the loop between frames.
  bool emitters_changed = false;   // an Le was edited: the area lights must be found again
  bool reload = false;
  bool back_to_scene_camera = false;

  // For the status line.
  double frame_ms = 0.0;
};

}  // namespace luz::app
