#pragma once
// Small scenes with known answers for the radiosity tests, and Howell's closed forms
// (J. R. Howell, "A Catalog of Radiation Heat Transfer Configuration Factors").
#include <cmath>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "core/scene.h"

namespace luz::test {

inline constexpr double pi = std::numbers::pi;

// ---- Scenes built here ------------------------------------------------------------------------
// A quad as one mesh of two triangles, counter-clockwise seen from its front.
inline int add_quad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, int material,
             const std::string& name) {
  Mesh mesh;
  mesh.name = name;
  mesh.positions = {a, b, c, d};
  const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
  mesh.normals = {n, n, n, n};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = material;
  scene.meshes.push_back(mesh);
  return int(scene.meshes.size() - 1);
}

inline int add_material(Scene& scene, float rho, float emitted_radiance = 0.0f) {
  Material m;
  m.kd = Rgb(rho);
  m.emission = Rgb(emitted_radiance);
  scene.materials.push_back(m);
  return int(scene.materials.size() - 1);
}

// The unit cube [0,1]^3 with all six faces facing in. Face order: floor, ceiling, x=0, x=1,
// z=0, z=1.
inline void add_closed_box(Scene& scene, const int materials[6]) {
  using v = glm::vec3;
  add_quad(scene, v(0, 0, 0), v(0, 0, 1), v(1, 0, 1), v(1, 0, 0), materials[0], "floor");
  add_quad(scene, v(0, 1, 0), v(1, 1, 0), v(1, 1, 1), v(0, 1, 1), materials[1], "ceiling");
  add_quad(scene, v(0, 0, 0), v(0, 1, 0), v(0, 1, 1), v(0, 0, 1), materials[2], "x0");
  add_quad(scene, v(1, 0, 0), v(1, 0, 1), v(1, 1, 1), v(1, 1, 0), materials[3], "x1");
  add_quad(scene, v(0, 0, 0), v(1, 0, 0), v(1, 1, 0), v(0, 1, 0), materials[4], "z0");
  add_quad(scene, v(0, 0, 1), v(0, 1, 1), v(1, 1, 1), v(1, 0, 1), materials[5], "z1");
}


// C-11: identical, parallel, directly opposed rectangles a x b at distance c; X = a/c, Y = b/c.
inline double howell_c11(double a, double b, double c) {
  const double X = a / c, Y = b / c;
  return 2.0 / (pi * X * Y) *
         (std::log(std::sqrt((1 + X * X) * (1 + Y * Y) / (1 + X * X + Y * Y))) +
          X * std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y)) +
          Y * std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) - X * std::atan(X) -
          Y * std::atan(Y));
}

// C-14: rectangles with a common edge of length l and an included angle of 90 degrees, from
// the one of width w to the one of height h; H = h/l, W = w/l.
inline double howell_c14(double h, double w, double l) {
  const double H = h / l, W = w / l, H2 = H * H, W2 = W * W, S = H2 + W2;
  const double log_term =
      std::log((1 + W2) * (1 + H2) / (1 + S)) +
      W2 * std::log(W2 * (1 + S) / ((1 + W2) * S)) + H2 * std::log(H2 * (1 + S) / ((1 + H2) * S));
  return 1.0 / (pi * W) *
         (W * std::atan(1 / W) + H * std::atan(1 / H) - std::sqrt(S) * std::atan(1 / std::sqrt(S)) +
          0.25 * log_term);
}

// B-13: a plane element to a parallel disc of radius r at distance h, on its axis.
inline double howell_b13(double r, double h) { return r * r / (h * h + r * r); }

}  // namespace luz::test
