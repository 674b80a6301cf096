#pragma once
// The viewer's radiosity model: one solve of one scene, stepped on the GL thread.
//
//   advance()  every frame: the requests (reset, single shots), then, while running, shots until
//              the frame's time budget (or its number of shots) is spent, as README's "how a
//              viewer drives the solver" does; then the vertex colours are uploaded again so the
//              class watches the light spread (slide 39 step 3), and the status refreshed;
//   draw()     B/pi through the RadiosityRenderer (Gouraud or flat, outlines, the ambient
//              estimate, or the unshot heat map), the last shooter in magenta;
//   read()     the clicked patch: E, rho, area, radiosity, unshot, B and B/pi.
//
// Patch size and hemicube resolution are fixed for a view's life: a remesh builds a new one.
// The solver keeps the mesh and the scene by reference: the view must go before the scene does.
#include <chrono>

#include <nlohmann/json.hpp>

#include "app/viewer/picking.h"
#include "app/models/radiosity/item_buffer_texture.h"
#include "app/models/radiosity/radiosity_state.h"
#include "core/camera.h"
#include "core/scene.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/radiosity_renderer.h"
#include "radiosity/shooting.h"

namespace luz::app {

class RadiositySession {
public:
  // Meshes the scene and starts the solver (slide 39 step 1); needs a current GL context.
  RadiositySession(const Scene& scene, const RadiosityOptions& options);
  RadiositySession(const RadiositySession&) = delete;
  RadiositySession& operator=(const RadiositySession&) = delete;

  // True when this view's mesh and hemicube are those `options` ask for.
  bool built_for(const RadiosityOptions& options) const;

  // This frame's shooting (see above), with the viewer's `options`. Fills state.status; clears
  // the requests it did.
  // `exposure`: the viewer's, taken out of the heat map so its ramp shows as it is;
  // `heat_map`: the vertex colours show the unshot power instead of B/pi.
  void advance(RadiosityState& state, const RadiosityOptions& options, float exposure, bool heat_map);

  // Shots in a pass that draws no frame, where the viewer paces its frames (the page's, see
  // ViewerSettings::paced_frames): while the loop runs, within the drive's budget, and never the
  // shot past what ends the run (the stopping rule, a `wait-shots` count), which the next frame's
  // advance() ends and shows. The requests, the status and the colours wait for that frame.
  bool shoots_between_frames(const RadiosityState& state) const;
  void shoot_between_frames(const RadiosityState& state);

  // The picture into the bound framebuffer, width x height pixels; the last shooter in magenta
  // when `show_shooter`.
  void draw(const Camera& camera, int width, int height, bool show_shooter);

  // The patch under a picked point of a scene triangle.
  PatchReading read(const Pick& pick) const;

  const PatchMesh& mesh() const { return mesh_; }
  const ProgressiveSolver& solver() const { return solver_; }

private:
  void refresh_status(RadiosityState& state, const RadiosityOptions& options) const;
  // "patch 12 (floor)" for shooter 12, "light 0 (key)" for -1 - 0 once shot, "" before any shot.
  std::string shooter_name(int shooter, int shots) const;

  const Scene& scene_;
  RadiosityOptions built_with_;
  PatchMesh mesh_;             // before the solver and the renderer, which keep references to it
  ProgressiveSolver solver_;
  RadiosityRenderer renderer_;
  ItemBufferTexture item_view_;

  bool colours_stale_ = true;     // the solution changed since the colours were uploaded
  bool heat_map_shown_ = false;   // what the uploaded colours are ...
  float exposure_shown_ = 0.0f;
  RadiosityOptions shown_with_;   // ... and with which display switches
  int item_view_shot_ = -1;       // the shot whose item buffer the overlay shows ...
  int item_view_shooter_ = -1;    // ... and its shooter
  std::chrono::steady_clock::time_point item_view_due_;  // the overlay's next redraw while running

  std::chrono::steady_clock::time_point last_advance_ = std::chrono::steady_clock::now();
  int shots_between_frames_ = 0;  // since the last advance(), counted in its rate
  double shots_per_second_ = 0.0;
};

// The heat map's fixed scale: a patch's unshot exitance in units of the scene's mean emitted
// exitance (the emitted power spread over all the patches' area), whatever the mesh's size, on
// a log scale from kHeatMapLowest (dark blue) to kHeatMapHighest and above (yellow). So the
// picture darkens as the solve converges (a scale from the current maximum would show red to
// the end). heat_colour() is the ramp the picture and the panel's legend share.
inline constexpr double kHeatMapLowest = 1e-3;
inline constexpr double kHeatMapHighest = 1.0;
Rgb heat_colour(double relative);  // black for nothing to shoot
RadianceField unshot_heat_map(const ProgressiveSolver& solver);

// For the script's dump-patch and dump-radiosity (tests, handouts).
nlohmann::json to_json(const PatchReading& reading);
nlohmann::json to_json(const RadiosityState& state, const RadiosityOptions& options);

}  // namespace luz::app
