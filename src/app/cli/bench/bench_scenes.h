#pragma once
// The scenes `luz bench whitted` and `luz bench local` run on (--scenes): a shipped scene's name
// (cornell_box) or a glTF file's path. All of them are loaded before a bench prints anything, so
// that a bad one ends it with one message and no half-printed table.
#include <string>
#include <vector>

#include "io/gltf_loader.h"

namespace luz::app {

struct BenchScene {
  std::string name;  // as given to --scenes: the table's label
  io::LoadedScene loaded;
};

// Throws luz::Error: kind usage for a name that is no shipped scene (the message lists them),
// the loader's own for a file that cannot be read.
std::vector<BenchScene> load_bench_scenes(const std::vector<std::string>& names);

}  // namespace luz::app
