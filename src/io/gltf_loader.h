#pragma once
// glTF 2.0 (.gltf / .glb) -> Scene, following SCENES.md rule by rule.
#include <filesystem>
#include <string>
#include <vector>

#include "core/scene.h"

namespace luz::io {

struct LoadedScene {
  Scene scene;
  std::vector<std::string> warnings;  // one line each, naming the file: "a.gltf: mesh 2 ..."
};

// Throws luz::Error (core/error.h) with a one-line message naming the file and the problem.
LoadedScene load_gltf(const std::filesystem::path& path);

}  // namespace luz::io
