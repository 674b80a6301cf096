// Slide 36's methods beside slide 39's shooting (see solver_comparison.h).
#include "radiosity/solver_comparison.h"

#include <algorithm>
#include <chrono>

namespace luz {

namespace {

size_t index(Method method) { return size_t(method); }

std::vector<Exitance> to_double(const std::vector<Rgb>& v) {
  std::vector<Exitance> out(v.size());
  for (size_t i = 0; i < v.size(); ++i) out[i] = Exitance(v[i].r, v[i].g, v[i].b);
  return out;
}

constexpr double kConverged = 1e-12;  // a method whose residual falls below this stops

}  // namespace

const char* to_string(Method method) {
  switch (method) {
    case Method::jacobi: return "jacobi";
    case Method::gauss_seidel: return "gauss-seidel";
    case Method::southwell: return "southwell";
    case Method::shooting: return "shooting";
  }
  return "?";
}

SolverComparison::SolverComparison(const Scene& scene, PatchMesh& mesh,
                                   const RadiosityOptions& options, size_t max_rows)
    : max_rows_(max_rows) {
  // The shooting of slide 39, its hemicube unrotated so that its rows are the matrix's rows:
  // what differs is only how it uses them (column i by reciprocity). It runs until told to stop.
  // Ray-cast factors are random per shot, so rays mean the analytic method here.
  RadiosityOptions shooting_options = options;
  shooting_options.random_rotation = false;
  if (shooting_options.form_factors == FormFactorMethod::rays) shooting_options.form_factors = FormFactorMethod::analytic;
  shooting_options.meshing = Meshing::uniform;                 // the matrix's own elements
  shooting_options.max_shots = 0;
  shooting_options.converge = 0.0f;
  shooting_options.ambient_estimate = false;
  shooting_ = std::make_unique<ProgressiveSolver>(scene, mesh, shooting_options);
  // Point lights first: what they leave on the patches becomes part of everyone's E.
  while (shooting_->lights_left() > 0) shooting_->step();

  system_ = RadiositySystem::of(mesh, shooting_options.form_factors == FormFactorMethod::analytic
                                          ? FormFactorMatrix::build_analytic(mesh, shooting_->hemicube())
                                          : FormFactorMatrix::build(mesh, shooting_->hemicube()));
  system_.E = to_double(shooting_->displayed());  // pi Le + rho (direct light of point lights)
  converged_ = converged_solution(system_);
  converged_norm_ = std::max(power_norm(system_, converged_), 1e-300);
  emitted_norm_ = std::max(power_norm(system_, system_.E), 1e-300);

  const std::vector<Exitance> zero(mesh.size(), Exitance(0.0));
  jacobi_ = gauss_seidel_ = southwell_ = zero;
  southwell_r_ = system_.E;  // r = E - (I - rho F) 0
  for (const Method m : kMethods) record(m);
}

SolverComparison::~SolverComparison() = default;

size_t SolverComparison::rows(Method method) const {
  const size_t n = size_t(iterations_[index(method)]);
  return method == Method::jacobi || method == Method::gauss_seidel ? n * system_.size() : n;
}

bool SolverComparison::done(Method method) const {
  return rows(method) >= max_rows_ || curves_[index(method)].back().residual < kConverged;
}

bool SolverComparison::step() {
  // The method that has used the fewest rows goes next (ties: in kMethods' order).
  const Method* next = nullptr;
  for (const Method& m : kMethods)
    if (!done(m) && (!next || rows(m) < rows(*next))) next = &m;
  if (!next) return false;
  iterate(*next);
  record(*next);
  return true;
}

void SolverComparison::iterate(Method method) {
  const auto start = std::chrono::steady_clock::now();
  switch (method) {
    case Method::jacobi: jacobi_sweep(system_, jacobi_, jacobi_next_); break;
    case Method::gauss_seidel: gauss_seidel_sweep(system_, gauss_seidel_); break;
    case Method::southwell: southwell_step(system_, southwell_, southwell_r_); break;
    case Method::shooting: shooting_->step(); break;
  }
  seconds_[index(method)] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++iterations_[index(method)];
}

std::vector<Exitance> SolverComparison::shown(Method method) const {
  switch (method) {
    case Method::jacobi: return jacobi_;
    case Method::gauss_seidel: return gauss_seidel_;
    case Method::southwell: return southwell_;
    case Method::shooting: return to_double(shooting_->displayed());
  }
  return {};
}

// Measuring is not timed: only iterate() adds to a method's seconds.
void SolverComparison::record(Method method) {
  SolverSample sample;
  sample.iteration = iterations_[index(method)];
  sample.rows = rows(method);
  sample.seconds = seconds_[index(method)] + (method == Method::shooting ? 0.0 : matrix_seconds());
  const std::vector<Exitance> B = shown(method);
  if (method == Method::southwell)
    sample.residual = power_norm(system_, southwell_r_) / emitted_norm_;  // kept exactly
  else if (method == Method::shooting)
    sample.residual = power_norm(system_, to_double(shooting_->unshot())) / emitted_norm_;
  else
    sample.residual = power_norm(system_, residual(system_, B)) / emitted_norm_;
  sample.error = power_norm_of_difference(system_, B, converged_) / converged_norm_;
  curves_[index(method)].push_back(sample);
}

std::span<const SolverSample> SolverComparison::curve(Method method) const {
  return curves_[index(method)];
}

}  // namespace luz
