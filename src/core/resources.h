#pragma once
// Where luz's own files are: its shaders, the shipped scenes, the lessons and the compiled
// catalogues. One rule for every kind. An installed luz (PREFIX/bin/luz beside
// PREFIX/share/luz/) reads them all from ../share/luz, found from its own executable, so a
// prefix can be moved or unpacked anywhere; any other luz (the build tree's) reads the folders
// the build was configured with: the source tree's shaders, scenes and lessons and the build
// tree's catalogues. No environment variable is needed either way.
#include <filesystem>

namespace luz {

// PREFIX/share/luz of an installed luz; empty for any other.
std::filesystem::path installed_data_dir();

std::filesystem::path shader_dir();  // *.vert, *.geom, *.frag, *.glsl
std::filesystem::path scene_dir();   // the shipped glTF scenes
std::filesystem::path lesson_dir();  // the lessons (sintesis.json)
std::filesystem::path locale_dir();  // LANG/LC_MESSAGES/luz.mo

std::filesystem::path default_scene();  // the Cornell box

}  // namespace luz
