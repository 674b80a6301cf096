// Adaptive subdivision (slide 40, "Mallado"; mesh_bisection.h, adaptive_subdivision.cpp):
//
// - the cuts go where the light changes: under a point light and a square occluder, the new
//   elements lie along the shadow's outline, which is known in closed form;
// - the new elements hold what they would have received had they been there from the start:
//   lit ones the light's closed-form irradiance, shadowed ones none; and a mesh refined halfway
//   through the solution ends where the same mesh solved from scratch ends;
// - the mesh stays conforming (no vertex in the middle of another element's edge), its patches
//   keep their area, locate() finds the element holding a point, and reset() gives back the mesh;
// - the energy balance holds at every step, refinements included.
#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/error.h"
#include "io/gltf_loader.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/shooting.h"
#include "radiosity_scenes.h"
#include "support.h"

namespace luz {
namespace {

using test::add_material;
using test::add_quad;

double mean(const Rgb& c) { return (double(c.r) + double(c.g) + double(c.b)) / 3.0; }

// A 4 x 4 m floor (rho 0.5) under a point light 4 m up, with a 1 x 1 m plate halfway, facing
// the floor: the shadow is the square |x|, |z| <= 1, the light's hard edge its outline.
constexpr float kLightHeight = 4.0f, kPlateHeight = 2.0f, kPlateHalf = 0.5f;
constexpr float kShadowHalf = kPlateHalf * kLightHeight / (kLightHeight - kPlateHeight);
constexpr float kIntensity = 40.0f;

Scene shadowed_floor(float plate_rho) {
  Scene scene;
  const int floor = add_material(scene, 0.5f), plate = add_material(scene, plate_rho);
  add_quad(scene, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, floor, "floor");
  const float a = kPlateHalf, h = kPlateHeight;
  add_quad(scene, {-a, h, -a}, {a, h, -a}, {a, h, a}, {-a, h, a}, plate, "plate");  // faces down
  Light light;
  light.position = {0.0f, kLightHeight, 0.0f};
  light.intensity = Rgb(kIntensity);
  scene.lights.push_back(light);
  return scene;
}

RadiosityOptions adaptive_options() {
  RadiosityOptions options;
  options.patch_size = 0.5f;
  options.elements_per_edge = 2;  // 0.25 m elements
  options.meshing = Meshing::adaptive;
  options.converge = 0.001f;
  return options;
}

// Distance from a floor point to the shadow's outline.
float to_outline(const glm::vec3& p) {
  return std::abs(std::max(std::abs(p.x), std::abs(p.z)) - kShadowHalf);
}

bool on_floor(const Patch& p) { return p.mesh == 0; }

// The light's irradiance on a floor element, by a 64-point quadrature of I cos / d^2 over it.
double direct_irradiance(const PatchMesh& mesh, const Patch& p) {
  const glm::vec3 &a = mesh.vertices[p.vertices[0]], &b = mesh.vertices[p.vertices[1]],
                  &c = mesh.vertices[p.vertices[2]];
  const glm::vec3 light(0.0f, kLightHeight, 0.0f);
  double sum = 0.0;
  const int n = 8;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = (i + 0.5) / n, v = (j + 0.5) / n;
      const double s = std::sqrt(u);
      const glm::dvec3 x = (1 - s) * glm::dvec3(a) + s * (1 - v) * glm::dvec3(b) + s * v * glm::dvec3(c);
      const glm::dvec3 d = glm::dvec3(light) - x;
      const double r = glm::length(d);
      sum += kIntensity * (d.y / r) / (r * r);
    }
  return sum / (n * n);
}

TEST(AdaptiveSubdivision, CutsAlongTheShadowsOutlineOnly) {
  const Scene scene = shadowed_floor(0.0f);
  PatchMesh mesh = PatchMesh::build(scene, adaptive_options());
  const size_t built = mesh.size();
  ProgressiveSolver solver(scene, mesh, adaptive_options());
  while (solver.step()) {}
  ASSERT_GT(solver.refinement_passes(), 0);
  size_t cut = 0, near_outline = 0;
  for (const Patch& p : mesh.patches) {
    if (p.level == 0) continue;
    ++cut;
    // Within two of the uniform elements' diagonals of the outline (conformity cuts some
    // neighbours beside the ones the gradient chose).
    if (to_outline(p.centre) < 2.0f * 0.25f * std::sqrt(2.0f)) ++near_outline;
  }
  EXPECT_GT(mesh.size(), built + 200) << "the outline is 8 m long: it needs many cuts";
  EXPECT_EQ(solver.refined_elements(), mesh.size() - built);
  EXPECT_GE(double(near_outline), 0.98 * double(cut)) << near_outline << " of " << cut;
  // And the elements far from it are left as built.
  for (const Patch& p : mesh.patches) {
    if (!on_floor(p) || to_outline(p.centre) <= 0.6f) continue;
    EXPECT_EQ(p.level, 0) << p.centre.x << " " << p.centre.z;
  }
}

TEST(AdaptiveSubdivision, NewElementsHoldTheLightsClosedForm) {
  // A black plate: the floor shows the light's direct irradiance only, known in closed form.
  const Scene scene = shadowed_floor(0.0f);
  PatchMesh mesh = PatchMesh::build(scene, adaptive_options());
  ProgressiveSolver solver(scene, mesh, adaptive_options());
  while (solver.step()) {}
  size_t lit = 0, dark = 0;
  for (size_t e = 0; e < mesh.size(); ++e) {
    const Patch& p = mesh.patches[e];
    if (!on_floor(p) || p.level == 0) continue;
    float nearest = 1e9f, farthest = 0.0f;  // of its corners, to the outline, signed inside
    bool inside = false, outside = false;
    for (const uint32_t v : p.vertices) {
      const glm::vec3& x = mesh.vertices[v];
      const float chebyshev = std::max(std::abs(x.x), std::abs(x.z));
      (chebyshev < kShadowHalf - 1e-4f ? inside : outside) = true;
      nearest = std::min(nearest, to_outline(x));
      farthest = std::max(farthest, to_outline(x));
    }
    const double got = mean(solver.irradiance()[e]);
    if (outside && !inside) {
      ++lit;
      EXPECT_NEAR(got, direct_irradiance(mesh, p), 2e-3 * direct_irradiance(mesh, p)) << e;
      EXPECT_NEAR(mean(solver.displayed()[e]), 0.5 * got, 1e-4 * got) << "displayed = rho H";
    } else if (inside && !outside) {
      ++dark;
      EXPECT_EQ(got, 0.0) << e;
    }
  }
  EXPECT_GT(lit, 50u);
  EXPECT_GT(dark, 50u);
}

// Refined halfway, after the light and 40 patches have shot, with the floor and plate lighting
// each other: what the new elements gathered from those shots and what they receive after must
// add up to the solution of the same mesh solved from its first shot.
TEST(AdaptiveSubdivision, RefiningHalfwayEndsWhereTheRefinedMeshSolvedFromScratchEnds) {
  const Scene scene = shadowed_floor(0.8f);
  RadiosityOptions options = adaptive_options();
  options.meshing = Meshing::uniform;  // no passes of its own: this test cuts once, by hand
  options.converge = 1e-4f;
  options.visibility_rays = 16;
  PatchMesh mesh = PatchMesh::build(scene, options);
  ProgressiveSolver halfway(scene, mesh, options);
  for (int shot = 0; shot < 41; ++shot) halfway.step();
  ASSERT_GT(halfway.refine(), 100u);
  while (halfway.step()) {}

  PatchMesh same = mesh;  // the refined mesh, solved from scratch
  ProgressiveSolver scratch(scene, same, options);
  while (scratch.step()) {}

  const std::vector<Rgb> a = halfway.displayed(), b = scratch.displayed();
  ASSERT_EQ(a.size(), b.size());
  double difference = 0.0, total = 0.0, new_difference = 0.0, new_total = 0.0;
  for (size_t e = 0; e < a.size(); ++e) {
    const double area = double(mesh.patches[e].area);
    difference += std::abs(mean(a[e]) - mean(b[e])) * area;
    total += mean(b[e]) * area;
    if (mesh.patches[e].level > 0) {
      new_difference += std::abs(mean(a[e]) - mean(b[e])) * area;
      new_total += mean(b[e]) * area;
    }
  }
  EXPECT_LT(difference / total, 0.01);
  EXPECT_LT(new_difference / new_total, 0.01) << "the new elements themselves";
}

TEST(AdaptiveSubdivision, EnergyBalancesAtEveryStepRefinementsIncluded) {
  const Scene scene = shadowed_floor(0.8f);
  PatchMesh mesh = PatchMesh::build(scene, adaptive_options());
  ProgressiveSolver solver(scene, mesh, adaptive_options());
  int passes = 0;
  while (solver.step()) {
    const EnergyTally t = solver.energy();
    ASSERT_NEAR(t.absorbed + t.unshot + t.escaped, t.emitted, 1e-5 * t.emitted) << solver.shots();
    ASSERT_GE(t.escaped, -1e-5 * t.emitted);
    passes = solver.refinement_passes();
  }
  EXPECT_GE(passes, 1);
}

// In a closed box nothing escapes: what the new elements gather from every shot so far must be
// all that reached their parents (with rays, whose rows sum to 1 there), or "escaped" would grow.
TEST(AdaptiveSubdivision, InAClosedBoxTheGatheredLightIsAllThereIs) {
  Scene scene;
  const int lamp = add_material(scene, 0.3f, 2.0f), grey = add_material(scene, 0.6f);
  const int materials[6] = {grey, lamp, grey, grey, grey, grey};
  test::add_closed_box(scene, materials);
  // A plate over the floor casts a shadow to refine along.
  add_quad(scene, {0.3f, 0.3f, 0.3f}, {0.7f, 0.3f, 0.3f}, {0.7f, 0.3f, 0.7f}, {0.3f, 0.3f, 0.7f}, grey, "plate");
  add_quad(scene, {0.3f, 0.3f, 0.3f}, {0.3f, 0.3f, 0.7f}, {0.7f, 0.3f, 0.7f}, {0.7f, 0.3f, 0.3f}, grey, "top");
  RadiosityOptions options;
  options.patch_size = 0.25f;
  options.elements_per_edge = 2;
  options.visibility_rays = 16;
  options.converge = 0.02f;
  PatchMesh mesh = PatchMesh::build(scene, options);
  const size_t built = mesh.size();
  ProgressiveSolver solver(scene, mesh, options);
  while (solver.step()) {
    const EnergyTally t = solver.energy();
    ASSERT_LT(std::abs(t.escaped), 3e-3 * t.emitted) << "shot " << solver.shots();
  }
  EXPECT_GT(mesh.size(), built + 50);

  // Shot through the hemicube, whose factors next to a shooter are off by a few percent, the
  // new elements' exact gathers differ from what their parents got: that light is moved between
  // the terms, and they still add up to what was emitted.
  options.form_factors = FormFactorMethod::hemicube;
  options.hemicube_res = 64;
  PatchMesh by_cube = PatchMesh::build(scene, options);
  ProgressiveSolver cube(scene, by_cube, options);
  double moved = 0.0;
  while (cube.step()) {
    const EnergyTally t = cube.energy();
    ASSERT_NEAR(t.absorbed + t.unshot + t.escaped, t.emitted, 1e-5 * t.emitted) << "shot " << cube.shots();
    moved = std::max(moved, std::abs(t.escaped));
  }
  EXPECT_GT(moved, 1e-3 * cube.emitted_power()) << "the gathers did move light";
}

// For every source mesh: no element edge has a vertex of that mesh at its midpoint (where a cut
// of the neighbour would have put a T-junction).
void expect_conforming(const PatchMesh& mesh) {
  std::set<std::tuple<int, float, float, float>> points;  // (source mesh, position)
  for (const Patch& p : mesh.patches)
    for (const uint32_t v : p.vertices)
      points.emplace(p.mesh, mesh.vertices[v].x, mesh.vertices[v].y, mesh.vertices[v].z);
  size_t junctions = 0;
  for (const Patch& p : mesh.patches)
    for (int k = 0; k < 3; ++k) {
      glm::vec3 a = mesh.vertices[p.vertices[k]], b = mesh.vertices[p.vertices[(k + 1) % 3]];
      if (std::tie(b.x, b.y, b.z) < std::tie(a.x, a.y, a.z)) std::swap(a, b);
      const glm::vec3 m = a + 0.5f * (b - a);
      junctions += points.count({p.mesh, m.x, m.y, m.z});
    }
  EXPECT_EQ(junctions, 0u);
}

TEST(AdaptiveSubdivision, TheCornellBoxMeshStaysConformingAndLocatable) {
  const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "cornell_box.gltf");
  RadiosityOptions options;
  options.target_patches = 200;
  options.meshing = Meshing::adaptive;
  options.converge = 0.04f;  // past the last pass
  PatchMesh mesh = PatchMesh::build(loaded.scene, options);
  const size_t built = mesh.size();
  const float area = mesh.total_area();
  std::vector<float> shooter_area;
  for (const ShootingPatch& s : mesh.shooters) shooter_area.push_back(s.area);
  ProgressiveSolver solver(loaded.scene, mesh, options);
  while (solver.step()) {}
  ASSERT_GT(mesh.size(), built + 100);

  expect_conforming(mesh);
  EXPECT_NEAR(mesh.total_area(), area, 1e-4 * area);
  for (size_t s = 0; s < mesh.shooters.size(); ++s) {
    double sum = 0.0;
    for (uint32_t k = 0; k < mesh.shooters[s].count; ++k)
      sum += mesh.patches[mesh.members[mesh.shooters[s].first + k]].area;
    EXPECT_NEAR(sum, shooter_area[s], 1e-4 * shooter_area[s]) << "patch " << s;
  }

  // locate(): the element it names holds the point, and its weights give the point back.
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  size_t in_cut = 0;
  for (size_t m = 0; m < loaded.scene.meshes.size(); ++m) {
    const Mesh& source = loaded.scene.meshes[m];
    for (size_t t = 0; t < source.triangle_count(); ++t)
      for (int sample = 0; sample < 200; ++sample) {
        float u = unit(random), v = unit(random);
        if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
        const glm::vec3 &A = source.positions[source.indices[3 * t]],
                        &B = source.positions[source.indices[3 * t + 1]],
                        &C = source.positions[source.indices[3 * t + 2]];
        const glm::vec3 point = A + u * (B - A) + v * (C - A);
        const PatchMesh::Location where = mesh.locate(int(m), int(t), {u, v});
        const Patch& p = mesh.patches[where.patch];
        ASSERT_EQ(p.mesh, int(m));
        ASSERT_EQ(p.triangle, int(t));
        const glm::vec3 back = where.weights.x * mesh.vertices[p.vertices[0]] +
                               where.weights.y * mesh.vertices[p.vertices[1]] +
                               where.weights.z * mesh.vertices[p.vertices[2]];
        EXPECT_LT(glm::length(back - point), 1e-4f) << "mesh " << m << " triangle " << t;
        if (p.level > 0) ++in_cut;
      }
  }
  EXPECT_GT(in_cut, 0u) << "some points fell in cut elements";
}

TEST(AdaptiveSubdivision, ResetGivesTheMeshBackAndSolvesTheSameAgain) {
  const Scene scene = shadowed_floor(0.8f);
  PatchMesh mesh = PatchMesh::build(scene, adaptive_options());
  const size_t built = mesh.size();
  ProgressiveSolver solver(scene, mesh, adaptive_options());
  while (solver.step()) {}
  const std::vector<Rgb> first = solver.displayed();
  const size_t refined = mesh.size();
  const int revision = mesh.revision;
  ASSERT_GT(refined, built);
  solver.reset();
  EXPECT_EQ(mesh.size(), built);
  EXPECT_NE(mesh.revision, revision) << "a renderer must know to upload the elements again";
  EXPECT_EQ(solver.refined_elements(), 0u);
  while (solver.step()) {}
  EXPECT_EQ(mesh.size(), refined);
  const std::vector<Rgb> second = solver.displayed();
  for (size_t e = 0; e < first.size(); ++e) ASSERT_EQ(mean(first[e]), mean(second[e])) << e;
}

TEST(AdaptiveSubdivision, UniformMeshingLeavesTheMeshAlone) {
  const Scene scene = shadowed_floor(0.8f);
  RadiosityOptions options = adaptive_options();
  options.meshing = Meshing::uniform;
  PatchMesh mesh = PatchMesh::build(scene, options);
  const size_t built = mesh.size();
  ProgressiveSolver solver(scene, mesh, options);
  while (solver.step()) {}
  EXPECT_EQ(mesh.size(), built);
  EXPECT_EQ(solver.refinement_passes(), 0);
}

TEST(AdaptiveSubdivision, ASolverRefusesAMeshAnotherHasRefined) {
  const Scene scene = shadowed_floor(0.8f);
  PatchMesh mesh = PatchMesh::build(scene, adaptive_options());
  ProgressiveSolver first(scene, mesh, adaptive_options()), second(scene, mesh, adaptive_options());
  while (first.step()) {}
  ASSERT_GT(first.refined_elements(), 0u);
  EXPECT_THROW(second.step(), Error);
}

// Subdivision respects its element budget: the shadow's outline wants hundreds of cuts (above),
// a budget of 100 stops them with at most 100 elements added, and says so.
TEST(AdaptiveSubdivision, StopsAtItsElementBudgetAndSaysSo) {
  const Scene scene = shadowed_floor(0.0f);
  RadiosityOptions options = adaptive_options();
  options.refine_budget = 100;
  PatchMesh mesh = PatchMesh::build(scene, options);
  const size_t built = mesh.size();
  ProgressiveSolver solver(scene, mesh, options);
  size_t largest = built;
  while (solver.step()) largest = std::max(largest, mesh.size());
  ASSERT_GT(solver.refinement_passes(), 0);
  EXPECT_LE(largest, built + 100);
  EXPECT_GT(mesh.size(), built + 50) << "it cuts up to the budget";
  size_t said = 0;
  for (const std::string& w : solver.warnings()) said += w.find("its budget of 100 more") != std::string::npos;
  EXPECT_EQ(said, 1u) << "once";
}

TEST(AdaptiveSubdivision, BadSettingsAreRefused) {
  RadiosityOptions options;
  options.refine_threshold = 0.0f;
  EXPECT_THROW(options.validate(), Error);
  options.refine_threshold = std::nanf("");
  EXPECT_THROW(options.validate(), Error);
  options.refine_threshold = 0.1f;
  options.refine_levels = 0;
  EXPECT_THROW(options.validate(), Error);
  options.refine_levels = kMaxRefineLevels + 1;
  EXPECT_THROW(options.validate(), Error);
  options.refine_levels = 4;
  options.refine_budget = -1;
  EXPECT_THROW(options.validate(), Error);
  options.refine_budget = kMaxRefineBudget + 1;
  EXPECT_THROW(options.validate(), Error);
  options.refine_budget = 0;
  EXPECT_NO_THROW(options.validate());
}

}  // namespace
}  // namespace luz
