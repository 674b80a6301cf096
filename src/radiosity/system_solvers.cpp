// Slide 36: (I - rho F) B = E solved by Jacobi, Gauss-Seidel and Southwell. See system_solvers.h.
//
// Sections: [the matrix] [the three methods] [measures]
#include "radiosity/system_solvers.h"

#include <chrono>
#include <cmath>
#include <numbers>

#include "radiosity/element_form_factor.h"
#include "radiosity/polygon_form_factor.h"

namespace luz {

namespace {

Exitance to_double(const Rgb& c) { return Exitance(c.r, c.g, c.b); }
double mean_abs(const Exitance& v) { return (std::abs(v.x) + std::abs(v.y) + std::abs(v.z)) / 3.0; }

}  // namespace

// ---- [the matrix] ------------------------------------------------------------------------------
size_t FormFactorMatrix::nonzeros() const {
  size_t n = 0;
  for (const auto& row : rows) n += row.size();
  return n;
}

FormFactorMatrix FormFactorMatrix::build(const PatchMesh& mesh, Hemicube& hemicube) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::vector<FormFactor>> rows(mesh.size());
  for (size_t i = 0; i < mesh.size(); ++i) rows[i] = hemicube.row(i);  // a hemicube per patch
  FormFactorMatrix F = from_rows(std::move(rows));
  F.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return F;
}

FormFactorMatrix FormFactorMatrix::build_analytic(const PatchMesh& mesh, Hemicube& hemicube) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::vector<FormFactor>> rows(mesh.size());
  for (size_t i = 0; i < mesh.size(); ++i) {
    const Patch& receiver = mesh.patches[i];
    const glm::vec3 eye = receiver.centre + Hemicube::eye_height(receiver.clearance) * receiver.normal;
    for (const FormFactor& seen : hemicube.row(i)) {
      const ShootingPatch& sender = mesh.shooters[mesh.shooter_of[seen.patch]];
      const double unoccluded = point_to_polygon_form_factor(eye, receiver.normal, sender.corners);
      if (!(unoccluded > 0.0)) {  // as the shooting does: seen only past its edge, in a pixel
        rows[i].push_back(seen);
        continue;
      }
      const double visible = double(seen.value) / unoccluded;
      rows[i].push_back({seen.patch, float(visible * element_to_patch_form_factor(mesh, receiver, sender))});
    }
  }
  FormFactorMatrix F = from_rows(std::move(rows));
  F.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return F;
}

FormFactorMatrix FormFactorMatrix::from_rows(std::vector<std::vector<FormFactor>> rows) {
  FormFactorMatrix F;
  F.rows = std::move(rows);
  F.columns.resize(F.rows.size());
  for (size_t j = 0; j < F.rows.size(); ++j)
    for (const FormFactor& f : F.rows[j]) F.columns[f.patch].push_back({uint32_t(j), f.value});
  return F;
}

RadiositySystem RadiositySystem::of(const PatchMesh& mesh, FormFactorMatrix F) {
  RadiositySystem s;
  s.F = std::move(F);
  for (const Patch& p : mesh.patches) {
    s.E.push_back(to_double(p.emission));  // E = pi Le (patch_mesh.cpp)
    s.rho.push_back(to_double(p.rho));
    s.area.push_back(double(p.area));
  }
  return s;
}

Exitance gathered(const RadiositySystem& s, const std::vector<Exitance>& B, size_t i) {
  Exitance sum(0.0);
  for (const FormFactor& f : s.F.rows[i]) sum += double(f.value) * B[f.patch];  // sum_j F_ij B_j
  return s.rho[i] * sum;
}

// ---- [the three methods] -----------------------------------------------------------------------
// Jacobi: B_i <- E_i + rho_i sum_j F_ij B_j, all i at once from the old B.
void jacobi_sweep(const RadiositySystem& s, std::vector<Exitance>& B, std::vector<Exitance>& next) {
  next.resize(B.size());
  for (size_t i = 0; i < s.size(); ++i) next[i] = s.E[i] + gathered(s, B, i);
  B.swap(next);
}

// Gauss-Seidel: B_i <- E_i + rho_i sum_j F_ij B_j, one i after the other in place.
void gauss_seidel_sweep(const RadiositySystem& s, std::vector<Exitance>& B) {
  for (size_t i = 0; i < s.size(); ++i) {
    // The diagonal F_ii (0 for a flat patch, which cannot see itself) is solved for, not lagged.
    Exitance F_ii(0.0);
    for (const FormFactor& f : s.F.rows[i])
      if (f.patch == i) F_ii = Exitance(double(f.value));
    const Exitance others = gathered(s, B, i) - s.rho[i] * F_ii * B[i];
    B[i] = (s.E[i] + others) / (Exitance(1.0) - s.rho[i] * F_ii);
  }
}

// Southwell: relax the equation with the largest residual power.
size_t southwell_step(const RadiositySystem& s, std::vector<Exitance>& B, std::vector<Exitance>& r) {
  size_t i = 0;
  double largest = -1.0;
  for (size_t k = 0; k < s.size(); ++k) {
    const double power = s.area[k] * mean_abs(r[k]);
    if (power > largest) {
      largest = power;
      i = k;
    }
  }
  // Equation i reads r_i = E_i - (1 - rho_i F_ii) B_i + rho_i sum_{j != i} F_ij B_j, so
  // dB_i = r_i / (1 - rho_i F_ii) makes it zero ...
  Exitance F_ii(0.0);
  for (const FormFactor& f : s.F.rows[i])
    if (f.patch == i) F_ii = Exitance(double(f.value));
  const Exitance dB = r[i] / (Exitance(1.0) - s.rho[i] * F_ii);
  B[i] += dB;
  // ... and every equation j that gathers from i sees it: r_j += rho_j F_ji dB_i.
  for (const FormFactor& f : s.F.columns[i])
    if (f.patch != i) r[f.patch] += s.rho[f.patch] * double(f.value) * dB;
  r[i] = Exitance(0.0);
  return i;
}

// ---- [measures] --------------------------------------------------------------------------------
std::vector<Exitance> residual(const RadiositySystem& s, const std::vector<Exitance>& B) {
  std::vector<Exitance> r(s.size());
  for (size_t i = 0; i < s.size(); ++i) r[i] = s.E[i] - B[i] + gathered(s, B, i);
  return r;
}

double power_norm(const RadiositySystem& s, const std::vector<Exitance>& v) {
  double total = 0.0;
  for (size_t i = 0; i < s.size(); ++i) total += s.area[i] * mean_abs(v[i]);
  return total;
}

double power_norm_of_difference(const RadiositySystem& s, const std::vector<Exitance>& a,
                                const std::vector<Exitance>& b) {
  double total = 0.0;
  for (size_t i = 0; i < s.size(); ++i) total += s.area[i] * mean_abs(a[i] - b[i]);
  return total;
}

std::vector<Exitance> converged_solution(const RadiositySystem& s, double tolerance, int max_sweeps) {
  std::vector<Exitance> B(s.size(), Exitance(0.0));
  const double target = tolerance * power_norm(s, s.E);
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    gauss_seidel_sweep(s, B);
    if (power_norm(s, residual(s, B)) <= target) break;
  }
  return B;
}

}  // namespace luz
