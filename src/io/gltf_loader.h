#pragma once
// glTF 2.0 (.gltf / .glb) -> Scene, following SCENES.md rule by rule.
#include <filesystem>
#include <string>
#include <vector>

#include "core/i18n.h"
#include "core/scene.h"

namespace luz::io {

struct LoadedScene {
  Scene scene;
  std::vector<std::string> warnings;  // one line each, naming the file: "a.gltf: mesh 2 ..."
};

// The warning of a scene without a camera (a message id: the warning is its translation): it gets
// Camera::framing's, and the exporter's option that would have brought the file's own.
inline constexpr const char* kNoCameraNotice = i18n::N_(
    "no camera in the scene: framing it from +Z, from above where it is flat (to export the camera "
    "from Blender, tick \"Cameras\" under Include in the glTF exporter)");

// Throws luz::Error (core/error.h) with a one-line message naming the file and the problem.
LoadedScene load_gltf(const std::filesystem::path& path);

}  // namespace luz::io
