#pragma once
// What the viewer shows and what the panel, the shortcuts and the script change: one struct, so
// that a key, a click on the panel and a script line do exactly the same thing. The local
// models read `local` (the same LocalOptions `luz render` fills from its flags) and the scene's
// lights and materials, which the panel edits in place.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/scene.h"
#include "app/common/option_values.h"
#include "radiosity/radiosity_options.h"
#include "local/local_options.h"
#include "raytracing/counters.h"
#include "raytracing/ray_tree.h"
#include "raytracing/whitted_options.h"

namespace luz::app {

// Whitted's picture: the raster view until a trace is asked for, then the tiles as they come.
enum class TracePhase { raster, tracing, done };

struct TraceProgress {
  TracePhase phase = TracePhase::raster;
  bool cancelled = false;  // the last trace stopped before its end (the view changed)
  int done = 0, total = 0; // tiles
  double seconds = 0.0;
  rt::Counters counters;   // of the finished trace
};

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
  std::string model = "phong";          // a name of the registry (model_registry.h); the
                                        // panel's radio buttons set it, the viewer follows
  float exposure = 0.0f;                // EV, from the scene, then the panel's
  bool exposure_fit = false;            // asked for: the exposure fitted to the next picture (core/exposure.h)
  bool present_parts = true;            // only the window's changed parts shown, where it keeps its back buffer
  bool display_copy = true;             // the local models' displayed values copied to the window
  bool display_direct = true;           // ...or drawn straight into it when no radiance is needed
                                        // (script: display-copy off runs the display pass instead)
  int scene_camera = 0;                 // the scene camera shown while !free_camera
  bool free_camera = false;             // the orbit camera moved away from it
  int selected_material = -1;           // the panel's material section (-1: none yet)

  // Whitted (model 4) and the hybrid: the tracer's switches, the struct `luz render --model
  // whitted` fills (its local terms and Blinn come from `local`, as the command takes them from
  // the --no-TERM flags). The trace and the ray tree belong to the view that traces.
  rt::WhittedOptions whitted;

  // The options of the models' own tables (the path tracer's, option_row.h), as `set` and the
  // lessons write them and each model's view reads its own.
  OptionValues model_options{OptionValues::Start::viewer};

  // Radiosity (model 5): the options `luz render --model radiosity` fills. Patch size and
  // hemicube resolution take effect at the next remesh, the rest at once; the loop and the
  // solver's status are its view's (models/radiosity/radiosity_state.h).
  RadiosityOptions radiosity;

  // Side by side (panes.h): the panes' models when there are two or more (empty: one picture,
  // `model`); the panel asks for another list with a `panes` line (panel_lines).
  std::vector<std::string> panes;

  bool show_panel = true;
  bool show_help = false;
  bool show_inspector = true;
  std::string error;   // the last scene that failed to load, shown until a load succeeds
  std::string note;    // the status line's latest message

  // What the panel's buttons ask: script lines, run by the loop between frames through the verbs
  // a key's line and a script's run (panel.h's panel_buttons), in the order they were pressed.
  std::vector<std::string> panel_lines;
  bool emitters_changed = false;   // an Le was edited: the area lights must be found again

  // The frame's time, smoothed over about ten frames, and the figure the status line takes
  // (Viewer::status_shown refreshes its figures twice a second).
  double frame_ms = 0.0;
  double status_ms = 0.0;
  bool status_ms_live = true;  // false: the status line's figures held (pictures to compare)
  // Where a frame's time goes, in ms, timed on one frame in eight and smoothed: the models'
  // pictures (into their float targets), their exposure to the window, the panel's ImGui pass
  // (building and drawing), and presenting the frame (glfwSwapBuffers).
  struct FramePhases {
    double models_ms = 0.0, exposure_ms = 0.0, panel_ms = 0.0, panel_building_ms = 0.0, present_ms = 0.0;
  } frame_phases;
};

}  // namespace luz::app
