// Ray-cast form factors (Wallace, Elmquist & Haines 1989) against closed forms, and against the
// hemicube, an independent way to the same visibility (GL rasterisation instead of Embree rays):
//
// - a point light inside a closed box: the elements' solid angles sum to 4 pi; with a square
//   plate beside the light, the plate takes its closed-form solid angle and the box the rest.
// - a patch of an empty closed box sends everything it shoots to the box: its row sums to 1.
// - with occluders (the Cornell box's blocks), the converged elements agree with the analytic
//   method, whose visibility is the hemicube's.
// - Whitted's scene: its point light delivers the same power through rays as through the cube
//   of item buffers.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "io/gltf_loader.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/ray_form_factors.h"
#include "radiosity/shooting.h"
#include "radiosity_scenes.h"
#include "support.h"

namespace luz {
namespace {

using test::add_closed_box;
using test::add_material;
using test::add_quad;

double mean(const Rgb& c) { return (double(c.r) + double(c.g) + double(c.b)) / 3.0; }

Scene grey_box() {
  Scene scene;
  const int grey = add_material(scene, 0.5f);
  const int materials[6] = {grey, grey, grey, grey, grey, grey};
  add_closed_box(scene, materials);
  return scene;
}

// The solid angle of a rectangle 2a x 2b seen from a point on its axis at distance d.
double rectangle_solid_angle(double a, double b, double d) {
  return 4.0 * std::asin(a * b / std::sqrt((a * a + d * d) * (b * b + d * d)));
}

TEST(RayFormFactors, APointLightInAClosedBoxReachesTheWholeSphere) {
  Scene scene = grey_box();
  const int plate_material = add_material(scene, 0.5f);
  // A plate 0.2 x 0.2 at height 0.7, facing down at a light 0.2 below it: it hides its solid
  // angle of the ceiling.
  const float a = 0.1f, d = 0.2f;
  const int plate = add_quad(scene, {0.5f - a, 0.7f, 0.5f - a}, {0.5f + a, 0.7f, 0.5f - a},
                             {0.5f + a, 0.7f, 0.5f + a}, {0.5f - a, 0.7f, 0.5f + a}, plate_material, "plate");
  Light light;
  light.position = {0.5f, 0.7f - d, 0.5f};
  PatchMesh mesh = PatchMesh::build(scene, 0.1f, 2);
  RayFormFactors rays(scene, mesh);
  const std::vector<FormFactor>& omegas = rays.solid_angles(light, 16, 1, 0);
  double box = 0.0, on_plate = 0.0;
  for (const FormFactor& f : omegas) (mesh.patches[f.patch].mesh == plate ? on_plate : box) += double(f.value);
  const double expected = rectangle_solid_angle(a, a, d);
  printf("plate %.6f sr (closed form %.6f), box %.6f sr (4 pi - plate %.6f), %llu rays\n", on_plate,
         expected, box, 4.0 * std::numbers::pi - expected, static_cast<unsigned long long>(rays.last_rays()));
  EXPECT_NEAR(on_plate, expected, 1e-4 * expected);  // nothing between: exact up to float
  // Elements across the shadow's edge are lit in part, by 16 rays each: a few tenths of a percent.
  EXPECT_NEAR(box, 4.0 * std::numbers::pi - expected, 0.003 * 4.0 * std::numbers::pi);
}

TEST(RayFormFactors, ARowOfAnEmptyClosedBoxSumsToOne) {
  const Scene scene = grey_box();
  PatchMesh mesh = PatchMesh::build(scene, 0.25f, 3);
  RayFormFactors rays(scene, mesh);
  double worst = 0.0;
  for (size_t i = 0; i < mesh.shooters.size(); i += 7) {  // corners, edges and middles
    double sum = 0.0;
    for (const FormFactor& f : rays.row(i, 4, 1, uint32_t(i))) sum += double(f.value);
    worst = std::max(worst, std::abs(sum - 1.0));
  }
  printf("worst row sum off 1 by %.4f%%\n", 100.0 * worst);
  // Every ray arrives: what is left is the contour integral's quadrature (0.1%).
  EXPECT_LT(worst, 0.003);
}

// Two ways to visibility, one answer: the converged patches of the Cornell box (its blocks
// cast the shadows) by rays and by the hemicube agree to a few percent on average, and in total
// light. Compared per shooting patch (its elements' area-weighted mean): an element's value
// carries the noise of both estimates at the shadows' edges (rays: 4 per element and shot; the
// hemicube: small, far elements aliased), which a patch averages over its 16 elements.
TEST(RayFormFactors, AgreeWithTheHemicubesVisibilityOnTheCornellBox) {
  const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "cornell_box.gltf");
  RadiosityOptions options;
  options.patch_size = 0.2f;
  options.converge = 0.005f;
  options.meshing = Meshing::uniform;  // both solve the one mesh
  PatchMesh mesh = PatchMesh::build(loaded.scene, options);
  options.form_factors = FormFactorMethod::rays;
  ProgressiveSolver by_rays(loaded.scene, mesh, options);
  options.form_factors = FormFactorMethod::analytic;
  ProgressiveSolver by_hemicube(loaded.scene, mesh, options);
  while (by_rays.step()) {}
  while (by_hemicube.step()) {}
  double sum_a = 0.0, sum_b = 0.0, off = 0.0;
  for (size_t s = 0; s < mesh.shooters.size(); ++s) {
    if (mesh.patches[mesh.members[mesh.shooters[s].first]].emission.r > 0.0f) continue;  // the lamp
    const double A = double(mesh.shooters[s].area);
    const double a = mean(by_rays.patch_radiosity(s)), b = mean(by_hemicube.patch_radiosity(s));
    sum_a += a * A;
    sum_b += b * A;
    off += std::abs(a - b) * A;
  }
  printf("total light: rays %+.3f%% of the hemicube's; patches apart by %.2f%% on average\n",
         100.0 * (sum_a - sum_b) / sum_b, 100.0 * off / sum_b);
  EXPECT_NEAR(sum_a, sum_b, 0.01 * sum_b);
  EXPECT_LT(off / sum_b, 0.03);
}

TEST(RayFormFactors, APointLightDeliversWhatTheCubeOfItemBuffersDelivers) {
  const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "whitted.gltf");
  RadiosityOptions options;
  options.patch_size = 0.5f;
  PatchMesh mesh = PatchMesh::build(loaded.scene, options);
  const auto delivered = [&](FormFactorMethod method) {
    options.form_factors = method;
    ProgressiveSolver solver(loaded.scene, mesh, options);
    EXPECT_EQ(solver.lights_left(), 1u);
    solver.step();  // the light's one shot
    double power = 0.0;
    for (size_t e = 0; e < mesh.size(); ++e) power += mean(solver.unshot()[e]) * double(mesh.patches[e].area);
    return power;
  };
  const double rays = delivered(FormFactorMethod::rays), cube = delivered(FormFactorMethod::hemicube);
  printf("reflected after the light's shot: rays %.6g W, cube %.6g W\n", rays, cube);
  EXPECT_NEAR(rays, cube, 0.01 * cube);
}

}  // namespace
}  // namespace luz
