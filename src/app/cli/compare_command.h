#pragma once
// `luz compare A.exr B.exr [--heatmap OUT.png [--range P]] [--mask-emitters]`: how far picture A is from
// reference B (core/image_compare.h has the figures and their definitions).
#include <string>

namespace CLI { class App; }

namespace luz::app {

struct CompareSettings {
  std::string a, b;      // B is the reference
  std::string heatmap;   // signed relative difference with a legend, PNG
  // The heat map's scale in percent, the same for every comparison so that handouts compare
  // (auto: fitted to this one, heatmap_range).
  std::string range = "50";
  bool mask_emitters = false;
  bool quiet = false;
};

void add_compare_flags(CLI::App& compare, CompareSettings& settings);

// Prints the figures; returns the exit code (1: a file is missing, not an image, or the two
// sizes differ; the message names the file).
int run_compare(const CompareSettings& settings);

}  // namespace luz::app
