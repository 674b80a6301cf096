#include "app/common/resources.h"

#include <system_error>

namespace luz::app {
namespace fs = std::filesystem;

fs::path scene_dir() {
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    for (const fs::path& candidate : {exe.parent_path() / "scenes", exe.parent_path() / "../share/luz/scenes"})
      if (fs::is_directory(candidate, error)) return candidate;
  }
  return LUZ_SCENE_DIR;
}

fs::path default_scene() { return scene_dir() / "cornell_box.gltf"; }

}  // namespace luz::app
