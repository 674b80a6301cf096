#pragma once
// Radiosity (model 5) as its view holds it: what the panel, the keys and the script change of
// the loop, and what the panel and the inspector show of the solver. Plain data, no GL: the
// solver itself lives in RadiositySession (radiosity_session.h), which the view builds when the
// model is first shown and which fills `status` and `patch` every frame. The options (patch
// size, hemicube, ...) are the viewer's settings, the radiosity table's row values.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/common/patch_reading.h"
#include "app/common/radiosity_drive.h"

namespace luz::app {

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
