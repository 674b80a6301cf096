// The local models against closed forms of the lecture's formula (slides 15-19, SCENES.md):
//   I = Ia*ka + sum_i IL_i * [kd*cos(theta) + ks*cos^n(alpha)]  (+ Le)
// rendered headless through OSMesa into float pixels.
//
// The setup makes every pixel a known point: a quad in the plane z = 0, seen straight down the
// -Z axis from (0, 0, 2), parallel to the image plane, so pixel centre -> world point is affine.
// The quad is a grid whose vertices sit exactly on every third pixel centre, so
//   - Phong is checked at every pixel (the closed form at the unprojected pixel centre),
//   - Gouraud at the pixels over the vertices (where the interpolated colour is the vertex's),
//   - flat at the pixels over the triangles' centroids (3x3-pixel cells put them on centres).
// Expected values are computed here in double precision from the closed forms, independently of
// the shaders. Tolerance: 1% relative, plus an absolute floor of 1e-4 of the image's largest
// expected value (for the far tails of highlights, where a relative test means nothing).
//
// The OpenGL context is made once for the whole test binary (GlEnvironment below), and is also
// the one test_local_models.cpp uses.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/scene.h"
#include "gl/shader.h"
#include "gl/window_context.h"
#include "local/local_renderer.h"

namespace luz {
namespace {

// ---- The quad seen from above -----------------------------------------------------------------
constexpr int size = 96;                // image width and height, pixels
constexpr int cell = 3;                 // grid cell, pixels: centroids land on pixel centres
constexpr double camera_height = 2.0;   // the camera at (0, 0, 2) looks down -Z
constexpr double pi = 3.14159265358979323846;
// yfov = 2 atan(1/2): the view covers exactly [-1, 1]^2 of the plane z = 0.
const float yfov = float(2.0 * std::atan(0.5));
constexpr double pixel = 2.0 / size;    // world size of a pixel on the plane

using dvec3 = glm::dvec3;

// The world point under the centre of pixel (x, y), row 0 at the top (+Y up in the world).
dvec3 world_of_pixel(double x, double y) {
  return {-1.0 + (x + 0.5) * pixel, 1.0 - (y + 0.5) * pixel, 0.0};
}

const dvec3 eye(0.0, 0.0, camera_height);
const dvec3 up_normal(0.0, 0.0, 1.0);

Camera top_camera() {
  Camera camera;
  camera.name = "top";
  camera.to_world = glm::translate(glm::mat4(1.0f), glm::vec3(eye));
  camera.yfov = yfov;
  camera.znear = 0.1f;
  camera.zfar = 10.0f;
  return camera;
}

// A grid over the plane z = 0 with a vertex on every `cell`-th pixel centre, reaching one cell
// past the image on every side. uv = (0, 0) at the image's top-left corner, (1, 1) bottom-right.
// `flipped`: clockwise winding seen from the camera and normals pointing down, away from the
// viewer (the two-sided lighting must make it render the same).
Mesh grid_quad(bool flipped = false) {
  Mesh mesh;
  mesh.name = flipped ? "quad (flipped)" : "quad";
  const int first = -1, last = size / cell + 1;  // vertex columns/rows, in cells
  const int n = last - first + 1;
  for (int j = first; j <= last; ++j)
    for (int i = first; i <= last; ++i) {
      const dvec3 p = world_of_pixel(i * cell, j * cell);
      mesh.positions.emplace_back(p);
      mesh.normals.emplace_back(0.0f, 0.0f, flipped ? -1.0f : 1.0f);
      mesh.uvs.emplace_back(float((p.x + 1.0) / 2.0), float((1.0 - p.y) / 2.0));
    }
  const auto index = [&](int i, int j) { return uint32_t((j - first) * n + (i - first)); };
  for (int j = first; j < last; ++j)
    for (int i = first; i < last; ++i) {
      // In pixel coordinates a = (i, j), b = (i+1, j), c = (i+1, j+1), d = (i, j+1), in cells.
      // Triangles (a, b, c) and (a, c, d): centroids at a + (2, 1) and a + (1, 2) pixels.
      // Counter-clockwise seen from +Z is a, c, b (pixel y runs down the world's y).
      const uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1),
                     d = index(i, j + 1);
      const std::vector<uint32_t> front = {a, c, b, a, d, c};
      const std::vector<uint32_t> back = {a, b, c, a, c, d};
      for (uint32_t v : flipped ? back : front) mesh.indices.push_back(v);
    }
  return mesh;
}

Scene quad_scene(const Material& material, bool flipped = false) {
  Scene scene;
  scene.path = "quad (built in the test)";
  scene.materials.push_back(material);
  scene.meshes.push_back(grid_quad(flipped));
  scene.cameras.push_back(top_camera());
  return scene;
}

Material grey_material() {
  Material m;
  m.name = "test";
  m.kd = Rgb(0.6f, 0.5f, 0.4f);
  m.ka = Rgb(0.3f, 0.2f, 0.1f);
  m.ks = Rgb(0.5f, 0.4f, 0.3f);
  m.shininess = 30.0f;
  return m;
}

Light point_light(glm::vec3 position, Rgb intensity) {
  Light light;
  light.name = "point";
  light.type = LightType::point;
  light.position = position;
  light.intensity = intensity;
  return light;
}

LocalOptions only(bool ambient, bool diffuse, bool specular) {
  LocalOptions o;
  o.terms.ambient = ambient;
  o.terms.diffuse = diffuse;
  o.terms.specular = specular;
  return o;
}

Image render(const Scene& scene, Shading shading, LocalOptions options) {
  options.shading = shading;
  LocalRenderer renderer(scene);
  return renderer.render(scene.cameras[0], size, size, options);
}

// ---- Closed forms (double precision, written from the lecture, not from the shaders) --------
dvec3 rgb(const Rgb& c) { return dvec3(c); }

// Unit vector from P toward the light, and the distance.
struct Toward {
  dvec3 L;
  double d;
};
Toward toward(const dvec3& P, const dvec3& light_position) {
  const dvec3 v = light_position - P;
  return {glm::normalize(v), glm::length(v)};
}

// cos(alpha) of Phong: R the mirror of L about N, against V.
double cos_alpha_phong(const dvec3& N, const dvec3& L, const dvec3& V) {
  const dvec3 R = 2.0 * glm::dot(N, L) * N - L;
  return std::max(glm::dot(R, V), 0.0);
}
// cos(alpha) of Blinn: N against the half vector.
double cos_alpha_blinn(const dvec3& N, const dvec3& L, const dvec3& V) {
  return std::max(glm::dot(N, glm::normalize(L + V)), 0.0);
}

// IL * [kd cos(theta) + ks cos^n(alpha)] with the switches; zero when N.L <= 0.
dvec3 reflected(const dvec3& IL, const dvec3& N, const dvec3& L, const dvec3& P,
                const Material& m, bool diffuse, bool specular, bool blinn = false) {
  const double cos_theta = glm::dot(N, L);
  if (cos_theta <= 0.0) return dvec3(0.0);
  const dvec3 V = glm::normalize(eye - P);
  const double ca = blinn ? cos_alpha_blinn(N, L, V) : cos_alpha_phong(N, L, V);
  dvec3 I(0.0);
  if (diffuse) I += IL * rgb(m.kd) * cos_theta;
  if (specular) I += IL * rgb(m.ks) * std::pow(ca, double(m.shininess));
  return I;
}

// A point light of intensity I at distance d, physical attenuation: IL = I / (pi d^2).
dvec3 point_IL(const Rgb& intensity, double d) { return rgb(intensity) / (pi * d * d); }

// ---- Comparing pixels with the closed form ----------------------------------------------------
// The pixels where a model's value is known exactly: all (Phong), vertices (Gouraud), centroids
// (flat). Each comes with the world point where the formula is evaluated.
struct Sample {
  int x, y;
  dvec3 P;
};

std::vector<Sample> samples(Shading shading) {
  std::vector<Sample> out;
  const auto add = [&](int x, int y) {
    if (x >= 0 && y >= 0 && x < size && y < size) out.push_back({x, y, world_of_pixel(x, y)});
  };
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      switch (shading) {
        case Shading::phong: add(x, y); break;
        case Shading::gouraud:
          if (x % cell == 0 && y % cell == 0) add(x, y);
          break;
        case Shading::flat:  // triangle (a, b, c) -> a + (2, 1); (a, c, d) -> a + (1, 2)
          if ((x % cell == 2 && y % cell == 1) || (x % cell == 1 && y % cell == 2)) add(x, y);
          break;
      }
    }
  return out;
}

// Compares the model's known pixels with `expected(P)`; reports the first few misses.
void expect_formula(const Image& image, Shading shading,
                    const std::function<dvec3(const dvec3& P)>& expected,
                    double relative = 0.01) {
  const std::vector<Sample> points = samples(shading);
  ASSERT_FALSE(points.empty());
  std::vector<dvec3> want;
  double largest = 0.0;
  for (const Sample& s : points) {
    want.push_back(expected(s.P));
    largest = std::max({largest, want.back().r, want.back().g, want.back().b});
  }
  const double floor = 1e-4 * largest;
  int misses = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Rgb got = image.at(points[i].x, points[i].y);
    for (int c = 0; c < 3; ++c) {
      const double w = want[i][c], g = got[c];
      if (std::abs(g - w) <= relative * std::abs(w) + floor) continue;
      if (++misses <= 5)
        ADD_FAILURE() << fmt::format("{} pixel ({}, {}) over ({:.4f}, {:.4f}) channel {}: got "
                                     "{:.6g}, closed form {:.6g}", to_string(shading),
                                     points[i].x, points[i].y, points[i].P.x, points[i].P.y, c,
                                     g, w);
    }
  }
  EXPECT_EQ(misses, 0) << to_string(shading) << ": " << points.size() << " pixels checked";
}

const Shading all_models[] = {Shading::phong, Shading::gouraud, Shading::flat};

// ---- The terms one by one ---------------------------------------------------------------------
TEST(LocalFormula, AmbientOnlyIsIaTimesKa) {
  Scene scene = quad_scene(grey_material());
  scene.ambient = Rgb(0.5f, 1.0f, 2.0f);
  scene.lights.push_back(point_light({0.2f, -0.1f, 0.8f}, Rgb(3.0f)));  // switched off below
  for (Shading shading : all_models) {
    const Image image = render(scene, shading, only(true, false, false));
    expect_formula(image, shading, [&](const dvec3&) {
      return rgb(scene.ambient) * rgb(scene.materials[0].ka);  // I_A = Ia * ka
    });
  }
}

TEST(LocalFormula, DiffusePointLightIsLambert) {
  Scene scene = quad_scene(grey_material());
  const glm::vec3 at(0.2f, -0.1f, 0.8f);
  scene.lights.push_back(point_light(at, Rgb(3.0f, 2.0f, 1.0f)));
  for (Shading shading : all_models) {
    const Image image = render(scene, shading, only(false, true, false));
    // kd/pi * I * cos(theta) / d^2
    expect_formula(image, shading, [&](const dvec3& P) {
      const Toward t = toward(P, dvec3(at));
      const double cos_theta = glm::dot(up_normal, t.L);
      return rgb(scene.materials[0].kd) / pi * rgb(scene.lights[0].intensity) * cos_theta /
             (t.d * t.d);
    });
  }
}

TEST(LocalFormula, SpecularPointLightIsPhong) {
  Scene scene = quad_scene(grey_material());
  const glm::vec3 at(0.3f, -0.2f, 1.2f);
  scene.lights.push_back(point_light(at, Rgb(3.0f, 2.0f, 1.0f)));
  for (Shading shading : all_models) {
    const Image image = render(scene, shading, only(false, false, true));
    // IL * ks * cos^n(alpha), R the mirror of L about N
    expect_formula(image, shading, [&](const dvec3& P) {
      const Toward t = toward(P, dvec3(at));
      const dvec3 V = glm::normalize(eye - P);
      return point_IL(scene.lights[0].intensity, t.d) * rgb(scene.materials[0].ks) *
             std::pow(cos_alpha_phong(up_normal, t.L, V), 30.0);
    });
  }
}

TEST(LocalFormula, BlinnUsesTheHalfVector) {
  Scene scene = quad_scene(grey_material());
  const glm::vec3 at(0.3f, -0.2f, 1.2f);
  scene.lights.push_back(point_light(at, Rgb(3.0f, 2.0f, 1.0f)));
  LocalOptions options = only(false, false, true);
  options.terms.blinn = true;
  const auto blinn = [&](const dvec3& P) {
    const Toward t = toward(P, dvec3(at));
    const dvec3 V = glm::normalize(eye - P);
    return point_IL(scene.lights[0].intensity, t.d) * rgb(scene.materials[0].ks) *
           std::pow(cos_alpha_blinn(up_normal, t.L, V), 30.0);
  };
  for (Shading shading : all_models) expect_formula(render(scene, shading, options), shading, blinn);

  // And Blinn is not Phong: away from the mirror point the two differ by far more than 1%.
  const Image phong = render(scene, Shading::phong, only(false, false, true));
  const Image half = render(scene, Shading::phong, options);
  EXPECT_GT(half.at(10, 10).r, 2.0f * phong.at(10, 10).r);
}

TEST(LocalFormula, AllTermsTogetherAdd) {
  Scene scene = quad_scene(grey_material());
  scene.ambient = Rgb(0.2f);
  const glm::vec3 at(0.3f, -0.2f, 1.2f);
  scene.lights.push_back(point_light(at, Rgb(3.0f, 2.0f, 1.0f)));
  for (Shading shading : all_models) {
    expect_formula(render(scene, shading, LocalOptions{}), shading, [&](const dvec3& P) {
      const Toward t = toward(P, dvec3(at));
      return rgb(scene.ambient) * rgb(scene.materials[0].ka) +
             reflected(point_IL(scene.lights[0].intensity, t.d), up_normal, t.L, P,
                       scene.materials[0], true, true);
    });
  }
}

// ---- Attenuation and light types --------------------------------------------------------------
TEST(LocalFormula, ClassroomAttenuation) {
  Scene scene = quad_scene(grey_material());
  const glm::vec3 at(-0.4f, 0.3f, 0.9f);
  Light light = point_light(at, Rgb(2.0f));
  light.attenuation.classroom = true;
  light.attenuation.c = glm::vec3(0.5f, 0.8f, 0.3f);
  scene.lights.push_back(light);
  for (Shading shading : all_models) {
    expect_formula(render(scene, shading, only(false, true, true)), shading, [&](const dvec3& P) {
      const Toward t = toward(P, dvec3(at));
      const dvec3 IL = rgb(light.intensity) / (0.5 + 0.8 * t.d + 0.3 * t.d * t.d) / pi;
      return reflected(IL, up_normal, t.L, P, scene.materials[0], true, true);
    });
  }
}

// A spot straight above the quad, pointing down: the cone's edges cross the picture.
Light down_spot() {
  Light light = point_light({0.1f, 0.0f, 1.0f}, Rgb(4.0f, 3.0f, 2.0f));
  light.name = "spot";
  light.type = LightType::spot;
  light.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  return light;
}

TEST(LocalFormula, SpotSmoothCone) {
  Scene scene = quad_scene(grey_material());
  Light light = down_spot();
  light.inner_cone = 0.3f;
  light.outer_cone = 0.6f;
  scene.lights.push_back(light);
  const double cos_inner = std::cos(0.3), cos_outer = std::cos(0.6);
  for (Shading shading : all_models) {
    expect_formula(render(scene, shading, only(false, true, false)), shading, [&](const dvec3& P) {
      const Toward t = toward(P, dvec3(light.position));
      // glTF's smooth falloff: the square of a linear ramp in cos(angle) from outer to inner.
      const double cos_angle = glm::dot(dvec3(0, 0, -1), -t.L);
      const double ramp = std::clamp((cos_angle - cos_outer) / (cos_inner - cos_outer), 0.0, 1.0);
      return reflected(point_IL(light.intensity, t.d) * ramp * ramp, up_normal, t.L, P,
                       scene.materials[0], true, false);
    });
  }
  // Inside the inner cone the spot is a point light; outside the outer cone it is dark.
  const Image image = render(scene, Shading::phong, only(false, true, false));
  EXPECT_GT(image.at(size / 2 + 2, size / 2).r, 0.1f);
  EXPECT_EQ(image.at(2, 2).r, 0.0f);
}

TEST(LocalFormula, SpotWarn) {
  Scene scene = quad_scene(grey_material());
  Light light = down_spot();
  light.warn_exponent = 8.0f;
  light.outer_cone = 0.7f;
  scene.lights.push_back(light);
  const double cos_outer = std::cos(0.7);
  for (Shading shading : all_models) {
    expect_formula(render(scene, shading, only(false, true, true)), shading, [&](const dvec3& P) {
      const Toward t = toward(P, dvec3(light.position));
      // Warn's non-uniform light: cos^p of the angle off the axis, inside the outer cone.
      const double cos_angle = glm::dot(dvec3(0, 0, -1), -t.L);
      const double warn = cos_angle >= cos_outer ? std::pow(cos_angle, 8.0) : 0.0;
      return reflected(point_IL(light.intensity, t.d) * warn, up_normal, t.L, P,
                       scene.materials[0], true, true);
    });
  }
}

TEST(LocalFormula, DirectionalLightIsEOverPi) {
  Scene scene = quad_scene(grey_material());
  Light sun;
  sun.name = "sun";
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, 0.4f, -1.0f));
  sun.intensity = Rgb(2.0f, 1.5f, 1.0f);  // E_perp, W/m^2
  scene.lights.push_back(sun);
  const dvec3 L = -glm::normalize(dvec3(0.3, 0.4, -1.0));
  for (Shading shading : all_models) {
    expect_formula(render(scene, shading, only(false, true, true)), shading, [&](const dvec3& P) {
      return reflected(rgb(sun.intensity) / pi, up_normal, L, P, scene.materials[0], true, true);
    });
  }
}

TEST(LocalFormula, TwoLightsAdd) {
  Scene scene = quad_scene(grey_material());
  const glm::vec3 at(0.3f, -0.2f, 1.2f);
  scene.lights.push_back(point_light(at, Rgb(3.0f, 2.0f, 1.0f)));
  Light sun;
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(-0.5f, 0.2f, -1.0f));
  sun.intensity = Rgb(1.0f, 1.0f, 2.0f);
  scene.lights.push_back(sun);
  const dvec3 L_sun = -glm::normalize(dvec3(-0.5, 0.2, -1.0));
  for (Shading shading : all_models) {
    expect_formula(render(scene, shading, only(false, true, true)), shading, [&](const dvec3& P) {
      const Toward t = toward(P, dvec3(at));
      return reflected(point_IL(scene.lights[0].intensity, t.d), up_normal, t.L, P,
                       scene.materials[0], true, true) +
             reflected(rgb(sun.intensity) / pi, up_normal, L_sun, P, scene.materials[0], true,
                       true);
    });
  }
}

TEST(LocalFormula, DisabledLightsAreSkipped) {
  Scene scene = quad_scene(grey_material());
  const glm::vec3 at(0.3f, -0.2f, 1.2f);
  scene.lights.push_back(point_light(at, Rgb(3.0f, 2.0f, 1.0f)));
  Light off = point_light({-0.5f, 0.5f, 0.5f}, Rgb(100.0f));
  off.enabled = false;
  scene.lights.push_back(off);
  expect_formula(render(scene, Shading::phong, only(false, true, false)), Shading::phong,
                 [&](const dvec3& P) {
                   const Toward t = toward(P, dvec3(at));
                   return reflected(point_IL(scene.lights[0].intensity, t.d), up_normal, t.L, P,
                                    scene.materials[0], true, false);
                 });
}

TEST(LocalFormula, LightBehindTheSurfaceGivesNothing) {
  Scene scene = quad_scene(grey_material());
  scene.lights.push_back(point_light({0.0f, 0.0f, -0.5f}, Rgb(10.0f)));  // under the quad
  for (Shading shading : all_models)
    expect_formula(render(scene, shading, only(false, true, true)), shading,
                   [](const dvec3&) { return dvec3(0.0); });
}

// ---- Two-sided lighting -----------------------------------------------------------------------
TEST(LocalFormula, BackFacesAreLitLikeFrontFaces) {
  // Winding clockwise from the camera and normals pointing away: the viewer sees the back of
  // every face, so the normal is flipped and the picture is the front's.
  Scene scene = quad_scene(grey_material(), /*flipped=*/true);
  const glm::vec3 at(0.3f, -0.2f, 1.2f);
  scene.lights.push_back(point_light(at, Rgb(3.0f, 2.0f, 1.0f)));
  for (Shading shading : all_models) {
    expect_formula(render(scene, shading, only(false, true, true)), shading, [&](const dvec3& P) {
      const Toward t = toward(P, dvec3(at));
      return reflected(point_IL(scene.lights[0].intensity, t.d), up_normal, t.L, P,
                       scene.materials[0], true, true);
    });
  }
}

// ---- Texture ------------------------------------------------------------------------------------
TEST(LocalFormula, TextureModulatesKd) {
  Material material = grey_material();
  material.kd_texture = 0;
  Scene scene = quad_scene(material);
  // 4x2 texels: the left half (u < 0.5) one colour, the right half another. Linear texels.
  const Rgb left(0.9f, 0.5f, 0.1f), right(0.2f, 0.4f, 0.8f);
  Texture texture;
  texture.name = "halves";
  texture.width = 4;
  texture.height = 2;
  texture.texels = {left, left, right, right, left, left, right, right};
  scene.textures.push_back(texture);
  const glm::vec3 at(0.1f, 0.2f, 1.0f);
  scene.lights.push_back(point_light(at, Rgb(3.0f)));

  const auto lambert = [&](const dvec3& P, const dvec3& factor) {
    const Toward t = toward(P, dvec3(at));
    return reflected(point_IL(scene.lights[0].intensity, t.d), up_normal, t.L, P, material, true,
                     false) * factor;
  };
  // Bilinear filtering between texel centres of one half gives that half's colour exactly:
  // u in [1/8, 3/8] is left, [5/8, 7/8] right; the pixels there (x in 14..33 and 62..81).
  for (Shading shading : {Shading::phong, Shading::gouraud, Shading::flat}) {
    const Image image = render(scene, shading, only(false, true, false));
    int checked = 0;
    for (const Sample& s : samples(shading)) {
      const double u = (s.P.x + 1.0) / 2.0;
      // flat samples the texture at the triangle's centroid, which is the pixel's point here
      const bool in_left = u > 0.14 && u < 0.36, in_right = u > 0.64 && u < 0.86;
      if (!in_left && !in_right) continue;
      const dvec3 want = lambert(s.P, rgb(in_left ? left : right));
      const Rgb got = image.at(s.x, s.y);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 0.01 * want[c] + 1e-6);
      ++checked;
    }
    EXPECT_GT(checked, 10) << to_string(shading);
  }

  // With textures switched off, kd alone.
  LocalOptions plain = only(false, true, false);
  plain.terms.textures = false;
  expect_formula(render(scene, Shading::phong, plain), Shading::phong,
                 [&](const dvec3& P) { return lambert(P, dvec3(1.0)); });
}

// ---- Emissive surfaces --------------------------------------------------------------------------
// One emissive triangle outside the view, at `centroid`, facing `facing`, of circumradius r.
Mesh emitter_triangle(const glm::vec3& centroid, const glm::vec3& facing, float r) {
  const glm::vec3 n = glm::normalize(facing);
  const glm::vec3 t1 = glm::normalize(glm::cross(n, glm::vec3(0, 0, 1)));  // n is never +-Z here
  const glm::vec3 t2 = glm::cross(n, t1);  // (t1, t2, n) right-handed: counter-clockwise about n
  Mesh mesh;
  mesh.name = "emitter";
  for (int k = 0; k < 3; ++k) {
    const float phi = float(2.0 * pi * k / 3.0);
    mesh.positions.push_back(centroid + r * (std::cos(phi) * t1 + std::sin(phi) * t2));
    mesh.normals.push_back(n);
  }
  mesh.indices = {0, 1, 2};
  mesh.material = 1;
  return mesh;
}

TEST(LocalFormula, EmissiveTriangleLightsAsPointLightAtItsCentroid) {
  Scene scene = quad_scene(grey_material());
  Material lamp;
  lamp.name = "lamp";
  lamp.kd = Rgb(0.0f);
  lamp.emission = Rgb(40.0f, 30.0f, 20.0f);
  scene.materials.push_back(lamp);
  // At x = 1.6, z = 0.9 it is outside the view (which covers |x| < 0.55 at that height).
  const glm::vec3 centroid(1.6f, 0.1f, 0.9f), facing(-1.0f, 0.0f, -1.0f);
  scene.meshes.push_back(emitter_triangle(centroid, facing, 0.1f));
  scene.find_area_lights();
  ASSERT_EQ(scene.area_lights.size(), 1u);
  const double area = 3.0 * std::sqrt(3.0) / 4.0 * 0.1 * 0.1;  // equilateral, circumradius 0.1
  ASSERT_NEAR(scene.area_lights[0].area, area, 1e-6);

  const dvec3 n = glm::normalize(dvec3(facing));
  for (Shading shading : all_models) {
    expect_formula(render(scene, shading, only(false, true, false)), shading, [&](const dvec3& P) {
      const Toward t = toward(P, dvec3(centroid));
      const double cos_e = std::max(glm::dot(n, -t.L), 0.0);
      const dvec3 intensity = rgb(lamp.emission) * area * cos_e;  // Le * A * cos(theta_e)
      return reflected(intensity / (pi * t.d * t.d), up_normal, t.L, P, scene.materials[0], true,
                       false);
    });
  }

  // Turned away from the quad, the emitter lights nothing (zero behind it).
  scene.meshes[1] = emitter_triangle(centroid, {1.0f, 0.0f, 1.0f}, 0.1f);
  scene.find_area_lights();
  expect_formula(render(scene, Shading::phong, only(false, true, true)), Shading::phong,
                 [](const dvec3&) { return dvec3(0.0); });
}

TEST(LocalFormula, EmissiveSurfaceShowsLe) {
  Material glow;
  glow.name = "glow";
  glow.kd = Rgb(0.0f);
  glow.emission = Rgb(0.7f, 0.8f, 0.9f);
  Scene scene = quad_scene(glow);
  scene.find_area_lights();  // ~2500 triangles: more than the shaders take, merged with a warning
  for (Shading shading : all_models)
    expect_formula(render(scene, shading, LocalOptions{}), shading,
                   [&](const dvec3&) { return rgb(glow.emission); });

  LocalOptions off;
  off.terms.emission = false;
  expect_formula(render(scene, Shading::phong, off), Shading::phong,
                 [](const dvec3&) { return dvec3(0.0); });

  LocalRenderer renderer(scene);
  ASSERT_EQ(renderer.warnings().size(), 1u);
  EXPECT_NE(renderer.warnings()[0].find("merged"), std::string::npos) << renderer.warnings()[0];

  // An emitter emits from its front (counter-clockwise) side only, like its area light.
  const Scene back = quad_scene(glow, /*flipped=*/true);
  expect_formula(render(back, Shading::phong, LocalOptions{}), Shading::phong,
                 [](const dvec3&) { return dvec3(0.0); });
}

TEST(LocalFormula, ManyAreaLightsKeepTheirTotalPower) {
  // 200 small coplanar emitters far above the quad merge into 64 lights; seen from far away
  // the merged lights must give (almost) the same irradiance as the unmerged sum.
  Scene scene = quad_scene(grey_material());
  Material lamp;
  lamp.kd = Rgb(0.0f);
  lamp.emission = Rgb(5.0f);
  scene.materials.push_back(lamp);
  Mesh panel;
  panel.material = 1;
  const int n = 10;  // 10 x 10 cells -> 200 triangles, facing down, around (0, 0, 6)
  const float h = 0.02f;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      panel.positions.emplace_back(float(i - n / 2) * h, float(j - n / 2) * h, 6.0f);
      panel.normals.emplace_back(0.0f, 0.0f, -1.0f);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1) + 1,
                     d = a + uint32_t(n + 1);
      for (uint32_t v : {a, c, b, a, d, c}) panel.indices.push_back(v);  // facing -Z, down
    }
  scene.meshes.push_back(panel);
  scene.find_area_lights();
  ASSERT_EQ(scene.area_lights.size(), 200u);
  ASSERT_LT(scene.area_lights[0].normal.z, 0.0f);

  LocalRenderer renderer(scene);
  const Image image = renderer.render(scene.cameras[0], size, size, only(false, true, false));
  EXPECT_EQ(renderer.warnings().size(), 1u);
  // The exact sum over the 200 emitters, each a point light at its centroid.
  expect_formula(image, Shading::phong, [&](const dvec3& P) {
    dvec3 sum(0.0);
    for (const AreaLight& a : scene.area_lights) {
      const Toward t = toward(P, dvec3(a.centroid));
      const double cos_e = std::max(glm::dot(dvec3(a.normal), -t.L), 0.0);
      sum += reflected(rgb(a.radiance) * double(a.area) * cos_e / (pi * t.d * t.d), up_normal,
                       t.L, P, scene.materials[0], true, false);
    }
    return sum;
  });
}

// ---- Scaffolding checks -----------------------------------------------------------------------
TEST(LocalGl, ShaderErrorsNameTheFile) {
  try {
    gl::Program program({"no_such_stage.frag"}, {"lighting.glsl"});
    FAIL() << "a missing shader file must throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind, ErrorKind::gl);
    EXPECT_NE(std::string(e.what()).find("no_such_stage.frag"), std::string::npos) << e.what();
  }
}

TEST(LocalGl, NoDisplayMeansNoWindow) {
  if (std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY"))
    GTEST_SKIP() << "a display is set; this checks the headless case";
  EXPECT_FALSE(gl::WindowContext::display_available());
  try {
    gl::WindowContext window(64, 64, "test");
    FAIL() << "a window without a display must throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind, ErrorKind::gl);
  }
}

TEST(LocalFormula, ShadingNames) {
  EXPECT_STREQ(to_string(Shading::flat), "flat");
  EXPECT_STREQ(to_string(Shading::gouraud), "gouraud");
  EXPECT_STREQ(to_string(Shading::phong), "phong");
}

}  // namespace
}  // namespace luz
