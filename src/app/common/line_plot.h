#pragma once
// A tiny line plotter into a core::Image, for `luz solvers --png` (no plotting library is in the
// Debian set Luz uses): panels with a log10 y axis and a linear or log10 x axis, grid lines at
// the decades, labels in the TrueType font of label_text.h, a legend of colour swatches. Values
// are radiance, so io::write_image writes the picture at exposure 0.
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/image.h"

namespace luz::app {

struct PlotSeries {
  std::string name;
  Rgb colour{1.0f};
  std::vector<glm::dvec2> points;  // (x, y), both > 0 on log axes (others are skipped)
};

struct PlotPanel {
  std::string title;
  std::string x_label, y_label;
  bool log_x = true;  // y is always log10
  double x_min = 1.0, x_max = 10.0, y_min = 1e-6, y_max = 1.0;
  std::vector<PlotSeries> series;
};

// Each series is drawn as a staircase (a value holds until the next point). Panels side by side,
// each `panel_width` x `height` pixels, a legend of the first panel's series under them. Throws
// luz::Error when the font is missing.
Image plot(const std::vector<PlotPanel>& panels, int panel_width, int height);

}  // namespace luz::app
