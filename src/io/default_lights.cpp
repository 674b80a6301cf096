#include "io/default_lights.h"

#include <algorithm>
#include <numbers>

#include <glm/geometric.hpp>

namespace luz::io {

bool has_no_lights(const Scene& scene) { return scene.lights.empty() && scene.area_lights.empty(); }

void add_default_lights(Scene& scene) {
  const Bounds bounds = scene.bounds();
  const glm::vec3 centre = bounds.centre();
  const float radius = std::max(0.5f * glm::length(bounds.extent()), 1e-3f);
  const Camera camera = scene.cameras.empty() ? Camera::framing(bounds) : scene.cameras.front();
  const glm::vec3 right = glm::normalize(glm::vec3(camera.to_world[0]));
  const glm::vec3 up = glm::normalize(glm::vec3(camera.to_world[1]));
  const glm::vec3 back = glm::normalize(glm::vec3(camera.to_world[2]));
  const float distance = 2.0f * radius;
  const float key_intensity = std::numbers::pi_v<float> * distance * distance;

  Light key;
  key.name = "default key light";
  key.type = LightType::point;
  key.position = centre + distance * glm::normalize(back + up + right);
  key.intensity = Rgb(key_intensity);

  Light fill = key;
  fill.name = "default fill light";
  fill.position = centre + distance * glm::normalize(back - right);
  fill.intensity = Rgb(0.25f * key_intensity);

  scene.lights.push_back(key);
  scene.lights.push_back(fill);
  scene.default_lights = true;
}

}  // namespace luz::io
