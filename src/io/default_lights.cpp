#include "io/default_lights.h"

#include <algorithm>
#include <numbers>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "core/i18n.h"

namespace luz::io {

bool has_no_lights(const Scene& scene) { return scene.lights.empty() && scene.area_lights.empty(); }

namespace {

// Is `p` inside the box (an interior: the default camera stands in the room it looks at)?
bool inside(const Bounds& bounds, const glm::vec3& p) {
  return glm::all(glm::greaterThan(p, bounds.min)) && glm::all(glm::lessThan(p, bounds.max));
}

}  // namespace

void add_default_lights(Scene& scene) {
  const Bounds bounds = scene.bounds();
  const glm::vec3 centre = bounds.centre();
  const float radius = std::max(0.5f * glm::length(bounds.extent()), 1e-3f);
  const Camera camera = scene.cameras.empty() ? Camera::framing(bounds) : scene.cameras.front();
  const glm::vec3 right = glm::normalize(glm::vec3(camera.to_world[0]));
  const glm::vec3 up = glm::normalize(glm::vec3(camera.to_world[1]));
  const glm::vec3 back = glm::normalize(glm::vec3(camera.to_world[2]));

  Light key;
  key.name = i18n::tr("default key light");
  key.type = LightType::point;
  Light fill = key;
  fill.name = i18n::tr("default fill light");
  const glm::vec3 eye = camera.position();
  if (inside(bounds, eye)) {
    // An interior: lights outside would be behind its walls. The key hangs halfway from the
    // camera to the centre, a quarter of the room's height above that, kept a tenth of the room
    // away from its walls; the fill is at the camera. A white surface R (half the box's diagonal)
    // from the key, facing it, shows radiance 1.
    const glm::vec3 margin = 0.1f * bounds.extent();
    const glm::vec3 raised = 0.5f * (eye + centre) + 0.25f * glm::dot(bounds.extent(), glm::abs(up)) * up;
    key.position = glm::clamp(raised, bounds.min + margin, bounds.max - margin);
    key.intensity = Rgb(std::numbers::pi_v<float> * radius * radius);
    fill.position = eye;
  } else {
    const float distance = 2.0f * radius;
    key.position = centre + distance * glm::normalize(back + up + right);
    key.intensity = Rgb(std::numbers::pi_v<float> * distance * distance);
    fill.position = centre + distance * glm::normalize(back - right);
  }
  fill.intensity = 0.25f * key.intensity;

  scene.lights.push_back(key);
  scene.lights.push_back(fill);
  scene.default_lights = true;
}

}  // namespace luz::io
