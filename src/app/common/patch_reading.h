#pragma once
// One radiosity patch as the solver holds it, read for the inspector (exitances in W/m^2, as
// slide 39 keeps them). Plain data: the radiosity view fills it, the inspector draws it.
#include <cstddef>
#include <string>

#include <glm/vec3.hpp>

#include "core/color.h"

namespace luz::app {

struct PatchReading {
  size_t patch = 0;              // the element clicked (it receives and is drawn)
  size_t shooter = 0;            // the shooting patch it belongs to
  int mesh = -1, triangle = -1;  // its source triangle in the scene
  std::string material;
  glm::vec3 centre{0.0f}, normal{0.0f};
  float area = 0.0f;     // m^2
  Rgb E{0.0f};           // emitted exitance, pi * Le
  Rgb rho{0.0f};         // kd
  Rgb radiosity{0.0f};   // shot so far ("radiosidad")
  Rgb unshot{0.0f};      // still to shoot ("carga emisora")
  Rgb B{0.0f};           // radiosity + unshot: what step 3 displays
  Rgb radiance{0.0f};    // B / pi
  int shots = 0;         // the solver's shots when read
};

}  // namespace luz::app
