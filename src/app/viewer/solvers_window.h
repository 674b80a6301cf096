#pragma once
// Slide 36 in the viewer: SolverComparison (src/radiosity/solver_comparison.h) on the current
// scene, stepped on the GL thread within a per-frame time budget, its residual and error curves
// drawn live in a window of their own, so the class sees why shooting shows a usable picture
// first: a shot uses one form-factor row, a Jacobi or Gauss-Seidel sweep all N of them.
//
//   advance()  every frame while the window is open: the first time a frame that says "building",
//              then the mesh, the N hemicubes of the matrix and B* (one long frame); then, while
//              running, SolverComparison::step() until the frame's budget is spent;
//   draw()     the window: controls, the two log-log plots with a legend, the caption.
//
// The window owns its state: the viewer's loop, the script's `solvers` verbs, J and the radiosity
// panel's button (both run `solvers toggle`) reach it through the viewer, never through the
// ViewerState every model's view can write. Its comparison needs the GL context current (the
// hemicubes draw through it) and keeps the scene by reference: scene_changed() lets go of it
// before the scene goes.
#include <cstddef>
#include <memory>
#include <string>

#include <glm/vec2.hpp>

#include <nlohmann/json.hpp>

#include "app/cli/solvers_command.h"
#include "core/color.h"
#include "core/scene.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/solver_comparison.h"

namespace luz::app {

// Slide 36's window (the J window): the system solved by Jacobi, Gauss-Seidel, Southwell and
// shooting side by side, on a coarse mesh of its own.
struct SolversState {
  bool open = false;          // the window is shown (J, the panel's button, `solvers open`)
  bool running = false;
  float budget_ms = 20.0f;    // stepping time per frame while running (GL thread)
  // The budget was chosen (`solvers budget MS`): each frame steps it and no more. Left at its
  // default, a viewer that paces its frames (the page's) steps between them too.
  bool budget_chosen = false;
  // Its own coarse mesh, whatever model 5 uses: the matrix has one hemicube per patch and up to
  // N^2 entries, and the class should see the curves within seconds.
  int target_patches = 400;
  int sweeps = 20;            // each method stops after this many sweeps' worth of rows

  // Requests, done by the window at the next frame.
  bool reset = false;         // build again (the mesh, the matrix, B*) and start over, paused
  size_t run_to_rows = 0;     // `wait-solver-rows N`: run, then pause once every method used N rows

  // What the window shows of the comparison, refreshed every frame.
  enum class Phase { none, building, ready, refused };
  struct Status {
    Phase phase = Phase::none;
    std::string message;      // why it was refused, or what the build is doing
    size_t patches = 0;
    size_t max_rows = 0;
    size_t rows = 0;          // the fewest rows any method has used (they advance together)
    bool done = false;        // every method reached max_rows (or converged)
    double matrix_seconds = 0.0;
    // Where the window drew its two plots, window coordinates (for the tests); zero if not drawn.
    glm::vec2 plot_min{0.0f}, plot_max{0.0f};
  } status;
};

class SolversWindow {
public:
  SolversWindow() = default;
  SolversWindow(const SolversWindow&) = delete;
  SolversWindow& operator=(const SolversWindow&) = delete;

  // What it shows and what was asked of it.
  const SolversState& state() const { return state_; }
  // The script's `solvers` and `wait-solver-rows`, J.
  void set_open(bool open) { state_.open = open; }
  void set_running(bool running) { state_.running = running; }
  void reset() { state_.reset = true; }
  void set_budget(float ms) {
    state_.budget_ms = ms;
    state_.budget_chosen = true;
  }
  void set_patches(int target) {  // on a new mesh: built again
    state_.target_patches = target;
    state_.reset = true;
  }
  void run_to_rows(size_t rows) {  // opens it, runs, pauses once every method used `rows` rows
    state_.open = true;
    state_.run_to_rows = rows;
  }

  // A new scene: the comparison on the old one goes, paused, and is built again when next shown.
  void scene_changed(const Scene& scene);
  // Its frame's work, on the GL thread (see above): nothing while closed and asked for nothing.
  // The plots' rectangles are cleared until draw() draws them again.
  void advance();
  // The window (ImGui only), when open; its close button closes it.
  // First shown at (x, y), width x height window units; the class may move and resize it.
  // `pinned`: kept at that place and size every frame (a lesson's dock), else placed there when
  // it opens and moved freely after.
  void draw(float x, float y, float width, float height, bool pinned);
  // A request still playing out over frames (rows asked for, a reset, the matrix being built).
  bool busy() const;
  // Work that changes what it shows from frame to frame (the methods stepping, or busy()).
  bool working() const;
  // Its steps may wait for the next paced frame (ViewerSettings::paced_frames): running at the
  // default budget, built, with rows left to step. Each read-back of a shot's hemicube waits for
  // the browser's drawing, so the page steps in the passes between its frames as well.
  bool paced() const;
  // A pass that draws no frame: a budget of steps, never the step past the rows asked for, which
  // the next frame's advance() ends and shows.
  void step_between_frames();

  const SolverComparison* comparison() const { return race_.get(); }

private:
  void build();
  // Steps until `ms` is spent, at least one (a sweep or a shot may take longer): false once
  // there is nothing left to step (the rows asked for reached, or every method done).
  bool step_for(float ms);

  SolversState state_;
  const Scene* scene_ = nullptr;
  std::unique_ptr<PatchMesh> mesh_;        // before race_, which keeps a reference to it
  std::unique_ptr<SolverComparison> race_;
};

// For the script's dump-solvers: the status and every method's curve.
nlohmann::json to_json(const SolversWindow& window);

}  // namespace luz::app
