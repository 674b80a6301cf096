#pragma once
// Where the shipped scenes are: next to the binary (an installed or copied tree), else the
// source tree the build was configured from.
#include <filesystem>

namespace luz::app {

std::filesystem::path scene_dir();
std::filesystem::path default_scene();  // the Cornell box

}  // namespace luz::app
