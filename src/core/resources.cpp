#include "core/resources.h"

#include <system_error>

namespace luz {
namespace fs = std::filesystem;

namespace {

// The installed layout, found once: share/luz seen from the executable's folder (../share/luz
// for GNUInstallDirs' bin and share), when that folder exists.
fs::path find_installed_data_dir() {
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};
  const fs::path data = (exe.parent_path() / LUZ_DATA_FROM_BIN).lexically_normal();
  return fs::is_directory(data, error) ? data : fs::path();
}

// `name` in the installed data folder, else the folder the build was configured with.
fs::path data_folder(const char* name, const char* configured) {
  const fs::path installed = installed_data_dir();
  return installed.empty() ? fs::path(configured) : installed / name;
}

}  // namespace

fs::path installed_data_dir() {
  static const fs::path data = find_installed_data_dir();
  return data;
}

fs::path shader_dir() { return data_folder("shaders", LUZ_SHADER_DIR); }
fs::path scene_dir() { return data_folder("scenes", LUZ_SCENE_DIR); }
fs::path lesson_dir() { return data_folder("lessons", LUZ_LESSON_DIR); }
fs::path locale_dir() { return data_folder("locale", LUZ_LOCALE_DIR); }

fs::path default_scene() { return scene_dir() / "cornell_box.gltf"; }

}  // namespace luz
