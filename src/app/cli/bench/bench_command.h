#pragma once
// `luz bench WHAT`: timings, never pass/fail. One function per benchmark, each in its own file
// (bench_command.cpp for the tracer, bench_radiosity.cpp); this header gathers their settings.
#include <string>
#include <vector>

#include "radiosity/radiosity_options.h"
#include "raytracing/whitted_options.h"

namespace CLI { class App; }

namespace luz::app {

// `luz bench whitted`: the tracer's time on shipped scenes, its rays per second of each kind, and
// the same rays traced bare through Embree in the same run and the same calls (the limit), as a
// ratio.
struct WhittedBenchSettings {
  int width = 1920;
  int height = 1080;
  int depth = 5;
  int spp = 1;
  int repeats = 3;  // each figure is the best of this many runs (and their median)
  rt::RendererKind renderer = rt::WhittedOptions{}.renderer;  // wavefront or recursive
  std::vector<std::string> scenes{"whitted", "cornell_box"};  // shipped names or paths
};

void add_bench_flags(CLI::App& bench, WhittedBenchSettings& settings);
int run_bench_whitted(const WhittedBenchSettings& settings);

// `luz bench radiosity`: shots per second and time to converge at several patch counts.
struct RadiosityBenchSettings {
  std::string scene;                                     // empty: the Cornell box that ships
  std::vector<int> patches = {1000, 4000, 16000, 64000}; // target patch counts
  int hemicube_res = RadiosityOptions{}.hemicube_res;
  HemicubePasses hemicube_passes = RadiosityOptions{}.hemicube_passes;
  HemicubeSums hemicube_sums = RadiosityOptions{}.hemicube_sums;
  double seconds = 30.0;                                 // time cap per patch count
  float converge = RadiosityOptions{}.converge;          // "converged": unshot below this
  // With a reference picture (linear EXR of the scene's first camera, e.g. a converged Mitsuba
  // render): instead of the table above, the time-to-error curve of each way of solving.
  std::string reference;
  // Which ways of solving the curve compares (names of kRadiosityWays); empty: all.
  std::vector<std::string> ways;
};

// The ways of solving `luz bench radiosity --reference` compares, by the names --ways takes.
inline constexpr const char* kRadiosityWays[] = {"uniform", "hemicube", "analytic", "overshoot",
                                                 "rays", "rays-ambient", "adaptive"};

// Prints a Markdown table to stdout; returns the exit code.
int run_radiosity_bench(const RadiosityBenchSettings& settings);

}  // namespace luz::app
