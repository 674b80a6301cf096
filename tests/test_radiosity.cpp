// Radiosity against closed forms and conservation laws (slides 29-40, SCENES.md units).
//
// - Hemicube form factors (Cohen & Greenberg 1985) against Howell's catalogue, J. R. Howell,
//   "A Catalog of Radiation Heat Transfer Configuration Factors": C-11 (identical, parallel,
//   directly opposed rectangles), C-14 (two rectangles with a common edge at 90 degrees) and
//   B-13 (plane element to a parallel coaxial disc, the element on the disc's axis). Area-to-
//   area factors are the area-weighted means of the rows of a finely meshed source,
//   F_AB = (1/A_A) sum_{i in A} A_i sum_{j in B} F_ij. Tolerance 0.5% at resolution 256 (its
//   reason at kHowell).
// - Row sums inside a closed box equal 1 within the hemicube's own discretisation error;
//   reciprocity A_A F_AB = A_B F_BA between unequal squares within 2%.
// - The furnace (a closed box, every patch emitting E with reflectance rho) converges to
//   E / (1 - rho); Cohen's ambient term makes the early picture close to it.
// - Energy: emitted = absorbed + unshot at every step in a closed box, with "absorbed" computed
//   here from the displayed radiosities: (1 - rho_j) / rho_j * (B_j - E_j) * A_j.
// - Point lights: the flux a floor square receives is I times the solid angle it subtends.
// - The Cornell box converges and bleeds colour; its ceiling is lit only indirectly.
//
// One OSMesa context for the whole binary (GlEnvironment).
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/scene.h"
#include "io/gltf_loader.h"
#include "radiosity/hemicube.h"
#include "radiosity/mesh_bisection.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/radiosity_renderer.h"
#include "radiosity/shooting.h"
#include "radiosity/vertex_colours.h"
#include "radiosity_scenes.h"
#include "support.h"

namespace luz {
namespace {

using test::add_quad;
using test::add_material;
using test::add_closed_box;
using test::howell_c11;
using test::howell_c14;
using test::howell_b13;
constexpr double pi = std::numbers::pi;

// F from the patches of source mesh `a` to those of mesh `b`, area-weighted over a.
double area_form_factor(const PatchMesh& mesh, Hemicube& hemicube, int a, int b,
                        double expected = 0.0) {
  double weighted = 0.0, area = 0.0;
  for (size_t i = 0; i < mesh.size(); ++i) {
    if (mesh.patches[i].mesh != a) continue;
    double to_b = 0.0;
    for (const FormFactor& f : hemicube.row(i))
      if (mesh.patches[f.patch].mesh == b) to_b += f.value;
    weighted += double(mesh.patches[i].area) * to_b;
    area += double(mesh.patches[i].area);
  }
  if (expected > 0.0)
    printf("F_AB = %.5f, closed form %.5f (%+.2f%%)\n", weighted / area, expected,
           100.0 * (weighted / area - expected) / expected);
  return weighted / area;
}

struct Fixture {
  PatchMesh mesh;
  std::unique_ptr<PatchItems> items;
  std::unique_ptr<Hemicube> hemicube;
  Fixture(const Scene& scene, float patch_size, int res) {
    mesh = PatchMesh::build(scene, patch_size);
    items = std::make_unique<PatchItems>(mesh);
    hemicube = std::make_unique<Hemicube>(mesh, *items, res);
  }
};

// ---- Howell's closed forms --------------------------------------------------------------------

// How far the hemicube's area factors may be from Howell's, relative. Two biases, worked out for
// C-11, the largest (they are smaller for C-14 and B-13): the hemicube's eye sits 0.1 of the
// patch's clearance above the patch (hemicube.cpp), which brings the opposite square nearer,
// +0.26% for patches of 1/12 of a side; and the area mean over the source's patch centres is the
// midpoint rule, O(h^2), +0.07% (both from the point-to-rectangle closed form, integrated over
// the mesh's centroids). Counting whole pixels adds a zero-mean noise: the outline of the
// receiver cuts about 500 of the 256-resolution pixels (dF ~ 1.2e-5 each), 0.04% of F a row
// (less on the mean of 288 rows). 0.33% of bias plus four times that noise: 0.5%.
constexpr double kHowell = 0.005;

TEST(HemicubeFormulas, ClosedFormsReproduceTheCatalogueValues) {
  // Values printed in the catalogue and in Cohen & Wallace's book, to 4 digits.
  EXPECT_NEAR(howell_c11(1, 1, 1), 0.1998, 1e-4);
  EXPECT_NEAR(howell_c14(1, 1, 1), 0.2000, 1e-4);
  EXPECT_NEAR(howell_b13(1, 1), 0.5, 1e-12);
}

TEST(Hemicube, DeltaFormFactorsAreTheExactOnesAndSumToOneUpToDiscretisation) {
  Scene scene;
  add_quad(scene, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, add_material(scene, 0.5f), "q");
  for (const int res : {64, 256}) {
    Fixture f(scene, 10.0f, res);
    const std::vector<float>& w = f.hemicube->delta_form_factors();
    double total = 0.0;
    for (const float x : w) total += x;
    // The midpoint rule on a smooth integrand: the error shrinks as 1/res^2.
    EXPECT_NEAR(total, 1.0, 2.0 / (res * res)) << res;
    // A pixel at the centre of the top face: dF = dA / pi (x = y = 1/res there).
    const Hemicube::Rect top = f.hemicube->face_rect(0);
    const double d = 1.0 / res, dA = 4.0 / (res * res);
    EXPECT_NEAR(w[size_t(top.height / 2) * size_t(f.hemicube->atlas_width()) + size_t(top.width / 2)],
                dA / (pi * (1 + 2 * d * d) * (1 + 2 * d * d)), 1e-6 * dA / pi);  // float table
  }
}

TEST(Hemicube, ParallelCoaxialSquaresMatchHowellC11) {
  Scene scene;
  const int grey = add_material(scene, 0.5f);
  const int a = add_quad(scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, grey, "bottom");
  const int b = add_quad(scene, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}, grey, "top");
  Fixture f(scene, 1.0f / 8.0f, 256);
  const double expected = howell_c11(1, 1, 1);
  EXPECT_NEAR(area_form_factor(f.mesh, *f.hemicube, a, b, expected), expected, kHowell * expected);
  EXPECT_NEAR(area_form_factor(f.mesh, *f.hemicube, b, a, expected), expected, kHowell * expected);
}

TEST(Hemicube, PerpendicularSquaresSharingAnEdgeMatchHowellC14) {
  Scene scene;
  const int grey = add_material(scene, 0.5f);
  // Floor y = 0 (facing +y) and wall x = 0 (facing +x), sharing the edge x = y = 0.
  const int floor = add_quad(scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, grey, "floor");
  const int wall = add_quad(scene, {0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}, grey, "wall");
  Fixture f(scene, 1.0f / 10.0f, 256);
  const double expected = howell_c14(1, 1, 1);
  EXPECT_NEAR(area_form_factor(f.mesh, *f.hemicube, floor, wall, expected), expected, kHowell * expected);
  EXPECT_NEAR(area_form_factor(f.mesh, *f.hemicube, wall, floor, expected), expected, kHowell * expected);
}

TEST(Hemicube, SmallPatchUnderADiscMatchesHowellB13) {
  Scene scene;
  const int grey = add_material(scene, 0.5f);
  const float s = 0.005f;  // a 1 cm square: the hemicube's point is its centre
  const int patch = add_quad(scene, {-s, 0, -s}, {-s, 0, s}, {s, 0, s}, {s, 0, -s}, grey, "patch");
  for (const float h : {0.5f, 1.0f, 2.0f}) {
    Scene with_disc = scene;
    Mesh disc;  // a fan of 256 triangles, radius 1 at height h, facing down
    disc.name = "disc";
    disc.material = grey;
    const int segments = 256;
    disc.positions.push_back({0, h, 0});
    for (int k = 0; k < segments; ++k) {
      const float angle = 2.0f * std::numbers::pi_v<float> * float(k) / float(segments);
      disc.positions.push_back({std::cos(angle), h, std::sin(angle)});
    }
    for (int k = 0; k < segments; ++k)
      disc.indices.insert(disc.indices.end(), {0u, uint32_t(1 + k), uint32_t(1 + (k + 1) % segments)});
    disc.normals.assign(disc.positions.size(), {0, -1, 0});
    with_disc.meshes.push_back(disc);
    Fixture f(with_disc, 10.0f, 256);
    const double expected = howell_b13(1.0, h);
    EXPECT_NEAR(area_form_factor(f.mesh, *f.hemicube, patch, 1, expected), expected, kHowell * expected) << h;
  }
}

TEST(Hemicube, RowsInAClosedBoxSumToOne) {
  Scene scene;
  const int grey = add_material(scene, 0.5f);
  const int materials[6] = {grey, grey, grey, grey, grey, grey};
  add_closed_box(scene, materials);
  Fixture f(scene, 0.25f, 128);
  double table = 0.0;
  for (const float w : f.hemicube->delta_form_factors()) table += w;
  for (size_t i = 0; i < f.mesh.size(); ++i) {
    double sum = 0.0;
    for (const FormFactor& ff : f.hemicube->row(i, 0.3f * float(i))) sum += ff.value;
    // Every pixel sees the box, so a row sums to the table's total (1 up to 1/res^2 terms).
    EXPECT_NEAR(sum, table, 1e-4) << "patch " << i;
    EXPECT_NEAR(sum, 1.0, 1e-3) << "patch " << i;
  }
}

// A patch sees nothing of the plane it lies in (F = 0 between coplanar patches): on a lone floor
// cut into patches every row is empty, the neighbours along its edges included.
TEST(Hemicube, APatchSeesNothingOfItsOwnPlane) {
  Scene scene;
  const int grey = add_material(scene, 0.5f);
  add_quad(scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, grey, "floor");
  Fixture f(scene, 0.25f, 128);
  ASSERT_GT(f.mesh.size(), 8u);
  for (size_t i = 0; i < f.mesh.size(); ++i)
    EXPECT_TRUE(f.hemicube->row(i, 0.3f * float(i)).empty()) << "patch " << i;
}

TEST(Hemicube, ReciprocityBetweenUnequalSquares) {
  Scene scene;
  const int grey = add_material(scene, 0.5f);
  const int small = add_quad(scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, grey, "small");
  const int large = add_quad(scene, {-0.5f, 1.5f, -0.5f}, {1.5f, 1.5f, -0.5f}, {1.5f, 1.5f, 1.5f},
                             {-0.5f, 1.5f, 1.5f}, grey, "large");
  Fixture f(scene, 1.0f / 8.0f, 256);
  const double forward = 1.0 * area_form_factor(f.mesh, *f.hemicube, small, large);
  const double backward = 4.0 * area_form_factor(f.mesh, *f.hemicube, large, small);
  EXPECT_GT(forward, 0.3);
  EXPECT_NEAR(forward, backward, 0.02 * forward);
}

// The hemicube drawn in one instanced pass, and summed on the GPU, against the five passes summed
// on the CPU, on the Cornell box for patches on every wall and the blocks, turned at random. One
// pass draws the same pixels up to float rounding, which may hand a pixel on the edge between two
// patches to the other one: per row the rows differ by at most two pixels' worth (the largest
// delta form factor, at the top face's centre, each way). The GPU adds the same pixels' deltas in
// float instead of double.
TEST(Hemicube, OnePassAndGpuSumsGiveTheFivePassRows) {
  const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "cornell_box.gltf");
  const PatchMesh mesh = PatchMesh::build(loaded.scene, 0.1f);
  const PatchItems items(mesh);
  const int res = 128;
  Hemicube five(mesh, items, res, HemicubePasses::five, HemicubeSums::cpu);
  Hemicube one(mesh, items, res, HemicubePasses::one, HemicubeSums::cpu);
  Hemicube gpu(mesh, items, res, HemicubePasses::one, HemicubeSums::gpu);
  const double pixel = top_delta_form_factor(0.0, 0.0, 4.0 / (res * res));
  const auto as_map = [](const std::vector<FormFactor>& row) {
    std::map<uint32_t, double> m;
    for (const FormFactor& f : row) m[f.patch] = f.value;
    return m;
  };
  const auto l1_difference = [](const std::map<uint32_t, double>& a, std::map<uint32_t, double> b) {
    double sum = 0.0;
    for (const auto& [j, value] : a) sum += std::abs(value - b[j]);
    for (const auto& [j, value] : b)
      if (!a.count(j)) sum += value;
    return sum;
  };
  double worst_pixels = 0.0, worst_gpu = 0.0;
  size_t rows = 0;
  for (size_t i = 0; i < mesh.size(); i += 7, ++rows) {
    const float rotation = 0.37f * float(i);
    const std::map<uint32_t, double> by_five = as_map(five.row(i, rotation));
    const std::map<uint32_t, double> by_one = as_map(one.row(i, rotation));
    const std::map<uint32_t, double> by_gpu = as_map(gpu.row(i, rotation));
    worst_pixels = std::max(worst_pixels, l1_difference(by_five, by_one) / pixel);
    ASSERT_EQ(by_gpu.size(), by_one.size()) << "patch " << i;
    for (const auto& [j, value] : by_one) {
      ASSERT_TRUE(by_gpu.count(j)) << "patch " << i << " misses " << j;
      worst_gpu = std::max(worst_gpu, std::abs(by_gpu.at(j) - value) / value);
    }
  }
  printf("%zu rows: one pass moves at most %.2f pixels' worth of a row; GPU sums within %.1e\n", rows,
         worst_pixels, worst_gpu);
  EXPECT_LE(worst_pixels, 2.0);
  EXPECT_LT(worst_gpu, 1e-5);
}

// ---- The solver --------------------------------------------------------------------------------
TEST(Shooting, FurnaceConvergesToEOverOneMinusRho) {
  Scene scene;
  const float rho = 0.5f, E = 1.0f;
  const int glowing = add_material(scene, rho, E / std::numbers::pi_v<float>);  // E = pi Le
  const int materials[6] = {glowing, glowing, glowing, glowing, glowing, glowing};
  add_closed_box(scene, materials);
  PatchMesh mesh = PatchMesh::build(scene, 0.25f);
  RadiosityOptions options;
  options.form_factors = FormFactorMethod::hemicube;  // the analytic ones: test_radiosity_form_factors
  options.hemicube_res = 128;
  options.converge = 1e-3f;

  // Early on (one shot per patch), Cohen's ambient term stands in for the light not yet shot:
  // the unshot power U would add rho U + rho^2 U + ... = rho U / (1 - rho) when shot, which is
  // what rho * ambient spreads over the area.
  options.max_shots = int(mesh.size());
  ProgressiveSolver early(scene, mesh, options);
  while (early.step()) {}
  const std::vector<Rgb> b_early = early.displayed();
  const Rgb ambient = early.ambient();
  double mean_without = 0.0, mean_with = 0.0;
  for (size_t i = 0; i < mesh.size(); ++i) {
    mean_without += double(b_early[i].g) * double(mesh.patches[i].area) / 6.0;
    mean_with += double(b_early[i].g + rho * ambient.g) * double(mesh.patches[i].area) / 6.0;
  }
  EXPECT_LT(mean_without, 0.95 * 2.0);
  EXPECT_NEAR(mean_with, 2.0, 0.005 * 2.0);

  options.max_shots = 0;
  options.random_rotation = false;  // every shot of a patch uses the same row: see the bound below
  ProgressiveSolver solver(scene, mesh, options);
  while (solver.step()) {}
  ASSERT_LT(solver.unshot_fraction(), 1e-3);
  double weighted = 0.0, worst = 0.0, worst_inner = 0.0;
  const std::vector<Rgb> B = solver.displayed();
  for (size_t i = 0; i < mesh.size(); ++i) {
    const Patch& p = mesh.patches[i];
    weighted += double(B[i].g) * double(p.area);
    const double off = std::abs(double(B[i].g) - 2.0);
    worst = std::max(worst, off);
    // Distance from the centre to the nearest edge of the box (the face's own two axes).
    double to_edge = 1.0;
    for (int axis = 0; axis < 3; ++axis)
      if (std::abs(p.normal[axis]) < 0.5f)
        to_edge = std::min({to_edge, double(p.centre[axis]), 1.0 - double(p.centre[axis])});
    if (to_edge > 0.2) worst_inner = std::max(worst_inner, off);
  }
  printf("furnace: %zu patches, %d shots, area-weighted mean %.5f, worst patch off by %.4f, "
         "worst away from the edges %.4f\n", mesh.size(), solver.shots(), weighted / 6.0, worst,
         worst_inner);
  // Energy fixes the area-weighted mean exactly: sum B_j A_j = E A / (1 - rho).
  EXPECT_NEAR(weighted / 6.0, E / (1 - rho), 0.002 * E / (1 - rho));
  // Patch by patch, the bound of the system the shooting solves: B_j = E + rho sum_i K_ji B_i
  // with K_ji = F_ij A_i / A_j (row i of the hemicube, by reciprocity). Exact form factors give
  // column sums c_j = sum_i K_ji = sum_i F_ji = 1 in a closed box; the hemicube's are off, as it
  // samples from the patch centre, which assumes the other patch is far compared with the
  // patch's size: worst for neighbours across the box's edges (the proximity error Baum,
  // Rushmeier and Winget, SIGGRAPH 1989, analyse). B* = E / (1 - rho) leaves the residual
  // rho (c_j - 1) B*, so e = B - B* obeys e = rho K e + rho (c - 1) B* and, K being >= 0,
  //   |e|_inf <= rho max_j |c_j - 1| B* / (1 - rho c_max),   |e_j| <= rho |c_j - 1| B* + rho c_j |e|_inf.
  // Stopping with unshot exitance U left shows B - rho K (I - rho K)^-1 U: at most
  // rho c_max |U|_inf / (1 - rho c_max) more off.
  Fixture f(scene, 0.25f, options.hemicube_res);
  ASSERT_EQ(f.mesh.size(), mesh.size());
  std::vector<double> c(mesh.size(), 0.0);
  for (size_t i = 0; i < mesh.size(); ++i)
    for (const FormFactor& ff : f.hemicube->row(i))
      c[ff.patch] += double(ff.value) * double(mesh.patches[i].area / mesh.patches[ff.patch].area);
  double c_max = 0.0, deviation = 0.0, unshot = 0.0;
  for (size_t j = 0; j < mesh.size(); ++j) {
    c_max = std::max(c_max, c[j]);
    deviation = std::max(deviation, std::abs(c[j] - 1.0));
    unshot = std::max(unshot, double(solver.unshot()[j].g));
  }
  const double exact = E / (1 - rho);
  const double e_inf = rho * deviation * exact / (1 - rho * c_max);
  const double stopped = rho * c_max * unshot / (1 - rho * c_max);
  printf("furnace bound: column sums within %.4f of 1, |e|_inf <= %.4f, stopping adds <= %.5f\n",
         deviation, e_inf / exact, stopped / exact);
  for (size_t j = 0; j < mesh.size(); ++j)
    EXPECT_LE(std::abs(double(B[j].g) - exact),
              rho * std::abs(c[j] - 1.0) * exact + rho * c[j] * e_inf + stopped + 1e-5 * exact)
        << "patch " << j << " at " << mesh.patches[j].centre.x << "," << mesh.patches[j].centre.y
        << "," << mesh.patches[j].centre.z;
}

TEST(Shooting, EmittedEqualsAbsorbedPlusUnshotAtEveryStep) {
  Scene scene;
  const int lamp = add_material(scene, 0.3f, 2.0f);
  const int materials[6] = {add_material(scene, 0.7f), lamp, add_material(scene, 0.5f),
                            add_material(scene, 0.2f), add_material(scene, 0.8f),
                            add_material(scene, 0.6f)};
  add_closed_box(scene, materials);
  PatchMesh mesh = PatchMesh::build(scene, 0.25f);
  RadiosityOptions options;
  options.form_factors = FormFactorMethod::hemicube;  // its rows sum to 1 within 1e-3 here
  options.hemicube_res = 64;
  options.max_shots = 150;
  options.meshing = Meshing::uniform;  // adaptive subdivision's balance: test_radiosity_adaptive
  ProgressiveSolver solver(scene, mesh, options);
  const double emitted = solver.emitted_power();
  EXPECT_NEAR(emitted, 2.0 * pi * 1.0, 1e-4);  // E A = pi Le * 1 m^2
  while (solver.step()) {
    const std::vector<Rgb> b = solver.displayed();
    double absorbed = 0.0;
    for (size_t j = 0; j < mesh.size(); ++j) {
      const Patch& p = mesh.patches[j];
      const double rho = p.rho.g;
      absorbed += (1.0 - rho) / rho * double(b[j].g - p.emission.g) * double(p.area);
    }
    EXPECT_NEAR(emitted, absorbed + solver.unshot_power(), 1e-3 * emitted) << "shot " << solver.shots();
    const EnergyTally tally = solver.energy();
    EXPECT_NEAR(tally.absorbed, absorbed, 1e-4 * emitted);
    EXPECT_LT(std::abs(tally.escaped), 1e-3 * emitted);
  }
  EXPECT_EQ(solver.shots(), 150);
  // Every shot lowers the unshot power (each patch reflects less than it receives).
  for (size_t k = 1; k < solver.history().size(); ++k)
    EXPECT_LE(solver.history()[k].unshot_power, solver.history()[k - 1].unshot_power);
}

TEST(PointSource, SquareReceivesIntensityTimesItsSolidAngle) {
  for (const float side : {2.0f, 0.5f}) {
    Scene scene;
    const float rho = 0.5f, h = 1.0f, half = 0.5f * side;
    const int grey = add_material(scene, rho);
    add_quad(scene, {-half, 0, -half}, {-half, 0, half}, {half, 0, half}, {half, 0, -half}, grey,
             "floor");
    Light light;
    light.position = {0.0f, h, 0.0f};
    light.intensity = Rgb(3.0f);
    scene.lights.push_back(light);
    PatchMesh mesh = PatchMesh::build(scene, 0.1f);
    RadiosityOptions options;
    options.hemicube_res = 256;
    ProgressiveSolver solver(scene, mesh, options);
    ASSERT_TRUE(solver.step());  // the light shoots first
    EXPECT_EQ(solver.last_shooter(), -1);
    EXPECT_NEAR(solver.emitted_power(), 3.0 * 4.0 * pi, 1e-3);
    // Solid angle of an a x b rectangle at distance h, seen from above its centre:
    // 4 asin(ab / sqrt((a^2 + 4h^2)(b^2 + 4h^2))).
    const double a = side, omega = 4.0 * std::asin(a * a / (a * a + 4.0 * h * h));
    // Flux received = sum of B_j / rho * A_j (B_j = rho * irradiance after the light's shot).
    double received = 0.0;
    const std::vector<Rgb> b = solver.displayed();
    for (size_t j = 0; j < mesh.size(); ++j)
      received += double(b[j].g) / rho * double(mesh.patches[j].area);
    EXPECT_NEAR(received, 3.0 * omega, 0.01 * 3.0 * omega) << side;
  }
}

TEST(PointSource, SpotSendsItsWholePowerIntoItsCone) {
  Scene scene;
  const int grey = add_material(scene, 0.5f);
  add_quad(scene, {-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, grey, "floor");
  Light spot;
  spot.type = LightType::spot;
  spot.position = {0.0f, 1.0f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.inner_cone = 0.3f;
  spot.outer_cone = 0.6f;  // the cone reaches tan(0.6) = 0.68 m: inside the floor
  spot.intensity = Rgb(5.0f);
  scene.lights.push_back(spot);
  PatchMesh mesh = PatchMesh::build(scene, 0.2f);
  RadiosityOptions options;
  options.hemicube_res = 256;
  ProgressiveSolver solver(scene, mesh, options);
  ASSERT_TRUE(solver.step());
  const EnergyTally tally = solver.energy();
  EXPECT_LT(solver.emitted_power(), 5.0 * 2.0 * pi * (1.0 - std::cos(0.6)));
  EXPECT_NEAR(tally.absorbed + tally.unshot, tally.emitted, 0.01 * tally.emitted);
}

// ---- Meshing and vertex colours ----------------------------------------------------------------
TEST(PatchMesh, ConformingSubdivisionWithoutTJunctions) {
  Scene scene;
  const int grey = add_material(scene, 0.5f);
  add_quad(scene, {0, 0, 0}, {0, 0, 1}, {1.3f, 0, 1}, {1.3f, 0, 0}, grey, "quad");
  PatchMesh mesh = PatchMesh::build(scene, 0.2f);
  const int n = mesh.subdivisions(0);
  ASSERT_EQ(mesh.size(), size_t(2 * n * n));
  EXPECT_NEAR(mesh.total_area(), 1.3f, 1e-5f);
  // Every edge is shared by two patches except the n segments of each of the quad's 4 sides.
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (const Patch& p : mesh.patches)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = p.vertices[k], b = p.vertices[(k + 1) % 3];
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  int boundary = 0;
  for (const auto& [edge, count] : edges) {
    EXPECT_LE(count, 2);
    boundary += count == 1;
  }
  EXPECT_EQ(boundary, 4 * n);
  EXPECT_EQ(mesh.vertices.size(), size_t((n + 1) * (n + 1)));  // the diagonal's points shared
}

TEST(PatchMesh, TargetCountAndLocate) {
  const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "cornell_box.gltf");
  for (const size_t target : {1000u, 4000u}) {
    PatchMesh mesh = PatchMesh::build(loaded.scene, PatchMesh::patch_size_for(loaded.scene, target));
    EXPECT_GT(mesh.size(), target * 7 / 10);
    EXPECT_LT(mesh.size(), target * 13 / 10);
    // locate() finds the patch whose corners interpolate back to the point.
    const Mesh& floor = loaded.scene.meshes[0];
    const glm::vec2 b(0.3f, 0.45f);
    const glm::vec3 A = floor.positions[floor.indices[0]], B = floor.positions[floor.indices[1]],
                    C = floor.positions[floor.indices[2]];
    const glm::vec3 point = A + b.x * (B - A) + b.y * (C - A);
    const PatchMesh::Location where = mesh.locate(0, 0, b);
    const Patch& p = mesh.patches[where.patch];
    const glm::vec3 back = where.weights.x * mesh.vertices[p.vertices[0]] +
                           where.weights.y * mesh.vertices[p.vertices[1]] +
                           where.weights.z * mesh.vertices[p.vertices[2]];
    EXPECT_LT(glm::length(back - point), 1e-5f);
    EXPECT_NEAR(where.weights.x + where.weights.y + where.weights.z, 1.0f, 1e-5f);
  }
}

TEST(VertexColours, NodalAveragingAcrossSmoothSurfacesNotAcrossCreases) {
  Scene scene;
  const int grey = add_material(scene, 0.5f);
  add_quad(scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, grey, "smooth");
  // A second quad meeting the first along x = 1 (a crease: its own vertices).
  add_quad(scene, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}, grey, "wall");
  PatchMesh mesh = PatchMesh::build(scene, 10.0f);  // one patch per triangle
  ASSERT_EQ(mesh.size(), 4u);
  const float pi_f = std::numbers::pi_v<float>;
  const std::vector<Rgb> B = {Rgb(pi_f), Rgb(3 * pi_f), Rgb(10 * pi_f), Rgb(10 * pi_f)};
  const RadianceField field = RadianceField::from(mesh, B);
  EXPECT_NEAR(field.patch[0].g, 1.0f, 1e-6f);  // B / pi
  // Vertex 0 and 2 of the quad are shared by both triangles (equal areas): the mean, 2.
  EXPECT_NEAR(field.corner[0].g, 2.0f, 1e-5f);
  EXPECT_NEAR(field.corner[1].g, 1.0f, 1e-5f);  // only triangle 0
  // The crease at x = 1: the floor's corner (1, 0, 1) keeps the floor's mean (2), the wall's
  // corner at the same place keeps the wall's value (10).
  int found = 0;
  for (size_t e = 0; e < mesh.size(); ++e)
    for (size_t k = 0; k < 3; ++k)
      if (glm::length(mesh.vertices[mesh.patches[e].vertices[k]] - glm::vec3(1, 0, 1)) < 1e-6f) {
        EXPECT_NEAR(field.corner[3 * e + k].g, mesh.patches[e].mesh == 0 ? 2.0f : 10.0f, 1e-5f);
        ++found;
      }
  EXPECT_EQ(found, 3);  // two floor triangles and one wall triangle
  // The CPU query interpolates the same vertex values the picture shows.
  EXPECT_NEAR(field.at(mesh, 0, 0, {0.0f, 0.0f}).g, 2.0f, 1e-5f);
  EXPECT_NEAR(field.at(mesh, 0, 0, {1.0f, 0.0f}).g, 1.0f, 1e-5f);
  EXPECT_NEAR(field.at(mesh, 0, 0, {0.5f, 0.0f}).g, 1.5f, 1e-5f);
}

// The display's surfaces are the geometry's, not the file's vertex sharing (SCENES.md): one mesh
// of a floor and a wall that share the vertices of their common edge (a box exported smooth)
// keeps each side's value at the crease, and a floor whose two triangles have their own vertices
// (a triangle soup) shows one value at each of the corners they have in common.
TEST(VertexColours, ACreaseKeepsItsTwoSidesAndASoupHasNoSeams) {
  const float pi_f = std::numbers::pi_v<float>;
  {
    Scene scene;
    Mesh mesh;
    mesh.name = "smooth box edge";
    mesh.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, {1, 1, 1}, {1, 1, 0}};
    mesh.normals.assign(6, glm::normalize(glm::vec3(1, 1, 0)));  // averaged, as Blender writes them
    mesh.indices = {0, 1, 2, 0, 2, 3, 3, 2, 4, 3, 4, 5};            // the edge (1, 0, z) shared
    mesh.material = add_material(scene, 0.5f);
    scene.meshes.push_back(mesh);
    const PatchMesh patches = PatchMesh::build(scene, 10.0f);
    ASSERT_EQ(patches.size(), 4u);
    const RadianceField field =
        RadianceField::from(patches, {Rgb(2 * pi_f), Rgb(2 * pi_f), Rgb(10 * pi_f), Rgb(10 * pi_f)});
    for (size_t e = 0; e < patches.size(); ++e)
      for (size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(field.corner[3 * e + k].g, e < 2 ? 2.0f : 10.0f, 1e-5f) << "element " << e << " corner " << k;
  }
  {
    Scene scene;
    Mesh mesh;
    mesh.name = "soup";
    mesh.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {0, 0, 0}, {1, 0, 1}, {1, 0, 0}};
    mesh.indices = {0, 1, 2, 3, 4, 5};
    mesh.material = add_material(scene, 0.5f);
    scene.meshes.push_back(mesh);
    const PatchMesh patches = PatchMesh::build(scene, 10.0f);
    ASSERT_EQ(patches.size(), 2u);
    const RadianceField field = RadianceField::from(patches, {Rgb(pi_f), Rgb(3 * pi_f)});
    // (0, 0, 0) and (1, 0, 1) belong to both triangles: the mean, 2; the others to one.
    for (size_t e = 0; e < 2; ++e)
      for (size_t k = 0; k < 3; ++k) {
        const glm::vec3 q = patches.vertices[patches.patches[e].vertices[k]];
        const bool shared = q.x == q.z;
        EXPECT_NEAR(field.corner[3 * e + k].g, shared ? 2.0f : e == 0 ? 1.0f : 3.0f, 1e-5f) << e << " " << k;
      }
  }
}

// A radiosity that varies linearly across a surface is shown exactly at every vertex, whatever the
// triangulation: the elements of a floor, cut unevenly as adaptive subdivision cuts them (its top
// row twice, a few elements inside), carry B = pi f(centroid) for a linear f, and every corner
// shows f there, on the floor's edges and corners as inside. A mean of the elements around a
// vertex shows f at their centroid instead, off by f's change over a third of an element on the
// edges, by an amount that alternates along the cut row. A wall meeting the floor at a crease,
// with a linear f of its own, keeps its own values along the crease.
TEST(VertexColours, ALinearRadiosityIsShownExactlyOnAnyMesh) {
  Scene scene;
  const int grey = add_material(scene, 0.5f);
  add_quad(scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, grey, "floor");
  add_quad(scene, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}, grey, "wall");
  PatchMesh mesh = PatchMesh::build(scene, 0.25f);
  {
    MeshBisection bisection(mesh);
    std::vector<uint32_t> changed;
    for (int pass = 0; pass < 2; ++pass)
      for (uint32_t e = 0, n = uint32_t(mesh.size()); e < n; ++e)
        if (mesh.patches[e].mesh == 0 && mesh.patches[e].centre.z > 0.8f) bisection.split(e, changed);
    for (const uint32_t e : {5u, 11u, 20u}) bisection.split(e, changed);
    mesh.group_by_shooter();
    mesh.find_display_surfaces();
  }
  const auto f = [](int surface, const glm::vec3& q) {
    return surface == 0 ? 3.5f + 2.0f * q.x - 3.0f * q.z : 0.5f + 4.0f * q.y + q.z;
  };
  std::vector<Rgb> B(mesh.size());
  for (size_t e = 0; e < mesh.size(); ++e)
    B[e] = Rgb(std::numbers::pi_v<float> * f(mesh.patches[e].mesh, mesh.patches[e].centre));
  const RadianceField field = RadianceField::from(mesh, B);
  size_t on_the_crease = 0;
  for (size_t c = 0; c < field.corner.size(); ++c) {
    const Patch& p = mesh.patches[c / 3];
    const glm::vec3 q = mesh.vertices[p.vertices[c % 3]];
    EXPECT_NEAR(field.corner[c].g, f(p.mesh, q), 1e-4f) << "mesh " << p.mesh << " at " << q.x << ", " << q.y << ", " << q.z;
    if (q.x == 1.0f && q.y == 0.0f) ++on_the_crease;
  }
  EXPECT_GT(on_the_crease, 8u);
  EXPECT_GT(mesh.size(), 64u) << "the cuts were made";
}

// Two materials side by side in one plane are two surfaces: a change of material stays sharp.
TEST(VertexColours, AChangeOfMaterialIsAnEdge) {
  Scene scene;
  add_quad(scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, add_material(scene, 0.5f), "white");
  add_quad(scene, {1, 0, 0}, {1, 0, 1}, {2, 0, 1}, {2, 0, 0}, add_material(scene, 0.1f), "dark");
  const PatchMesh mesh = PatchMesh::build(scene, 10.0f);
  const float pi_f = std::numbers::pi_v<float>;
  const RadianceField field = RadianceField::from(mesh, {Rgb(pi_f), Rgb(pi_f), Rgb(4 * pi_f), Rgb(4 * pi_f)});
  for (size_t e = 0; e < mesh.size(); ++e)
    for (size_t k = 0; k < 3; ++k)
      EXPECT_NEAR(field.corner[3 * e + k].g, mesh.patches[e].mesh == 0 ? 1.0f : 4.0f, 1e-5f);
}


TEST(VertexColours, UnshotHeatMapShowsTheEmittersFirst) {
  Scene scene;
  const int grey = add_material(scene, 0.5f), lamp = add_material(scene, 0.5f, 1.0f);
  const int materials[6] = {grey, lamp, grey, grey, grey, grey};
  add_closed_box(scene, materials);
  PatchMesh mesh = PatchMesh::build(scene, 0.5f);
  RadiosityOptions options;
  options.hemicube_res = 64;
  ProgressiveSolver solver(scene, mesh, options);
  const RadianceField before = RadianceField::unshot_heat_map(solver);
  for (size_t i = 0; i < mesh.size(); ++i) {
    const bool emitter = mesh.patches[i].mesh == 1;
    EXPECT_NEAR(before.patch[i].g, emitter ? 1.0f : 0.0f, 1e-5f) << i;  // yellow or black
  }
  ASSERT_TRUE(solver.step());
  const RadianceField after = RadianceField::unshot_heat_map(solver);
  EXPECT_EQ(after.patch[size_t(solver.last_shooter())], Rgb(0.0f)) << "the shooter has nothing left";
}

// ---- The Cornell box ---------------------------------------------------------------------------
TEST(CornellBox, ConvergesBleedsColourAndLightsTheCeilingIndirectly) {
  const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "cornell_box.gltf");
  const Scene& scene = loaded.scene;
  PatchMesh mesh = PatchMesh::build(scene, 0.1f);
  RadiosityOptions options;
  options.hemicube_res = 128;
  options.converge = 0.03f;
  ProgressiveSolver solver(scene, mesh, options);
  const auto mesh_named = [&scene](const std::string& name) {
    for (size_t m = 0; m < scene.meshes.size(); ++m)
      if (scene.meshes[m].name == name) return int(m);
    return -1;
  };
  const int ceiling = mesh_named("ceiling"), light = mesh_named("light");
  ASSERT_GE(ceiling, 0);
  ASSERT_GE(light, 0);

  // The lamp faces down from just under the ceiling: its own shots never reach the ceiling.
  for (size_t i = 0; i < mesh.size(); ++i)
    if (mesh.patches[i].mesh == light) solver.shoot(i);
  for (size_t i = 0; i < mesh.size(); ++i)
    if (mesh.patches[i].mesh == ceiling) {
      ASSERT_EQ(solver.displayed()[i].r, 0.0f);
    }

  while (solver.step()) {}
  EXPECT_LT(solver.unshot_fraction(), 0.03);
  const std::vector<Rgb> B = solver.displayed();
  Rgb ceiling_sum(0.0f), red_facing(0.0f), green_facing(0.0f), up_facing(0.0f);
  for (size_t i = 0; i < mesh.size(); ++i) {
    const Patch& p = mesh.patches[i];
    const std::string& name = scene.meshes[size_t(p.mesh)].name;
    if (p.mesh == ceiling) ceiling_sum += B[i] * p.area;
    if (name != "short_block" && name != "tall_block") continue;
    // The red wall is at x ~ 0.55, the green one at x = 0.
    if (p.normal.x > 0.7f) red_facing += B[i] * p.area;
    if (p.normal.x < -0.7f) green_facing += B[i] * p.area;
    if (p.normal.y > 0.9f) up_facing += B[i] * p.area;
  }
  EXPECT_GT(ceiling_sum.r, 0.0f);
  const auto red_green = [](const Rgb& c) { return c.r / c.g; };
  // Under the lamp alone (17 : 12), faces are as red as the lamp is: the block tops.
  EXPECT_NEAR(red_green(up_facing), 17.0f / 12.0f, 0.15f);
  EXPECT_GT(red_green(red_facing), 1.3f * red_green(up_facing)) << "a red tint";
  EXPECT_LT(red_green(green_facing), red_green(up_facing) / 1.3f) << "a green tint";
}


// SCENES.md units: the local models light the floor under the lamp with the lamp as a point
// light at its centroid, radiance kd/pi * Le A cos cos / d^2; radiosity's direct light there,
// B/pi after the lamp's patches have shot, must be the same quantity but for the lamp being
// integrated over its area: 1.5% less than the centroid approximation (point-to-rectangle form
// factor 0.014257 against A / (pi h^2) = 0.014479).
TEST(CornellBox, DirectLightUnderTheLampAgreesWithTheLocalModel) {
  io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "cornell_box.gltf");
  // Without the blocks: the tall one stands 1 cm from the floor under the lamp and hides a third
  // of the lamp from it (radiosity sees that shadow: -31%; the local models have no shadows).
  std::erase_if(loaded.scene.meshes, [](const Mesh& m) { return m.name.ends_with("_block"); });
  loaded.scene.find_area_lights();
  const Scene& scene = loaded.scene;
  PatchMesh mesh = PatchMesh::build(scene, 0.03f);
  RadiosityOptions options;
  options.hemicube_res = 256;
  ProgressiveSolver solver(scene, mesh, options);
  int floor = -1, light = -1;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    if (scene.meshes[m].name == "floor") floor = int(m);
    if (scene.meshes[m].name == "light") light = int(m);
  }
  ASSERT_GE(floor, 0);
  ASSERT_GE(light, 0);
  for (size_t i = 0; i < mesh.size(); ++i)
    if (mesh.patches[i].mesh == light) solver.shoot(i);

  ASSERT_EQ(scene.area_lights.size(), 2u);  // the lamp's two triangles
  glm::vec3 lamp_centre(0.0f);
  float lamp_area = 0.0f;
  for (const AreaLight& a : scene.area_lights) {
    lamp_centre += a.area * a.centroid;
    lamp_area += a.area;
  }
  lamp_centre /= lamp_area;
  const glm::vec3 below(lamp_centre.x, 0.0f, lamp_centre.z);
  size_t nearest = 0;
  float best = 1e30f;
  for (size_t i = 0; i < mesh.size(); ++i)
    if (mesh.patches[i].mesh == floor && glm::length(mesh.patches[i].centre - below) < best) {
      best = glm::length(mesh.patches[i].centre - below);
      nearest = i;
    }
  const Patch& p = mesh.patches[nearest];
  const Material& lamp = scene.materials[size_t(scene.meshes[size_t(light)].material)];
  const Material& white = scene.materials[size_t(scene.meshes[size_t(floor)].material)];
  const glm::vec3 to_lamp = lamp_centre - p.centre;
  const float d = glm::length(to_lamp), cos_r = to_lamp.y / d;  // floor normal +y, lamp -y
  const Rgb local = white.kd / std::numbers::pi_v<float> * lamp.emission * lamp_area * cos_r *
                    cos_r / (d * d);
  const Rgb radiosity = solver.displayed()[nearest] / std::numbers::pi_v<float>;
  // The local model's point at the centroid stands for the lamp's form factor A cos^2 / (pi d^2);
  // radiosity integrates over the lamp. So radiosity must be the local value times the exact
  // point-to-parallel-rectangle factor over the centroid one (0.98474 here). What is left is the
  // hemicube counting whole pixels: the 3 cm floor patch is about 7 pixels across on each lamp
  // patch's hemicube (res 256, 0.55 m away), so its area is off by the ~1.5 pixels its outline
  // cuts of 49, 3% per row at random; the lamp's 72 patches, with randomly turned hemicubes,
  // average that to 0.35%. The bound is four of those standard deviations, 1.4%.
  double x0 = 1e30, x1 = -1e30, z0 = 1e30, z1 = -1e30;
  for (const glm::vec3& v : scene.meshes[size_t(light)].positions) {
    x0 = std::min(x0, double(v.x)), x1 = std::max(x1, double(v.x));
    z0 = std::min(z0, double(v.z)), z1 = std::max(z1, double(v.z));
  }
  const double h = lamp_centre.y - p.centre.y;
  // A plane element at height h below a corner of the parallel rectangle [0, x] x [0, y] (in
  // Howell's catalogue); odd in x and y, so four corners give any rectangle.
  const auto corner = [h](double x, double y) {
    const double X = x / h, Y = y / h;
    return (X / std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) +
            Y / std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y))) / (2 * pi);
  };
  const double px = p.centre.x, pz = p.centre.z;
  const double exact = corner(x1 - px, z1 - pz) - corner(x0 - px, z1 - pz) - corner(x1 - px, z0 - pz) +
                       corner(x0 - px, z0 - pz);
  const double centroid = double(lamp_area) * double(cos_r * cos_r) / (pi * double(d * d));
  const Rgb expected = local * float(exact / centroid);
  printf("floor under the lamp: local %.4f, radiosity %.4f (%+.2f%%); integrated over the lamp "
         "%.4f (radiosity %+.2f%%)\n", local.r, radiosity.r, 100.0 * (radiosity.r - local.r) / local.r,
         expected.r, 100.0 * (radiosity.r - expected.r) / expected.r);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(radiosity[c], expected[c], 0.014f * expected[c]) << c;
}


// No cracks: inside the Cornell box every pixel shows a patch, never the background, even
// along the joins of walls, floor and ceiling (separate primitives, subdivided differently);
// and the highlighted shooter shows in its colour.
TEST(RadiosityRenderer, NoCracksAlongTheJoinsAndTheShooterHighlighted) {
  io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "cornell_box.gltf");
  loaded.scene.background = Rgb(0.0f, 0.0f, 100.0f);  // unmistakable
  const Scene& scene = loaded.scene;
  for (const float size : {0.1f, 0.037f}) {
    PatchMesh mesh = PatchMesh::build(scene, size);
    RadiosityOptions options;
    options.hemicube_res = 64;
    options.max_shots = 5;
    options.pixel_samples = 1;  // a crack shows in one sample, not averaged away
    ProgressiveSolver solver(scene, mesh, options);
    while (solver.step()) {}
    RadiosityRenderer renderer(scene, mesh);
    renderer.update(RadianceField::of(solver), options);
    const Image image = renderer.render(scene.cameras.front(), 400, 400, options, solver.last_shooter());
    // The box fills the picture but for a thin frame (the floor's and ceiling's front edges
    // project to rows 390.6 and about 7 of 400, the side walls' about 4 pixels from the sides):
    // the open front shows the background only there.
    int background = 0, highlighted = 0, frame = 0;
    for (int x = 0; x < 400; ++x) frame += image.at(x, 399).b > 50.0f;
    EXPECT_GT(frame, 300) << "the background is visible below the floor";
    for (int y = 12; y < 388; ++y)
      for (int x = 12; x < 388; ++x) {
        background += image.at(x, y).b > 50.0f;
        highlighted += image.at(x, y).r == 4.0f && image.at(x, y).b == 4.0f;
      }
    EXPECT_EQ(background, 0) << "patch size " << size;
    EXPECT_GT(highlighted, 0) << "patch size " << size;
  }
}

// Radiosity leaves a patch on its front side only: seen from behind, the Cornell box's back
// wall is black (not its radiosity, not the background), where from inside it is lit.
// A lit face a metre in front of a dark one, seen from 1.5 km through a camera whose file asks
// for a near plane of 5 cm (an engine's fins before its body, as a CAD export frames it): with
// that near plane a 24-bit depth buffer tells depths apart only every few metres, and the dark
// face would show through the lit one in speckles. Every pixel of the lit face shows its value.
TEST(RadiosityRenderer, ADistantSceneKeepsItsDepthOrder) {
  Scene scene;
  const int lamp = add_material(scene, 0.0f, 1.0f), dark = add_material(scene, 0.5f);
  add_quad(scene, {-200, -200, 0}, {200, -200, 0}, {200, 200, 0}, {-200, 200, 0}, lamp, "lit face");
  add_quad(scene, {-300, -300, -1}, {300, -300, -1}, {300, 300, -1}, {-300, 300, -1}, dark, "body");
  PatchMesh mesh = PatchMesh::build(scene, 100.0f);
  std::vector<Rgb> exitance(mesh.size());
  for (size_t e = 0; e < mesh.size(); ++e) exitance[e] = mesh.patches[e].emission;
  RadiosityRenderer renderer(scene, mesh);
  RadiosityOptions options;
  options.pixel_samples = 1;
  renderer.update(RadianceField::from(mesh, exitance), options);
  Camera camera;
  camera.to_world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 1500.0f));
  camera.yfov = 0.2f;  // 300 m across at 1.5 km: the lit face fills the picture
  camera.znear = 0.05f;
  camera.zfar = 1e6f;
  const Image image = renderer.render(camera, 64, 64, options);
  int wrong = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) wrong += std::abs(image.at(x, y).g - 1.0f) > 1e-3f;
  EXPECT_EQ(wrong, 0) << "pixels of 64 x 64 showing the face behind";
  // The near plane moves out only as far as the scene allows: from inside the scene, znear.
  Bounds bounds;
  for (const glm::vec3& v : mesh.vertices) bounds.grow(v);
  EXPECT_GT(camera.near_plane(bounds, 1.0f), 1400.0f);
  camera.to_world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -0.5f));
  EXPECT_EQ(camera.near_plane(bounds, 1.0f), 0.05f);
  // Nor past what a wide view shows off its axis: a block 34 degrees aside, inside a view 115
  // degrees wide, is 1794 m away but its nearest face only 1490 m deep.
  Bounds aside;
  aside.grow({1000, -10, -10});
  aside.grow({1100, 10, 10});
  camera.to_world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 1500.0f));
  camera.yfov = 2.0f;
  EXPECT_LT(camera.near_plane(aside, 1.0f), 1490.0f);
  EXPECT_GT(camera.near_plane(aside, 1.0f), 100.0f);
}

TEST(RadiosityRenderer, APatchSeenFromBehindIsBlack) {
  io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "cornell_box.gltf");
  loaded.scene.background = Rgb(0.0f, 0.0f, 100.0f);  // unmistakable
  const Scene& scene = loaded.scene;
  PatchMesh mesh = PatchMesh::build(scene, 0.1f);
  RadiosityOptions options;
  options.hemicube_res = 64;
  options.max_shots = 5;
  ProgressiveSolver solver(scene, mesh, options);
  while (solver.step()) {}
  RadiosityRenderer renderer(scene, mesh);
  renderer.update(RadianceField::of(solver), options);
  // The scene's camera looks at the back wall from inside (+z); this one, with its field of view,
  // from behind the wall (-z).
  Camera behind = scene.cameras.front();
  behind.to_world = glm::translate(glm::mat4(1.0f), glm::vec3(0.278f, 0.273f, 1.4f));
  const Rgb inside = renderer.render(scene.cameras.front(), 64, 64, options).at(32, 32);
  const Rgb outside = renderer.render(behind, 64, 64, options).at(32, 32);
  EXPECT_GT(inside.g, 0.01f) << "the back wall is lit from inside";
  EXPECT_EQ(outside, Rgb(0.0f)) << "its back, seen from outside";
}

// Supersampling is a box filter: 16 pictures shifted on a 4 x 4 grid over the pixel average to
// what one picture at 4 x the size gives, each 4 x 4 block of its pixels averaged (their
// centres are the same points of the screen).
TEST(RadiosityRenderer, PixelSamplesAreABoxFilterOverThePixel) {
  const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "cornell_box.gltf");
  const Scene& scene = loaded.scene;
  PatchMesh mesh = PatchMesh::build(scene, 0.1f);
  RadiosityOptions options;
  options.max_shots = 20;
  ProgressiveSolver solver(scene, mesh, options);
  while (solver.step()) {}
  RadiosityRenderer renderer(scene, mesh);
  renderer.update(RadianceField::of(solver), options);
  const int size = 48;
  options.pixel_samples = 16;
  const Image supersampled = renderer.render(scene.cameras.front(), size, size, options);
  options.pixel_samples = 1;
  const Image large = renderer.render(scene.cameras.front(), 4 * size, 4 * size, options);
  const Image single = renderer.render(scene.cameras.front(), size, size, options);
  double off = 0.0, total = 0.0, edges = 0.0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      Rgb block(0.0f);
      for (int dy = 0; dy < 4; ++dy)
        for (int dx = 0; dx < 4; ++dx) block += large.at(4 * x + dx, 4 * y + dy) / 16.0f;
      for (int c = 0; c < 3; ++c) {
        off += std::abs(double(supersampled.at(x, y)[c]) - double(block[c]));
        edges += std::abs(double(single.at(x, y)[c]) - double(block[c]));
        total += double(block[c]);
      }
    }
  printf("16 samples against the 4x picture's blocks: %.2e of the light apart; 1 sample: %.2e\n",
         off / total, edges / total);
  EXPECT_LT(off / total, 1e-3);
  EXPECT_GT(edges / total, 10.0 * off / total) << "one sample a pixel is not the block mean at edges";
}

}  // namespace
}  // namespace luz
