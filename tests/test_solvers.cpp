// Slide 36's system (I - rho F) B = E and its solvers (radiosity/system_solvers.h), beside the
// shooting of slide 39 (radiosity/solver_comparison.h).
//
// - A two-patch system worked by hand: each of Jacobi, Gauss-Seidel and Southwell reaches its
//   solution to 1e-12, and Jacobi's and Gauss-Seidel's residuals fall as their closed forms
//   4^-k and 16^-k say (10 and 5 sweeps to 1e-6).
// - A closed diffuse box with an emitting ceiling (192 patches, hemicube 64): the residuals of
//   Jacobi and Gauss-Seidel fall at every sweep; Gauss-Seidel reaches |r| < 1e-6 |E| in fewer
//   sweeps than Jacobi; Jacobi, Gauss-Seidel and Southwell end within 1e-6 (area-weighted L1,
//   relative) of the converged B, and the shooting within 1%: it solves the system whose column
//   i is row i by reciprocity, F_ji = F_ij A_i / A_j, which the analytic form factors keep (the
//   same contour integral both ways; only the visibility, here nearly 1 everywhere, comes from
//   each side's hemicube). With the hemicube's own point-to-area values, which between
//   neighbouring patches are not reciprocal to better than a few percent, the shooting ends
//   several times farther away (within 5%).
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/scene.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/solver_comparison.h"
#include "radiosity/system_solvers.h"
#include "radiosity_scenes.h"

namespace luz {
namespace {

// Two unit patches facing each other with F_12 = F_21 = 1/2, rho = 1/2, E = (1, 0):
//   B_1 = 1 + B_2 / 4,  B_2 = B_1 / 4   =>   B_1 = 16/15, B_2 = 4/15.
RadiositySystem two_patches() {
  RadiositySystem s;
  s.F = FormFactorMatrix::from_rows({{{1, 0.5f}}, {{0, 0.5f}}});
  s.E = {Exitance(1.0), Exitance(0.0)};
  s.rho = {Exitance(0.5), Exitance(0.5)};
  s.area = {1.0, 1.0};
  return s;
}

void expect_two_patch_solution(const std::vector<Exitance>& B) {
  EXPECT_NEAR(B[0].x, 16.0 / 15.0, 1e-12);
  EXPECT_NEAR(B[1].y, 4.0 / 15.0, 1e-12);
}

TEST(SystemSolvers, JacobiSolvesTheHandWorkedSystem) {
  const RadiositySystem s = two_patches();
  std::vector<Exitance> B(2, Exitance(0.0)), next;
  for (int sweep = 0; sweep < 40; ++sweep) jacobi_sweep(s, B, next);
  expect_two_patch_solution(B);
}

TEST(SystemSolvers, GaussSeidelSolvesTheHandWorkedSystem) {
  const RadiositySystem s = two_patches();
  std::vector<Exitance> B(2, Exitance(0.0));
  for (int sweep = 0; sweep < 20; ++sweep) gauss_seidel_sweep(s, B);
  expect_two_patch_solution(B);
}

// The residual of each sweep on the two patches, in closed form. Jacobi's iteration matrix is
// rho F = [[0, 1/4], [1/4, 0]] and its residual obeys r^(k+1) = (rho F) r^(k): from r^(0) = E =
// (1, 0) it alternates between the patches, |r^(k)| = 4^-k. A Gauss-Seidel sweep sets B_2 from
// the new B_1, so r_2 = 0 after it and r_1 = (change of B_2) / 4, which shrinks by 1/16 a sweep:
// |r^(k)| = 16^-k, the square of Jacobi's rate (Gauss-Seidel's spectral radius is the square of
// Jacobi's for this consistently ordered 2x2 system: Young's theorem).
// To |r| < 1e-6 |E|: Jacobi needs k > 6 / log10(4) = 9.97, 10 sweeps (4^-10 = 9.5e-7), and
// Gauss-Seidel k > 6 / log10(16) = 4.98, 5 sweeps (16^-5 = 9.5e-7), half as many.
int sweeps_to_residual(const RadiositySystem& s, double target, bool gauss_seidel,
                       std::vector<double>* history = nullptr) {
  std::vector<Exitance> B(s.size(), Exitance(0.0)), next;
  for (int sweep = 1; sweep <= 100; ++sweep) {
    if (gauss_seidel) gauss_seidel_sweep(s, B);
    else jacobi_sweep(s, B, next);
    const double r = power_norm(s, residual(s, B)) / power_norm(s, s.E);
    if (history) history->push_back(r);
    if (r < target) return sweep;
  }
  return -1;
}

TEST(SystemSolvers, JacobiResidualFallsByAQuarterASweepOnTheHandWorkedSystem) {
  std::vector<double> history;
  EXPECT_EQ(sweeps_to_residual(two_patches(), 1e-6, false, &history), 10);
  for (size_t k = 0; k < history.size(); ++k)
    EXPECT_NEAR(history[k], std::pow(4.0, -double(k + 1)), 1e-15) << "sweep " << k + 1;
}

TEST(SystemSolvers, GaussSeidelNeedsHalfJacobisSweepsOnTheHandWorkedSystem) {
  std::vector<double> history;
  EXPECT_EQ(sweeps_to_residual(two_patches(), 1e-6, true, &history), 5);
  for (size_t k = 0; k < history.size(); ++k)
    EXPECT_NEAR(history[k], std::pow(16.0, -double(k + 1)), 1e-15) << "sweep " << k + 1;
}

TEST(SystemSolvers, SouthwellSolvesTheHandWorkedSystemAndKeepsItsResidual) {
  const RadiositySystem s = two_patches();
  std::vector<Exitance> B(2, Exitance(0.0)), r = s.E;
  for (int step = 0; step < 40; ++step) southwell_step(s, B, r);
  expect_two_patch_solution(B);
  const std::vector<Exitance> exact = residual(s, B);  // the kept residual is the true one
  for (size_t i = 0; i < 2; ++i) EXPECT_NEAR(glm::length(r[i] - exact[i]), 0.0, 1e-15);
}

// ---- A closed diffuse box --------------------------------------------------------------------
void add_quad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, int material) {
  Mesh mesh;
  mesh.positions = {a, b, c, d};
  const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
  mesh.normals = {n, n, n, n};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = material;
  scene.meshes.push_back(mesh);
}

// The unit cube, faces inward: a grey floor and ceiling (the ceiling glows), red and green walls.
Scene closed_box() {
  Scene scene;
  const auto material = [&scene](Rgb kd, float le) {
    Material m;
    m.kd = kd;
    m.emission = Rgb(le);
    scene.materials.push_back(m);
    return int(scene.materials.size() - 1);
  };
  const int grey = material(Rgb(0.7f), 0.0f), light = material(Rgb(0.7f), 1.0f);
  const int red = material(Rgb(0.7f, 0.1f, 0.1f), 0.0f), green = material(Rgb(0.1f, 0.6f, 0.1f), 0.0f);
  using v = glm::vec3;
  add_quad(scene, v(0, 0, 0), v(0, 0, 1), v(1, 0, 1), v(1, 0, 0), grey);
  add_quad(scene, v(0, 1, 0), v(1, 1, 0), v(1, 1, 1), v(0, 1, 1), light);
  add_quad(scene, v(0, 0, 0), v(0, 1, 0), v(0, 1, 1), v(0, 0, 1), red);
  add_quad(scene, v(1, 0, 0), v(1, 0, 1), v(1, 1, 1), v(1, 1, 0), green);
  add_quad(scene, v(0, 0, 0), v(1, 0, 0), v(1, 1, 0), v(0, 1, 0), grey);
  add_quad(scene, v(0, 0, 1), v(0, 1, 1), v(1, 1, 1), v(1, 0, 1), grey);
  return scene;
}

class ClosedBox : public testing::Test {
protected:
  static constexpr int kSweeps = 30;
  static void SetUpTestSuite() {
    scene_ = new Scene(closed_box());
    RadiosityOptions options;
    options.patch_size = 0.4f;
    options.elements_per_edge = 1;  // the matrix methods solve on the patches themselves
    options.hemicube_res = 64;
    mesh_ = new PatchMesh(PatchMesh::build(*scene_, options));
    race_ = new SolverComparison(*scene_, *mesh_, options, size_t(kSweeps) * mesh_->size());
    while (race_->step()) {}
  }
  static void TearDownTestSuite() {
    delete race_;
    delete mesh_;
    delete scene_;
  }
  static Scene* scene_;
  static PatchMesh* mesh_;
  static SolverComparison* race_;
};
Scene* ClosedBox::scene_ = nullptr;
PatchMesh* ClosedBox::mesh_ = nullptr;
SolverComparison* ClosedBox::race_ = nullptr;

TEST_F(ClosedBox, JacobiAndGaussSeidelResidualsFallAtEverySweep) {
  ASSERT_GT(mesh_->size(), size_t(100));
  for (const Method m : {Method::jacobi, Method::gauss_seidel}) {
    const auto curve = race_->curve(m);
    ASSERT_GT(curve.size(), size_t(10)) << to_string(m);
    for (size_t k = 1; k < curve.size(); ++k)
      EXPECT_LT(curve[k].residual, curve[k - 1].residual) << to_string(m) << ", sweep " << k;
  }
}

TEST_F(ClosedBox, GaussSeidelNeedsFewerSweepsThanJacobi) {
  const auto sweeps_to = [](std::span<const SolverSample> curve, double target) {
    for (const SolverSample& s : curve)
      if (s.residual < target) return s.iteration;
    return 1 << 30;
  };
  const int jacobi = sweeps_to(race_->curve(Method::jacobi), 1e-6);
  const int gauss_seidel = sweeps_to(race_->curve(Method::gauss_seidel), 1e-6);
  EXPECT_LT(jacobi, kSweeps) << "Jacobi reaches 1e-6 within the sweeps run";
  // Strictly fewer: rho F is non-negative and irreducible (every wall sees another) with spectral
  // radius below 1, so by the Stein-Rosenberg theorem Gauss-Seidel's spectral radius is strictly
  // below Jacobi's.
  printf("sweeps to |r| < 1e-6 |E|: Jacobi %d, Gauss-Seidel %d\n", jacobi, gauss_seidel);
  EXPECT_LT(gauss_seidel, jacobi);
}

TEST_F(ClosedBox, TheFourMethodsConvergeToTheSameRadiosity) {
  for (const Method m : kMethods)
    printf("%-13s error %.3g, residual %.3g after %zu rows\n", to_string(m),
           race_->curve(m).back().error, race_->curve(m).back().residual, race_->curve(m).back().rows);
  for (const Method m : {Method::jacobi, Method::gauss_seidel, Method::southwell})
    EXPECT_LT(race_->curve(m).back().error, 1e-6) << to_string(m);
  EXPECT_LT(race_->curve(Method::shooting).back().residual, 1e-6) << "the shooting has converged";
  EXPECT_LT(race_->curve(Method::shooting).back().error, 0.01) << "the shooting's B, against B*";
  // B* itself solves the system.
  const RadiositySystem& s = race_->system();
  EXPECT_LT(power_norm(s, residual(s, race_->converged())), 1e-9 * power_norm(s, s.E));
}

// The same race with hemicube rows: the shooting converges, to a B farther from the matrix's.
TEST_F(ClosedBox, HemicubeRowsAreNotReciprocalAndTheShootingShowsIt) {
  RadiosityOptions options;
  options.patch_size = 0.4f;
  options.elements_per_edge = 1;
  options.hemicube_res = 64;
  options.form_factors = FormFactorMethod::hemicube;
  PatchMesh mesh = PatchMesh::build(*scene_, options);
  SolverComparison race(*scene_, mesh, options, size_t(kSweeps) * mesh.size());
  while (race.step()) {}
  const double analytic = race_->curve(Method::shooting).back().error;
  const double hemicube = race.curve(Method::shooting).back().error;
  printf("the shooting against the matrix's B*: analytic %.3g, hemicube %.3g\n", analytic, hemicube);
  EXPECT_LT(race.curve(Method::shooting).back().residual, 1e-6);
  EXPECT_LT(race.curve(Method::gauss_seidel).back().error, 1e-6);
  EXPECT_LT(hemicube, 0.05);
  EXPECT_LT(3.0 * analytic, hemicube);
}

TEST_F(ClosedBox, ShootingShowsAUsablePictureFirst) {
  // After as many rows as one sweep, the shooting's picture (radiosity + unshot) is closer to B*
  // than anything Jacobi or Gauss-Seidel can show before they finish their first sweep (B = 0).
  const size_t n = mesh_->size();
  double shooting_error = 1.0;
  for (const SolverSample& s : race_->curve(Method::shooting))
    if (s.rows <= n) shooting_error = s.error;
  EXPECT_LT(shooting_error, 0.5);
  // Jacobi's first sweep from B = 0 gives B = E exactly, so its first error is |E - B*| / |B*|,
  // what the light sources alone would show; the shooting's picture is better than that.
  const RadiositySystem& s = race_->system();
  const auto jacobi = race_->curve(Method::jacobi);
  ASSERT_GE(jacobi.size(), size_t(2));
  EXPECT_EQ(jacobi[1].iteration, 1);
  EXPECT_EQ(jacobi[1].rows, n);
  const double emitted_only = power_norm_of_difference(s, s.E, race_->converged()) /
                              power_norm(s, race_->converged());
  EXPECT_NEAR(jacobi[1].error, emitted_only, 1e-12);
  EXPECT_LT(shooting_error, emitted_only);
}


// ---- The analytic matrix ----------------------------------------------------------------------
// Reciprocity wall by wall: the sum over pairs of walls (a, b) of |A_a F_ab - A_b F_ba|, over the
// sum of A_a F_ab, where A_a F_ab = sum over i in a, j in b of A_i F_ij. Per patch pair, the
// visibility's pixel count is too noisy for small far patches to show anything.
double reciprocity_gap(const PatchMesh& mesh, const FormFactorMatrix& F, size_t walls) {
  std::vector<std::vector<double>> between(walls, std::vector<double>(walls, 0.0));
  for (size_t i = 0; i < mesh.size(); ++i)
    for (const FormFactor& f : F.rows[i])
      between[size_t(mesh.patches[i].mesh)][size_t(mesh.patches[f.patch].mesh)] +=
          double(mesh.patches[i].area) * f.value;
  double differences = 0.0, total = 0.0;
  for (size_t a = 0; a < walls; ++a)
    for (size_t b = 0; b < walls; ++b) {
      differences += std::abs(between[a][b] - between[b][a]);
      total += between[a][b];
    }
  return differences / total;
}

double worst_row_sum_error(const FormFactorMatrix& F) {
  double worst = 0.0;
  for (const auto& row : F.rows) {
    double sum = 0.0;
    for (const FormFactor& f : row) sum += f.value;
    worst = std::max(worst, std::abs(sum - 1.0));
  }
  return worst;
}

// An empty closed box 1 x 1 x 1.6 m: the walls' patches are not the floor's size. Nothing hides
// anything, so the analytic rows, one contour integral each way, are reciprocal but for the
// hemicube's pixel count of what is visible; the hemicube's own point-to-area rows are not.
TEST(AnalyticMatrix, ReciprocalInAnEmptyBoxOfUnequalPatches) {
  Scene scene;
  const int grey = test::add_material(scene, 0.5f);
  using v = glm::vec3;
  const float d = 1.6f;
  test::add_quad(scene, v(0, 0, 0), v(0, 0, d), v(1, 0, d), v(1, 0, 0), grey, "floor");
  test::add_quad(scene, v(0, 1, 0), v(1, 1, 0), v(1, 1, d), v(0, 1, d), grey, "ceiling");
  test::add_quad(scene, v(0, 0, 0), v(0, 1, 0), v(0, 1, d), v(0, 0, d), grey, "x0");
  test::add_quad(scene, v(1, 0, 0), v(1, 0, d), v(1, 1, d), v(1, 1, 0), grey, "x1");
  test::add_quad(scene, v(0, 0, 0), v(1, 0, 0), v(1, 1, 0), v(0, 1, 0), grey, "z0");
  test::add_quad(scene, v(0, 0, d), v(0, 1, d), v(1, 1, d), v(1, 0, d), grey, "z1");
  const PatchMesh mesh = PatchMesh::build(scene, 0.3f);
  const PatchItems items(mesh);
  Hemicube hemicube(mesh, items, 128);
  const FormFactorMatrix analytic = FormFactorMatrix::build_analytic(mesh, hemicube);
  const FormFactorMatrix by_hemicube = FormFactorMatrix::build(mesh, hemicube);
  float smallest = 1e9f, largest = 0.0f;
  for (const Patch& p : mesh.patches) {
    smallest = std::min(smallest, p.area);
    largest = std::max(largest, p.area);
  }
  const double analytic_gap = reciprocity_gap(mesh, analytic, scene.meshes.size());
  const double hemicube_gap = reciprocity_gap(mesh, by_hemicube, scene.meshes.size());
  printf("%zu patches of %.4f .. %.4f m^2: reciprocity off by %.4f analytic, %.4f hemicube; rows sum to 1 "
         "within %.4f\n", mesh.size(), smallest, largest, analytic_gap, hemicube_gap, worst_row_sum_error(analytic));
  ASSERT_GT(largest, 1.2f * smallest);
  EXPECT_LT(analytic_gap, 0.001);
  EXPECT_LT(3.0 * analytic_gap, hemicube_gap);
  EXPECT_LT(worst_row_sum_error(analytic), 0.01);
}

// A cube floating in a closed box: every hemicube pixel sees a front face, so what patch i sees
// of the others adds up to 1 in the analytic rows too, the hemicube's visibility taking off what
// the cube hides of each patch.
TEST(AnalyticMatrix, RowsSumToOneAroundABlock) {
  Scene scene;
  const int grey = test::add_material(scene, 0.5f);
  const int materials[6] = {grey, grey, grey, grey, grey, grey};
  test::add_closed_box(scene, materials);
  using v = glm::vec3;
  const float x0 = 0.3f, x1 = 0.6f, y0 = 0.3f, y1 = 0.6f, z0 = 0.35f, z1 = 0.65f;
  test::add_quad(scene, v(x0, y1, z0), v(x0, y1, z1), v(x1, y1, z1), v(x1, y1, z0), grey, "top");
  test::add_quad(scene, v(x0, y0, z0), v(x1, y0, z0), v(x1, y0, z1), v(x0, y0, z1), grey, "bottom");
  test::add_quad(scene, v(x0, y0, z0), v(x0, y0, z1), v(x0, y1, z1), v(x0, y1, z0), grey, "-x");
  test::add_quad(scene, v(x1, y0, z0), v(x1, y1, z0), v(x1, y1, z1), v(x1, y0, z1), grey, "+x");
  test::add_quad(scene, v(x0, y0, z0), v(x0, y1, z0), v(x1, y1, z0), v(x1, y0, z0), grey, "-z");
  test::add_quad(scene, v(x0, y0, z1), v(x1, y0, z1), v(x1, y1, z1), v(x0, y1, z1), grey, "+z");
  const PatchMesh mesh = PatchMesh::build(scene, 0.25f);
  const PatchItems items(mesh);
  Hemicube hemicube(mesh, items, 128);
  const double worst = worst_row_sum_error(FormFactorMatrix::build_analytic(mesh, hemicube));
  printf("%zu patches: the analytic rows sum to 1 within %.4f\n", mesh.size(), worst);
  EXPECT_LT(worst, 0.02);
}

}  // namespace
}  // namespace luz
