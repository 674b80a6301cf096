#pragma once
// SCENES.md "Scenes without lights": the lights a scene gets when it brings none.
#include "core/i18n.h"
#include "core/scene.h"

namespace luz::io {

// The message the loader adds to its warnings when it calls add_default_lights (a message id:
// the warning is its translation).
inline constexpr const char* kDefaultLightsNotice = i18n::N_(
    "no lights in the scene: using the default lights (to export lights from Blender, tick \"Punctual "
    "Lights\" under Include in the glTF exporter; it does not export area lights, an emissive plane "
    "is exported)");

// Does the scene have no light at all (no punctual light, no emissive triangle)?
// Needs scene.area_lights filled (Scene::find_area_lights).
bool has_no_lights(const Scene& scene);

// Adds the two default point lights, fixed in the scene. With c the centre of the bounding box,
// R half its diagonal, and right, up, back the default camera's (cameras[0]) +X, +Y, +Z axes:
//   key  at c + 2R * normalize(back + up + right), intensity pi * (2R)^2 (W/sr, white)
//   fill at c + 2R * normalize(back - right),      intensity a quarter of the key's
// A white diffuse surface at c facing the key light then shows radiance exactly 1 from it,
// L = (kd / pi) * I / d^2 = (1 / pi) * pi (2R)^2 / (2R)^2, and none from the fill, whose direction
// is perpendicular to the key's as seen from c. Both shine from the camera's side, so what the
// camera sees is lit, and the key from above right casts shadows the eye can read.
// An interior (the camera inside the bounding box, as in a room exported from Blender) would have
// both behind its walls: there the key is at the midpoint of camera and c, raised a quarter of the
// box's height along up and kept a tenth of the box from its faces, with intensity pi R^2 (radiance
// 1 on a white surface R from it, facing it), and the fill, a quarter of that, at the camera.
void add_default_lights(Scene& scene);

}  // namespace luz::io
