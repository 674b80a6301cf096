#pragma once
// Slide 36's three methods and slide 39's shooting, run side by side on one scene so the class
// sees their convergence curves: residual and error against the converged solution, per
// iteration, per form-factor row used and per second.
//
//   SolverComparison race(scene, mesh, options, max_rows);    // the full matrix is built here
//   while (race.step()) { plot(race.curve(Method::jacobi)); ... }   // live, one iteration a step
//
// step() advances the method that has used the fewest form-factor rows so far, one iteration
// (a Jacobi or Gauss-Seidel sweep = N rows, a Southwell relaxation or a shot = 1 row), so the
// four curves move forward together along the rows axis and a viewer can call it within a
// frame's time budget (a sweep costs N sparse rows on the CPU, a shot one hemicube on the GPU).
//
// What each number means:
// - rows: form-factor rows used. Jacobi and Gauss-Seidel use every row per sweep; Southwell
//   relaxes one equation (its column) per step; a shot draws one hemicube.
// - seconds: measured time of the method's own work. Jacobi, Gauss-Seidel and Southwell are
//   also charged the time to build the whole matrix (matrix_seconds()), since none can take its
//   first step before every hemicube is drawn; the shooting draws its hemicubes as it goes.
// - residual: |r| / |E| with r = E - (I - rho F) B and |v| = sum_i A_i mean_rgb |v_i| (a power).
//   For the shooting, r is its unshot exitance, the residual of the system it solves (its
//   column from reciprocity, F_ij A_i / A_j: shooting.h).
// - error: |B - B*| / |B*|, B* = Gauss-Seidel to |r| < 1e-10 |E|. B is what each method would
//   show: Jacobi's, Gauss-Seidel's and Southwell's iterate; for the shooting radiosity + unshot
//   (slide 39's step 3).
//
// Needs a current GL context for its whole life (the hemicube and the shooting draw through it).
#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/scene.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/radiosity_options.h"
#include "radiosity/shooting.h"
#include "radiosity/system_solvers.h"

namespace luz {

enum class Method { jacobi, gauss_seidel, southwell, shooting };
inline constexpr std::array<Method, 4> kMethods = {Method::jacobi, Method::gauss_seidel,
                                                   Method::southwell, Method::shooting};
const char* to_string(Method method);  // "jacobi", "gauss-seidel", "southwell", "shooting"

struct SolverSample {
  int iteration = 0;   // sweeps for Jacobi and Gauss-Seidel, relaxations or shots for the others
  size_t rows = 0;
  double seconds = 0.0;
  double residual = 1.0;
  double error = 1.0;
};

class SolverComparison {
public:
  // Builds F (one unrotated hemicube per patch, options.hemicube_res), the system, and B*.
  // Point lights are shot once first, and what their light leaves on the patches is part of E
  // for every method. Each method stops after `max_rows` rows (or once its residual is 1e-12).
  SolverComparison(const Scene& scene, PatchMesh& mesh, const RadiosityOptions& options,
                   size_t max_rows);
  ~SolverComparison();

  // One iteration of the method with the fewest rows used; false when all four are done.
  bool step();
  bool done(Method method) const;

  std::span<const SolverSample> curve(Method method) const;
  // The exitance each method would show now (W/m^2), and the converged one.
  std::vector<Exitance> shown(Method method) const;
  const std::vector<Exitance>& converged() const { return converged_; }

  const RadiositySystem& system() const { return system_; }
  double matrix_seconds() const { return system_.F.seconds; }
  size_t max_rows() const { return max_rows_; }

private:
  void iterate(Method method);
  void record(Method method);
  size_t rows(Method method) const;

  RadiositySystem system_;
  std::vector<Exitance> converged_;
  double converged_norm_ = 1.0, emitted_norm_ = 1.0;
  size_t max_rows_;
  std::unique_ptr<ProgressiveSolver> shooting_;
  std::vector<Exitance> jacobi_, jacobi_next_, gauss_seidel_, southwell_, southwell_r_;
  std::array<int, 4> iterations_{};
  std::array<double, 4> seconds_{};  // own work only
  std::array<std::vector<SolverSample>, 4> curves_;
};

}  // namespace luz
