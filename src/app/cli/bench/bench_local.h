#pragma once
// `luz bench local`: milliseconds per frame of the local models (flat, Gouraud, Phong), plain and
// with each of slide 19's effects, next to the limit of the same GL: the same triangles drawn
// with a trivial shader into the same framebuffer, measured in the same run. Timings, never
// pass/fail.
#include <string>
#include <vector>

namespace CLI { class App; }

namespace luz::app {

struct LocalBenchSettings {
  int width = 1280;
  int height = 720;
  int frames = 10;  // timed frames per row, after two untimed ones (first uploads, maps)
  std::vector<std::string> scenes{"cornell_box", "cornell_spheres", "local_effects",
                                  "phong_spheres", "whitted"};  // shipped names or paths
  std::vector<std::string> shadings{"flat", "gouraud", "phong"};
  std::vector<std::string> effects{"none", "fog", "shadows", "transparency", "reflection", "all"};
};

void add_local_bench_flags(CLI::App& bench, LocalBenchSettings& settings);
int run_bench_local(const LocalBenchSettings& settings);

}  // namespace luz::app
