#pragma once
// `luz bench whitted`: the tracer's time on shipped scenes, its rays per second of each kind, and
// the same rays traced bare through Embree in the same run (the limit), as a ratio.
#include <string>
#include <vector>

namespace CLI { class App; }

namespace luz::app {

struct BenchSettings {
  int width = 1920;
  int height = 1080;
  int depth = 5;
  int spp = 1;
  int repeats = 3;  // each figure is the best of this many runs
  std::vector<std::string> scenes{"whitted", "cornell_box"};  // shipped names or paths
};

void add_bench_flags(CLI::App& bench, BenchSettings& settings);
int run_bench_whitted(const BenchSettings& settings);

}  // namespace luz::app
