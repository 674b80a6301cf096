#pragma once
// The radiosity system of slide 36 in matrix form, and the three classic ways to solve it side
// by side: Jacobi, Gauss-Seidel and Southwell.
//
//   B_i = E_i + rho_i sum_j F_ij B_j        for every patch i, that is   (I - rho F) B = E
//
// F is the full form-factor matrix: row i is the hemicube of patch i (Hemicube::row), so
// building it costs one hemicube per patch before any method can start. Jacobi and Gauss-Seidel
// gather: a sweep evaluates every row once. Southwell relaxes one equation at a time, the one
// with the largest residual power; it needs column i of F to update the other residuals.
// Progressive shooting (slide 39, shooting.h) is Southwell with that column taken from row i by
// reciprocity, F_ji = F_ij A_i / A_j, so it never needs the whole matrix (Gortler, Cohen and
// Slusallek, "Radiosity and Relaxation Methods", IEEE CG&A 14(6), 1994; Cohen, Chen, Wallace
// and Greenberg, SIGGRAPH 1988).
//
// Exitances are RGB in double here (residuals are followed down to 1e-10 of E).
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "radiosity/hemicube.h"
#include "radiosity/patch_mesh.h"

namespace luz {

using Exitance = glm::dvec3;  // W/m^2 per channel

// F by rows (F_ij, j seen from i) and by columns (F_ji for every j: the same entries, sorted by
// column), both sparse.
struct FormFactorMatrix {
  std::vector<std::vector<FormFactor>> rows;
  std::vector<std::vector<FormFactor>> columns;  // columns[i] lists (j, F_ji)
  double seconds = 0.0;                          // spent drawing the hemicubes

  size_t size() const { return rows.size(); }
  size_t nonzeros() const;
  // One hemicube per patch, unrotated (needs the hemicube's GL context).
  static FormFactorMatrix build(const PatchMesh& mesh, Hemicube& hemicube);
  // The analytic method's rows (shooting.h, FormFactorMethod::analytic) seen from the receiver:
  // patch i's hemicube says which part of patch j it sees, and F_ij is that part of Lambert's
  // contour integral from patch i to patch j's triangle, the same integral the shooting uses
  // from j's side. Reciprocity A_i F_ij = A_j F_ji then holds but for the visibility, so that
  // shooting and gathering solve the same system. The mesh must be one element per patch.
  static FormFactorMatrix build_analytic(const PatchMesh& mesh, Hemicube& hemicube);
  // From rows given by hand (tests); fills the columns.
  static FormFactorMatrix from_rows(std::vector<std::vector<FormFactor>> rows);
};

// Everything of (I - rho F) B = E but B.
struct RadiositySystem {
  FormFactorMatrix F;
  std::vector<Exitance> E;     // exitance emitted (W/m^2), with any first bounce of point lights
  std::vector<Exitance> rho;   // diffuse reflectance
  std::vector<double> area;    // m^2: weights of the norm

  size_t size() const { return E.size(); }
  // E = pi Le, rho and A of the mesh's patches.
  static RadiositySystem of(const PatchMesh& mesh, FormFactorMatrix F);
};

// rho_i sum_j F_ij B_j: what patch i reflects of the exitance it gathers (row i of rho F B).
Exitance gathered(const RadiositySystem& s, const std::vector<Exitance>& B, size_t i);

// ---- The three methods of slide 36 -----------------------------------------------------------
// Jacobi: B^(k+1) = E + rho F B^(k). Every row reads only the previous sweep's B; `next` is
// scratch of the same size.
void jacobi_sweep(const RadiositySystem& s, std::vector<Exitance>& B, std::vector<Exitance>& next);

// Gauss-Seidel: the same rows, in place: row i already reads the new B_j of the rows before it.
void gauss_seidel_sweep(const RadiositySystem& s, std::vector<Exitance>& B);

// Southwell: r = E - (I - rho F) B is kept up to date; relax the equation i with the largest
// residual power A_i |r_i| (B_i grows by what makes r_i zero) and pass that change to the others
// through column i: r_j += rho_j F_ji dB_i. Returns i.
size_t southwell_step(const RadiositySystem& s, std::vector<Exitance>& B, std::vector<Exitance>& r);

// ---- Measuring them ----------------------------------------------------------------------------
// r = E - (I - rho F) B.
std::vector<Exitance> residual(const RadiositySystem& s, const std::vector<Exitance>& B);
// Area-weighted L1 norm, sum_i A_i mean_rgb |v_i|: a power in W (for r, the "unshot" power of
// slide 39's step 2; for B - B*, the power misplaced).
double power_norm(const RadiositySystem& s, const std::vector<Exitance>& v);
double power_norm_of_difference(const RadiositySystem& s, const std::vector<Exitance>& a,
                                const std::vector<Exitance>& b);
// Gauss-Seidel until |r| < tolerance |E| (or `max_sweeps`): the reference "converged" B.
std::vector<Exitance> converged_solution(const RadiositySystem& s, double tolerance = 1e-10,
                                         int max_sweeps = 10000);

}  // namespace luz
