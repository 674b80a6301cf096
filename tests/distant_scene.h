#pragma once
// A scene seen from far away, as a CAD export frames it: a lit face a metre in front of a dark
// plate, 1.5 km from a camera whose file asks for a near plane of 5 cm (2CylinderEngine's fins
// before its body). With that near plane a 24-bit depth buffer tells depths 1.5 km away apart
// only every few metres (steps of depth^2 / (near 2^24)), and the dark plate shows through.
// The plate is drawn first (the smaller, its far side nearer: the local models draw nearest far
// side first; the mesh order elsewhere), so that where the two depths round to the same value it
// stays (a depth test passes only when strictly nearer); both are turned 30 degrees about +Y, so
// that their depths sweep a hundred metres across the picture instead of rounding one way.
#include <glm/ext/matrix_transform.hpp>

#include "core/scene.h"
#include "radiosity_scenes.h"

namespace luz::test {

inline constexpr int distant_plate = 0, distant_lit_face = 1;  // mesh indices

// Camera 0 looks down -Z from 1.5 km; `zfar` 0 leaves the far plane to the renderer.
inline Scene distant_faces_scene(float zfar) {
  Scene scene;
  scene.path = "distant faces (built in the test)";
  scene.ambient = Rgb(0.0f);  // no lights either: the plate is black, the face its emission
  const int lamp = add_material(scene, 0.0f, 1.0f), dark = add_material(scene, 0.5f);
  const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0, 1, 0));
  const auto at = [&](float x, float y, float z) { return glm::vec3(turn * glm::vec4(x, y, z, 1.0f)); };
  add_quad(scene, at(-150, -150, -1), at(150, -150, -1), at(150, 150, -1), at(-150, 150, -1), dark, "plate");
  add_quad(scene, at(-200, -200, 0), at(200, -200, 0), at(200, 200, 0), at(-200, 200, 0), lamp, "lit face");
  Camera camera;
  camera.to_world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 1500.0f));
  camera.yfov = 0.2f;  // 300 m across at 1.5 km: the lit face (346 m wide, turned) fills a square picture
  camera.znear = 0.05f;
  camera.zfar = zfar;
  scene.cameras.push_back(camera);
  return scene;
}

}  // namespace luz::test
