#pragma once
// `luz bench WHAT`: timings (never pass/fail). One function per benchmark, in its own file
// (bench_radiosity.cpp, ...); this header only gathers their settings.
#include <string>
#include <vector>

#include "radiosity/radiosity_options.h"

namespace luz::app {

struct RadiosityBenchSettings {
  std::string scene;                                     // empty: the Cornell box that ships
  std::vector<int> patches = {1000, 4000, 16000, 64000}; // target patch counts
  int hemicube_res = RadiosityOptions{}.hemicube_res;
  double seconds = 30.0;                                 // time cap per patch count
  float converge = RadiosityOptions{}.converge;          // "converged": unshot below this
};

// Prints a Markdown table to stdout; returns the exit code.
int run_radiosity_bench(const RadiosityBenchSettings& settings);

}  // namespace luz::app
