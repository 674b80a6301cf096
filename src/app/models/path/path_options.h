#pragma once
// The path tracer's options table (option_row.h), over rt::PathOptions: its --spp, --depth and
// --seed, `path spp N` in a script, its panel's sliders. --spp and --depth are the Whitted
// tracer's flags too (`luz render` gives one flag to the rows of both tables); the defaults are
// the path tracer's own (rt::PathOptions: 16 samples, depth 16), except in the viewer, which
// refines to a reference the difference view can trust (kViewerTarget).
#include "app/common/option_row.h"
#include "raytracing/path_options.h"

namespace luz::app {

inline constexpr int kViewerTarget = 256;  // samples per pixel the window refines to

const OptionTable& path_table();

}  // namespace luz::app
