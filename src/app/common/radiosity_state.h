#pragma once
// Radiosity (model 5) in the viewer's state: what the panel, the keys and the script change, and
// what the panel and the inspector show of the solver. Plain data, no GL: the solver itself lives
// in RadiositySession (radiosity_session.h), which the viewer builds when the model is first shown and
// which fills `status` and `patch` every frame.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/color.h"
#include "radiosity/radiosity_options.h"

namespace luz::app {

// How the viewer drives the solver: it shoots on the GL thread, a share per frame, so the window
// stays interactive while the light spreads (DESIGN.md, Threads).
struct RadiosityDrive {
  bool running = false;
  bool by_time = true;        // a time budget per frame (else a number of shots per frame)
  float budget_ms = 15.0f;    // shooting time per frame while running
  int shots_per_frame = 10;
  bool heat_map = false;      // show the unshot power per patch instead of B/pi
  bool show_shooter = true;   // the last shooter in magenta
  bool show_item_buffer = true;  // the small window with its hemicube's five faces
};

// The clicked patch, for the inspector (exitances in W/m^2, as slide 39 keeps them).
struct PatchReading {
  size_t patch = 0;              // the element clicked (it receives and is drawn)
  size_t shooter = 0;            // the shooting patch it belongs to
  int mesh = -1, triangle = -1;  // its source triangle in the scene
  std::string material;
  glm::vec3 centre{0.0f}, normal{0.0f};
  float area = 0.0f;     // m^2
  Rgb E{0.0f};           // emitted exitance, pi * Le
  Rgb rho{0.0f};         // kd
  Rgb radiosity{0.0f};   // shot so far ("radiosidad")
  Rgb unshot{0.0f};      // still to shoot ("carga emisora")
  Rgb B{0.0f};           // radiosity + unshot: what step 3 displays
  Rgb radiance{0.0f};    // B / pi
  int shots = 0;         // the solver's shots when read
};

// What the panel shows of the solver, refreshed by the view every frame.
struct RadiosityStatus {
  bool built = false;
  size_t patches = 0;          // shooting patches built
  size_t elements = 0;         // the elements they are cut into (what receives and is drawn)
  size_t refined_elements = 0; // of those, added by adaptive subdivision so far
  int refinement_passes = 0;
  float patch_size = 0.0f;     // the mesh's longest edge, m
  int hemicube_res = 0;        // of the solver that runs
  bool remesh_pending = false; // the options ask for another patch size or hemicube
  int shots = 0;
  double unshot_fraction = 1.0;
  double shots_per_second = 0.0;
  bool done = false;           // converged or out of shots
  int last_shooter = -1;       // as ProgressiveSolver::last_shooter()
  std::string shooter;         // "patch 12 (floor)", "light 0 (key)", "" before any shot
  std::vector<float> plot;     // log10(unshot fraction) after shot 0, 1, 2, ...
  unsigned item_view_texture = 0;  // the unfolded hemicube in false colours (GL texture)
  int item_view_size = 0;          // its width = height, pixels
  std::string item_view_shooter;   // the patch it was drawn for: the last shooter, or one before
  // Where the panel drew the plot and the window the item buffer, window coordinates (for the
  // tests' dump-radiosity); zero when not drawn.
  glm::vec2 plot_min{0.0f}, plot_max{0.0f};
  glm::vec2 item_view_min{0.0f}, item_view_max{0.0f};
};

struct RadiosityState {
  // The options `luz render --model radiosity` fills from its flags. Patch size and hemicube
  // resolution take effect at the next remesh; the rest at once.
  RadiosityOptions options;
  RadiosityDrive drive;
  RadiosityStatus status;
  std::optional<PatchReading> patch;  // the clicked patch

  // Requests, done by the loop at the next frame.
  int steps = 0;          // single shots still to do
  int stop_at = 0;        // run, then pause at this many shots (0: no such stop)
  bool reset = false;     // slide 39 step 1 again
  bool remesh = false;    // a new mesh and solver with the options' patch size and hemicube
};

}  // namespace luz::app
