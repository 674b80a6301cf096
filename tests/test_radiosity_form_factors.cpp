// Lambert's contour integral (polygon_form_factor.h) against Howell's closed forms, and the
// analytic method in the solver against the furnace (closed box: every F row sums to 1).
//
// Area-to-area factors integrate the point-to-polygon factor over the receiver with the
// three-point rule on a grid of small triangles, F_AB = (1/A_A) sum_i A_i F(i -> B); at 64 x 64
// cells per side the quadrature is far below the 0.5% asked of it (Howell's values to 4 digits).
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "radiosity/element_form_factor.h"
#include "radiosity/polygon_form_factor.h"
#include "radiosity_scenes.h"

namespace luz {
namespace {

using test::howell_b13;
using test::howell_c11;
using test::howell_c14;

// F from the rectangle origin + [0,1] u + [0,1] v (normal n) to `polygon`, integrated over
// cells x cells squares of two triangles each.
double rectangle_to_polygon(glm::vec3 origin, glm::vec3 u, glm::vec3 v, glm::vec3 n,
                            const std::vector<glm::vec3>& polygon, int cells) {
  double sum = 0.0;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      const glm::vec3 p00 = origin + (float(i) / float(cells)) * u + (float(j) / float(cells)) * v;
      const glm::vec3 p10 = p00 + u / float(cells), p01 = p00 + v / float(cells),
                      p11 = p10 + v / float(cells);
      sum += triangle_to_polygon_form_factor(p00, p10, p11, n, polygon);
      sum += triangle_to_polygon_form_factor(p00, p11, p01, n, polygon);
    }
  return sum / (2.0 * cells * cells);
}

TEST(ContourIntegral, ParallelCoaxialSquaresMatchHowellC11) {
  // Receiver: the unit square at y = 0 facing up; emitter the one at y = c facing down,
  // counter-clockwise seen from below.
  for (const float c : {0.5f, 1.0f, 2.0f}) {
    const std::vector<glm::vec3> top = {{0, c, 0}, {1, c, 0}, {1, c, 1}, {0, c, 1}};
    const double F = rectangle_to_polygon({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, top, 64);
    const double expected = howell_c11(1, 1, c);
    printf("C-11 c = %.1f: %.6f, closed form %.6f (%+.3f%%)\n", c, F, expected, 100 * (F - expected) / expected);
    EXPECT_NEAR(F, expected, 0.005 * expected);
  }
}

TEST(ContourIntegral, PerpendicularSquaresSharingAnEdgeMatchHowellC14) {
  // Floor [0,1]^2 at y = 0 facing up; wall at x = 0 facing +x, counter-clockwise seen from +x.
  for (const float h : {0.5f, 1.0f, 2.0f}) {
    const std::vector<glm::vec3> wall = {{0, 0, 0}, {0, h, 0}, {0, h, 1}, {0, 0, 1}};
    const double F = rectangle_to_polygon({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, wall, 64);
    const double expected = howell_c14(h, 1, 1);
    printf("C-14 h = %.1f: %.6f, closed form %.6f (%+.3f%%)\n", h, F, expected, 100 * (F - expected) / expected);
    EXPECT_NEAR(F, expected, 0.005 * expected);
  }
}

TEST(ContourIntegral, PointUnderADiscMatchesHowellB13) {
  // A disc as a 4096-gon inscribed in radius r (area short by (2 pi / N)^2 / 6, 4e-7).
  for (const float h : {0.5f, 1.0f, 2.0f}) {
    std::vector<glm::vec3> disc;
    const int sides = 4096;
    for (int k = 0; k < sides; ++k) {  // counter-clockwise seen from below
      const double a = 2.0 * test::pi * k / sides;
      disc.push_back({float(std::cos(a)), h, float(std::sin(a))});
    }
    const double F = point_to_polygon_form_factor({0, 0, 0}, {0, 1, 0}, disc);
    EXPECT_NEAR(F, howell_b13(1.0, h), 1e-5 * howell_b13(1.0, h)) << h;
  }
}

// An element next to the shooting patch, sharing an edge with it at a right angle, where the
// integrand grows as log(distance) toward the edge: the solver's factor (element_form_factor.h,
// 48 points there) is within 0.3% of the same integral on 1024 sub-triangles (0.05% measured);
// three points are 0.75% off.
TEST(ElementFormFactor, AnElementBesideThePatchIsIntegratedOverItsArea) {
  // The patch: a right triangle in the wall x = 0, facing +x; the element: a thin triangle on the
  // floor y = 0, facing up, along the edge they share from (0, 0, 0) to (0, 0, 1).
  ShootingPatch shooter;
  shooter.corners[0] = {0, 0, 0};
  shooter.corners[1] = {0, 1, 0};
  shooter.corners[2] = {0, 0, 1};
  shooter.normal = {1, 0, 0};
  shooter.centre = (shooter.corners[0] + shooter.corners[1] + shooter.corners[2]) / 3.0f;
  shooter.area = 0.5f;
  for (const glm::vec3& c : shooter.corners)
    shooter.radius = std::max(shooter.radius, glm::length(c - shooter.centre));
  PatchMesh mesh;
  mesh.vertices = {{0, 0, 0}, {0, 0, 1}, {0.2f, 0, 0.5f}};
  const Patch element = make_element(mesh.vertices, 0, 1, 2);
  ASSERT_GT(element.normal.y, 0.99f);
  ASSERT_TRUE(near_the_patch(element, shooter));
  const std::vector<glm::vec3> patch(std::begin(shooter.corners), std::end(shooter.corners));
  const double reference = triangle_to_polygon_form_factor(mesh.vertices[0], mesh.vertices[1], mesh.vertices[2],
                                                           element.normal, patch, 5);
  const double F = element_to_patch_form_factor(mesh, element, shooter);
  printf("element beside the patch: %.6f, 1024 sub-triangles %.6f (%+.3f%%)\n", F, reference,
         100.0 * (F - reference) / reference);
  EXPECT_GT(reference, 0.0);
  EXPECT_NEAR(F, reference, 0.003 * reference);
}

// The solver's single-precision integral (its own atan) agrees with the double one, which the
// closed forms above hold, from random points to random triangles in front of them.
TEST(ContourIntegral, SinglePrecisionAgreesWithDouble) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
  const auto point = [&] { return glm::vec3(coordinate(random), coordinate(random), coordinate(random)); };
  int compared = 0;
  double worst = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const glm::vec3 x = point(), n = glm::normalize(point());
    const std::vector<glm::vec3> triangle = {point(), point(), point()};
    const double F = point_to_polygon_form_factor(x, n, triangle);
    if (!(F > 1e-4)) continue;
    worst = std::max(worst, std::abs(point_to_polygon_form_factor_single(x, n, triangle) - F) / F);
    ++compared;
  }
  printf("%d triangles, worst relative difference %.2e\n", compared, worst);
  EXPECT_GT(compared, 2000);
  // Float's own rounding, where the contour's terms nearly cancel: 2.7e-4 at worst with the
  // library's atan2f too; the polynomial adds nothing measurable.
  EXPECT_LT(worst, 1e-3);
}

TEST(ContourIntegral, BackFacesAndWhatLiesBelowTheHorizonGiveNothing) {
  const std::vector<glm::vec3> up = {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}};  // faces up
  EXPECT_EQ(point_to_polygon_form_factor({0.5f, 0, 0.5f}, {0, 1, 0}, up), 0.0);
  const std::vector<glm::vec3> down = {{0, -1, 0}, {1, -1, 0}, {1, -1, 1}, {0, -1, 1}};
  EXPECT_EQ(point_to_polygon_form_factor({0.5f, 0, 0.5f}, {0, 1, 0}, down), 0.0);
  // A wall straddling the horizon counts only above it: half of a wall 2 m tall centred on
  // the point's plane is the C-14 wall of height 1 (point form at the floor's centre: check
  // against the unclipped upper half).
  const std::vector<glm::vec3> tall = {{0, -1, 0}, {0, 1, 0}, {0, 1, 1}, {0, -1, 1}};
  const std::vector<glm::vec3> upper = {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}};
  const glm::vec3 x(0.5f, 0.0f, 0.5f);
  EXPECT_NEAR(point_to_polygon_form_factor(x, {0, 1, 0}, tall),
              point_to_polygon_form_factor(x, {0, 1, 0}, upper), 1e-12);
  EXPECT_GT(point_to_polygon_form_factor(x, {0, 1, 0}, upper), 0.05);
}

}  // namespace
}  // namespace luz
