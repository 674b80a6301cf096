// The optics of the reflected and transmitted rays against closed forms worked here in double
// precision, independently of src/raytracing/optics.cpp (which uses the cosine form of
// Fresnel's equations; these expectations use the sine and tangent forms).
// Tolerance: 1e-5 (float arithmetic on unit vectors). And the highlight's power, computed by
// series, against std::pow in double precision.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "raytracing/hit_math.h"
#include "raytracing/optics.h"

namespace luz::rt {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr float tolerance = 1e-5f;

// A unit direction arriving at angle theta (radians) from the normal +Y, in the x-y plane,
// travelling down toward the surface y = 0.
glm::vec3 incident(double theta) { return glm::vec3(float(std::sin(theta)), float(-std::cos(theta)), 0.0f); }
const glm::vec3 N(0.0f, 1.0f, 0.0f);

TEST(Optics, ReflectionKeepsTheAngleAndTheTangent) {
  for (double deg : {0.0, 10.0, 45.0, 80.0}) {
    const glm::vec3 r = reflect(incident(deg * pi / 180), N);
    EXPECT_NEAR(r.x, std::sin(deg * pi / 180), tolerance);
    EXPECT_NEAR(r.y, std::cos(deg * pi / 180), tolerance);
    EXPECT_NEAR(r.z, 0.0f, tolerance);
  }
}

TEST(Optics, SnellsLawIntoGlass) {
  const double n1 = 1.0, n2 = 1.5;
  for (double deg : {0.0, 15.0, 30.0, 60.0, 89.0}) {
    const double ti = deg * pi / 180, tt = std::asin(n1 * std::sin(ti) / n2);
    const auto t = refract(incident(ti), N, float(n1 / n2));
    ASSERT_TRUE(t.has_value()) << deg;
    EXPECT_NEAR(t->x, std::sin(tt), tolerance) << deg;   // n1 sin(ti) = n2 sin(tt)
    EXPECT_NEAR(t->y, -std::cos(tt), tolerance) << deg;  // on through the surface
    EXPECT_NEAR(t->z, 0.0f, tolerance) << deg;           // in the plane of incidence
    EXPECT_NEAR(glm::length(*t), 1.0f, tolerance);
  }
}

TEST(Optics, TotalInternalReflectionBeyondTheCriticalAngle) {
  const double critical = std::asin(1.0 / 1.5) * 180 / pi;  // 41.81 degrees, glass to air
  EXPECT_TRUE(refract(incident((critical - 0.5) * pi / 180), N, 1.5f).has_value());
  EXPECT_FALSE(refract(incident((critical + 0.5) * pi / 180), N, 1.5f).has_value());
  EXPECT_FALSE(refract(incident(80 * pi / 180), N, 1.5f).has_value());
  // Just below the critical angle the transmitted ray leaves almost along the surface.
  const auto grazing = refract(incident((critical - 0.01) * pi / 180), N, 1.5f);
  ASSERT_TRUE(grazing.has_value());
  EXPECT_GT(grazing->x, 0.99f);
  EXPECT_EQ(fresnel_dielectric(float(std::cos((critical + 0.5) * pi / 180)), 1.5f), 1.0f);
}

// Fresnel by the sine and tangent forms: Rs = sin^2(ti - tt) / sin^2(ti + tt),
// Rp = tan^2(ti - tt) / tan^2(ti + tt), F = (Rs + Rp) / 2.
double fresnel_sines(double ti, double n1, double n2) {
  const double tt = std::asin(n1 * std::sin(ti) / n2);
  const double rs = std::pow(std::sin(ti - tt) / std::sin(ti + tt), 2);
  const double rp = std::pow(std::tan(ti - tt) / std::tan(ti + tt), 2);
  return 0.5 * (rs + rp);
}

TEST(Optics, FresnelAtNormalIncidenceIsTheSquaredRatio) {
  // ((n2 - n1) / (n2 + n1))^2 = 0.04 for glass, from either side.
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.0f / 1.5f), 0.04f, tolerance);
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.5f), 0.04f, tolerance);
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.0f / 1.33f), std::pow(0.33 / 2.33, 2), tolerance);
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.0f), 0.0f, tolerance);  // no boundary, no reflection
}

TEST(Optics, FresnelAtGrazingIncidenceIsOne) {
  EXPECT_NEAR(fresnel_dielectric(0.0f, 1.0f / 1.5f), 1.0f, tolerance);
  // Approaching grazing, F rises monotonically toward 1 (0.99 at 89.9 degrees).
  float previous = 0.0f;
  for (double deg = 80; deg < 90; deg += 0.5) {
    const float f = fresnel_dielectric(float(std::cos(deg * pi / 180)), 1.0f / 1.5f);
    EXPECT_GT(f, previous) << deg;
    previous = f;
  }
  EXPECT_GT(fresnel_dielectric(float(std::cos(89.9 * pi / 180)), 1.0f / 1.5f), 0.98f);
}

TEST(Optics, FresnelMatchesTheSineFormsAtEveryAngle) {
  for (double deg = 5; deg < 90; deg += 5) {
    const double ti = deg * pi / 180;
    EXPECT_NEAR(fresnel_dielectric(float(std::cos(ti)), float(1.0 / 1.5)),
                fresnel_sines(ti, 1.0, 1.5), 1e-5) << deg;
    if (deg < 41) {  // inside the glass, below the critical angle
      EXPECT_NEAR(fresnel_dielectric(float(std::cos(ti)), 1.5f), fresnel_sines(ti, 1.5, 1.0), 1e-5) << deg;
    }
  }
}

TEST(Optics, BrewstersAngleLeavesOnlyTheSPolarisedHalf) {
  // At tan(theta_B) = n2 / n1, Rp = 0 and ti + tt = 90 degrees, so F = sin^2(ti - tt) / 2.
  const double tb = std::atan(1.5), tt = pi / 2 - tb;
  EXPECT_NEAR(fresnel_dielectric(float(std::cos(tb)), float(1.0 / 1.5)),
              0.5 * std::pow(std::sin(tb - tt), 2), 1e-5);
}

// The highlight's cos^n(alpha), which the tracer computes by series so that its lanes vectorise,
// against the power in double precision: within 3e-7 (1 + |n log2 x|) relative (the error of
// log2 x grows with the exponent that multiplies it), exactly 1 at x = 1 and for n = 0, and 0 at
// x = 0, as std::pow gives them.
TEST(Optics, CosPowerIsPow) {
  double worst = 0.0;
  for (const float n : {0.25f, 1.0f, 1.7f, 2.0f, 5.0f, 12.5f, 32.0f, 100.0f, 128.0f, 200.0f, 900.0f, 2048.0f})
    for (int i = 1; i <= 20000; ++i) {
      const float x = float(i) / 20000.0f;
      const double exact = std::pow(double(x), double(n));
      if (exact < 1e-36) continue;  // below float's normal range the series stops at 2^-126
      const double bound = 3e-7 * (1.0 + std::abs(double(n) * std::log2(double(x))));
      const double error = std::abs(double(cos_power(x, n)) - exact) / exact;
      worst = std::max(worst, error / bound);
      ASSERT_LE(error, bound) << "x " << x << ", n " << n;
    }
  EXPECT_GT(worst, 0.1);  // the bound is not slack by orders of magnitude
  EXPECT_EQ(cos_power(1.0f, 200.0f), 1.0f);
  EXPECT_EQ(cos_power(0.3f, 0.0f), 1.0f);
  EXPECT_EQ(cos_power(0.0f, 0.0f), 1.0f);
  EXPECT_EQ(cos_power(0.0f, 10.0f), 0.0f);
  EXPECT_LT(cos_power(1e-30f, 2.0f), 1e-37f);
}

}  // namespace
}  // namespace luz::rt
