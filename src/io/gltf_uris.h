#pragma once
// External URIs of a glTF file as paths in the scene's folder (SCENES.md "Format"). Private to
// src/io, like gltf_internal.h, but free of tinygltf so the checks before parsing can use it.
//
// Converters write Windows paths (`.\tex.jpg`, `..\maps\tex.jpg`, `D:\work\tex.jpg`): a
// backslash is a folder separator here. A URI may not leave the scene's folder; an image whose URI
// does is looked for by its file name beside the scene instead.
#include <filesystem>
#include <string>

namespace luz::io::gltf {

bool is_data_uri(const std::string& uri);

// The URI percent-decoded (as tinygltf opens it) with every backslash turned into '/'.
std::string uri_path(const std::string& uri);

// Is `path` (absolute) inside `folder` (canonical) once symbolic links are resolved?
bool inside(const std::filesystem::path& folder, const std::filesystem::path& path);

// Why `uri` (not a data URI) is not a file in `folder`, as an N_() message id ("is absolute",
// "goes up with ..", ...), or nullptr when it resolves inside the folder.
const char* why_outside(const std::filesystem::path& folder, const std::string& uri);

// The file an image URI that leaves the folder stands for: its last component beside the scene.
std::filesystem::path beside_the_scene(const std::filesystem::path& folder, const std::string& uri);

}  // namespace luz::io::gltf
