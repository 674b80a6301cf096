#pragma once
// Small scenes built in C++ for the tracer's tests: quads and boxes with known answers.
#include <cmath>
#include <string>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include "core/scene.h"

namespace luz::test {

// A quad with corners c, c + a, c + a + b, c + b, counter-clockwise (its front) seen from the
// side a x b points to; flat normals along a x b.
inline Mesh quad(const std::string& name, glm::vec3 c, glm::vec3 a, glm::vec3 b, int material) {
  Mesh mesh;
  mesh.name = name;
  mesh.positions = {c, c + a, c + a + b, c + b};
  const glm::vec3 n = glm::normalize(glm::cross(a, b));
  mesh.normals = {n, n, n, n};
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = material;
  return mesh;
}

// An axis-aligned box [lo, hi], faces wound counter-clockwise seen from outside (glTF's front).
inline Mesh box(const std::string& name, glm::vec3 lo, glm::vec3 hi, int material) {
  Mesh mesh;
  mesh.name = name;
  const glm::vec3 s = hi - lo;
  const auto face = [&](glm::vec3 c, glm::vec3 a, glm::vec3 b) {
    const Mesh q = quad(name, c, a, b, material);
    const uint32_t base = uint32_t(mesh.positions.size());
    for (size_t i = 0; i < 4; ++i) {
      mesh.positions.push_back(q.positions[i]);
      mesh.normals.push_back(q.normals[i]);
      mesh.uvs.push_back(q.uvs[i]);
    }
    for (uint32_t i : q.indices) mesh.indices.push_back(base + i);
  };
  const glm::vec3 X(s.x, 0, 0), Y(0, s.y, 0), Z(0, 0, s.z);
  face(lo, Y, X);                 // z = lo.z, facing -z
  face(lo + Z, X, Y);             // z = hi.z, facing +z
  face(lo, Z, Y);                 // x = lo.x, facing -x
  face(lo + X, Y, Z);             // x = hi.x, facing +x
  face(lo, X, Z);                 // y = lo.y, facing -y
  face(lo + Y, Z, X);             // y = hi.y, facing +y
  mesh.material = material;
  return mesh;
}

// A UV sphere with smooth normals, counter-clockwise outside.
inline Mesh sphere(const std::string& name, glm::vec3 centre, float radius, int material,
                   int rings = 24, int segments = 48) {
  Mesh mesh;
  mesh.name = name;
  const float pi = 3.14159265f;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const float theta = pi * float(i) / float(rings), phi = 2 * pi * float(j) / float(segments);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      mesh.positions.push_back(centre + radius * n);
      mesh.normals.push_back(n);
      mesh.uvs.emplace_back(float(j) / float(segments), float(i) / float(rings));
    }
  const auto at = [&](int i, int j) { return uint32_t(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      // Seen from outside, (i, j) -> (i, j+1) -> (i+1, j) turns counter-clockwise.
      if (i > 0) for (uint32_t v : {at(i, j), at(i, j + 1), at(i + 1, j)}) mesh.indices.push_back(v);
      if (i < rings - 1)
        for (uint32_t v : {at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)}) mesh.indices.push_back(v);
    }
  mesh.material = material;
  return mesh;
}

// A camera at `eye` looking at `target`, +Y up.
inline Camera look_at(glm::vec3 eye, glm::vec3 target, float yfov = 0.6f) {
  Camera camera;
  camera.name = "test";
  camera.to_world = glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
  camera.yfov = yfov;
  camera.znear = 0.01f;
  camera.zfar = 1000.0f;
  return camera;
}

inline Material matte(Rgb kd) {
  Material m;
  m.name = "matte";
  m.kd = kd;
  m.ka = Rgb(0.0f);
  return m;
}

}  // namespace luz::test
