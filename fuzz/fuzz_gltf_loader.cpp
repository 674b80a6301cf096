// libFuzzer target: the glTF loader on arbitrary bytes, as a .gltf or .glb file (the loader
// tells them apart by the GLB magic). The file lies in a scratch folder beside copies of the
// shipped scenes' .bin buffers, so that mutations of the shipped scenes (the corpus) still
// reach the accessors. A luz::Error is the expected answer to bad input; anything else that
// escapes, and every sanitizer report, is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "core/error.h"
#include "io/gltf_loader.h"

namespace fs = std::filesystem;

namespace {

fs::path scratch_scene() {
  static const fs::path scene = [] {
    const fs::path folder = fs::temp_directory_path() / ("luz-fuzz-gltf-" + std::to_string(getpid()));
    fs::create_directories(folder);
    for (const fs::directory_entry& entry : fs::directory_iterator(LUZ_SCENE_DIR))
      if (entry.path().extension() == ".bin")
        fs::copy_file(entry.path(), folder / entry.path().filename(), fs::copy_options::overwrite_existing);
    return folder / "fuzz.gltf";
  }();
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const fs::path scene = scratch_scene();
  {
    std::ofstream out(scene, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  try {
    luz::io::load_gltf(scene);
  } catch (const luz::Error&) {
  }
  return 0;
}
