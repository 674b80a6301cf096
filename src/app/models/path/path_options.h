#pragma once
// The path tracer's options table (option_row.h), over PathSettings: its --spp, --depth and
// --seed, `path spp N` in a script, its panel's sliders, and the file `luz render` writes beside
// the picture (--error-out). --spp and --depth are the Whitted
// tracer's flags too (`luz render` gives one flag to the rows of both tables); the defaults are
// the path tracer's own (rt::PathOptions: 16 samples, depth 16), except in the viewer, which
// refines to a reference the difference view can trust (kViewerTarget).
#include <string>

#include "app/common/option_row.h"
#include "raytracing/path_options.h"

namespace luz::app {

// The tracer's options, and what the command line writes beside the picture.
struct PathSettings : rt::PathOptions {
  std::string error_out;  // --error-out FILE.exr: the standard error of the mean, per pixel
};

inline constexpr int kViewerTarget = 256;  // samples per pixel the window refines to

const OptionTable& path_table();

}  // namespace luz::app
