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
// Needs the GL context current for its whole life (the hemicubes draw through it). It keeps the
// scene by reference: the view must go before the scene does.
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/solvers_command.h"
#include "app/viewer/solvers_state.h"
#include "core/color.h"
#include "core/scene.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/solver_comparison.h"

namespace luz::app {

class SolversWindow {
public:
  explicit SolversWindow(const Scene& scene) : scene_(scene) {}
  SolversWindow(const SolversWindow&) = delete;
  SolversWindow& operator=(const SolversWindow&) = delete;

  void advance(SolversState& state);
  // The window (ImGui only); `open` is cleared by its close button.
  // First shown at (x, y), width x height window units; the class may move and resize it.
  // `pinned`: kept at that place and size every frame (a lesson's dock), else placed there when
  // it opens and moved freely after.
  void draw(SolversState& state, float x, float y, float width, float height, bool pinned) const;

  const SolverComparison* comparison() const { return race_.get(); }

private:
  void build(SolversState& state);

  const Scene& scene_;
  std::unique_ptr<PatchMesh> mesh_;        // before race_, which keeps a reference to it
  std::unique_ptr<SolverComparison> race_;
};

// For the script's dump-solvers: the status and every method's curve.
nlohmann::json to_json(const SolversState& state, const SolversWindow* view);

}  // namespace luz::app
