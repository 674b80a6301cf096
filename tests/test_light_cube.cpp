// A point light as a radiosity source (radiosity/point_source.h) where the answer is known
// exactly: at the centre of a closed cube each of the six walls subtends 4 pi / 6 sr, so each
// receives the sixth of the light's flux, I 4 pi / 6, and the cube of item buffers around the
// light sees one wall per face. The pixel sums are the midpoint rule for the integral of
// dA / r^3 over a face, whose error falls as 1/res^2 (1.5e-5 relative at res 128, worked out
// for this test); the bound is 1/res^2.
#include <cmath>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/scene.h"
#include "radiosity/item_buffer.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/point_source.h"

namespace luz {
namespace {

void add_wall(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, const std::string& name) {
  Mesh mesh;
  mesh.name = name;
  mesh.positions = {a, b, c, d};
  const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
  mesh.normals = {n, n, n, n};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = 0;
  scene.meshes.push_back(mesh);
}

// The unit cube [0, 1]^3, every wall facing in.
Scene closed_cube() {
  Scene scene;
  Material grey;
  grey.kd = Rgb(0.5f);
  scene.materials.push_back(grey);
  using v = glm::vec3;
  add_wall(scene, v(0, 0, 0), v(0, 0, 1), v(1, 0, 1), v(1, 0, 0), "y0");
  add_wall(scene, v(0, 1, 0), v(1, 1, 0), v(1, 1, 1), v(0, 1, 1), "y1");
  add_wall(scene, v(0, 0, 0), v(0, 1, 0), v(0, 1, 1), v(0, 0, 1), "x0");
  add_wall(scene, v(1, 0, 0), v(1, 0, 1), v(1, 1, 1), v(1, 1, 0), "x1");
  add_wall(scene, v(0, 0, 0), v(1, 0, 0), v(1, 1, 0), v(0, 1, 0), "z0");
  add_wall(scene, v(0, 0, 1), v(0, 1, 1), v(1, 1, 1), v(1, 0, 1), "z1");
  return scene;
}

TEST(LightCube, EachWallOfACubeSubtendsASixthOfTheSphereFromItsCentre) {
  const Scene scene = closed_cube();
  PatchMesh mesh = PatchMesh::build(scene, 0.25f);
  const PatchItems items(mesh);
  const int res = 128;
  PointSource cube(mesh, items, res);
  Light light;
  light.position = glm::vec3(0.5f);
  light.intensity = Rgb(1.0f);
  double wall[6] = {};
  for (const FormFactor& f : cube.solid_angles(light)) wall[mesh.patches[f.patch].mesh] += double(f.value);
  const double sixth = 4.0 * std::numbers::pi / 6.0, tolerance = 1.0 / (res * res);
  for (int w = 0; w < 6; ++w)
    EXPECT_NEAR(wall[w], sixth, tolerance * sixth) << scene.meshes[size_t(w)].name;
  EXPECT_NEAR(cube.emitted_solid_angle(), 4.0 * std::numbers::pi, tolerance * 4.0 * std::numbers::pi);
}

}  // namespace
}  // namespace luz
