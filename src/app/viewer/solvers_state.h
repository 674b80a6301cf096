#pragma once
// Slide 36's window in the viewer's state: the system (I - rho F) B = E solved four ways side by
// side (Jacobi, Gauss-Seidel, Southwell, shooting), their curves plotted live. Plain data, no
// GL: the comparison itself lives in SolversWindow (solvers_window.h), which fills `status`.
#include <cstddef>
#include <string>

#include <glm/vec2.hpp>

namespace luz::app {

struct SolversState {
  bool open = false;          // the window is shown (J, the panel's button, `solvers open`)
  bool running = false;
  float budget_ms = 20.0f;    // stepping time per frame while running (GL thread)
  // Its own coarse mesh, whatever model 5 uses: the matrix has one hemicube per patch and up to
  // N^2 entries, and the class should see the curves within seconds.
  int target_patches = 400;
  int sweeps = 20;            // each method stops after this many sweeps' worth of rows

  // Requests, done by the view at the next frame.
  bool reset = false;         // build again (the mesh, the matrix, B*) and start over, paused
  size_t run_to_rows = 0;     // `wait-solver-rows N`: run, then pause once every method used N rows

  // What the window shows of the comparison, refreshed by the view every frame.
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

}  // namespace luz::app
