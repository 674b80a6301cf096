#pragma once
// `luz solvers SCENE --csv FILE [--png FILE]`: slide 36's Jacobi, Gauss-Seidel and Southwell
// beside slide 39's shooting on one scene (radiosity/solver_comparison.h), their curves written
// as CSV and plotted.
#include <string>

#include "core/color.h"
#include "radiosity/radiosity_options.h"
#include "radiosity/solver_comparison.h"

namespace luz::app {

struct SolversSettings {
  std::string scene;
  std::string csv;
  std::string png;                 // optional
  float patch_size = 0.0f;         // 0: from `patches`
  int patches = 400;               // about this many patches (when no --patch-size)
  int hemicube_res = 64;
  // analytic: F_ij from Lambert's contour integral, the hemicube giving only the visibility, so
  // that the shooting's columns and the matrix's rows are reciprocal; hemicube: both from the
  // hemicube's point-to-area values, which are not.
  FormFactorMethod form_factors = FormFactorMethod::analytic;
  int iterations = 20;             // Jacobi and Gauss-Seidel sweeps; the others run as many rows
  bool quiet = false;
};

// One colour and name per method, shared by `luz solvers`' PNG and the viewer's window.
Rgb method_colour(Method method);
const char* method_label(Method method);

// A full matrix is N^2: larger meshes are refused (bad input, exit 1).
inline constexpr size_t kMaxSolverPatches = 5000;

// Returns the exit code (0, 1 bad input, 2 usage) after printing any message.
int run_solvers(const SolversSettings& settings);

}  // namespace luz::app
