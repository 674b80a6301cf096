#pragma once
// The difference view's switch and its latest figures (difference_window.h), in the ViewerState
// so that the panel, the script and the tests read the same numbers.
#include <string>

#include "core/color.h"

namespace luz::app {

// One comparison of the picture shown against the path tracer's reference of the same view:
// image_compare.h's figures, which `luz compare A.exr B.exr` prints for the same two pictures.
struct DifferenceFigures {
  std::string model;               // the model compared
  int width = 0, height = 0;
  Rgb mean_error{0.0f};            // A - B per channel
  Rgb mean_absolute_error{0.0f};
  double rel_rmse = 0.0;
  double mean_relative_error = 0.0;  // over the lit pixels
  int lit_pixels = 0;
  float range = 1.0f;              // the heat map saturates at +-range (relative)
  int reference_spp = 0;
  double reference_noise = 0.0;    // the reference's own relative standard error
};

struct DifferenceState {
  bool on = false;         // the panel's checkbox, `difference on|off`
  bool valid = false;      // figures holds this frame's comparison (the reference has a pass)
  DifferenceFigures figures;
  std::string why;         // what shows instead when there is no comparison
  // Kept by the view each frame: the reference is still refining (the viewer keeps drawing),
  // the script waits for it (`wait-path` with the difference on), the reference runs for it.
  bool refining = false;
  bool waiting = false;
  bool running = false;
};

}  // namespace luz::app
