#include "app/cli/bench/bench_scenes.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/common/i18n.h"
#include "core/resources.h"
#include "core/error.h"

namespace luz::app {

namespace {

// A name without a slash or a dot is a shipped scene's; anything else a path.
bool names_a_shipped_scene(const std::string& name) {
  return name.find('/') == std::string::npos && name.find('.') == std::string::npos;
}

std::string shipped_scenes() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(scene_dir(), error))
    if (entry.path().extension() == ".gltf") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return fmt::format("{}", fmt::join(names, ", "));
}

}  // namespace

std::vector<BenchScene> load_bench_scenes(const std::vector<std::string>& names) {
  std::vector<BenchScene> scenes;
  for (const std::string& name : names) {
    std::filesystem::path path = name;
    if (names_a_shipped_scene(name)) {
      path = scene_dir() / (name + ".gltf");
      if (!std::filesystem::is_regular_file(path))
        throw Error(ErrorKind::usage, trf("--scenes: no shipped scene \"{}\" (the shipped ones: {})", name,
                                          shipped_scenes()));
    }
    scenes.push_back({name, io::load_gltf(path)});
  }
  return scenes;
}

}  // namespace luz::app
