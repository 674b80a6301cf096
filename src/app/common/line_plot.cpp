// The line plotter of line_plot.h. Sections: [drawing] [plot]
#include "app/common/line_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "app/common/label_text.h"

namespace luz::app {

namespace {

void put(Image& image, int x, int y, const Rgb& colour) {
  if (x >= 0 && y >= 0 && x < image.width && y < image.height) image.at(x, y) = colour;
}

// ---- [drawing] ---------------------------------------------------------------------------------
// Bresenham's line, two pixels thick.
void line(Image& image, glm::ivec2 a, glm::ivec2 b, const Rgb& colour) {
  const int dx = std::abs(b.x - a.x), dy = -std::abs(b.y - a.y);
  const int sx = a.x < b.x ? 1 : -1, sy = a.y < b.y ? 1 : -1;
  int error = dx + dy;
  for (;;) {
    put(image, a.x, a.y, colour);
    put(image, a.x + 1, a.y, colour);
    put(image, a.x, a.y + 1, colour);
    if (a == b) break;
    const int e2 = 2 * error;
    if (e2 >= dy) { error += dy; a.x += sx; }
    if (e2 <= dx) { error += dx; a.y += sy; }
  }
}

void fill(Image& image, int x0, int y0, int x1, int y1, const Rgb& colour) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) put(image, x, y, colour);
}

const Rgb kBackground(1.0f), kInk(0.0f), kGrid(0.8f);
constexpr float kTextPixels = 13.0f, kTitlePixels = 19.0f;

// The plot's text, in the labels' TrueType font (label_text.h): accents and signs as written.
struct Writer {
  Image& image;
  LabelFont font;
  int width(const std::string& text, float pixels = kTextPixels) const { return font.measure(text, pixels).width; }
  // Left-aligned with its top at y.
  void at(int x, int y, const std::string& text, float pixels = kTextPixels) const {
    font.draw(image, x, y, text, pixels, kInk);
  }
};

// 10 to the power e as a plot labels its decades: "1", "10", "10⁻³".
std::string decade_label(int e) {
  if (e == 0) return "1";
  if (e == 1) return "10";
  static const char* const superscript[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string label = e < 0 ? "10⁻" : "10";
  for (const char digit : std::to_string(std::abs(e))) label += superscript[digit - '0'];
  return label;
}

}  // namespace

// ---- [plot] ------------------------------------------------------------------------------------
Image plot(const std::vector<PlotPanel>& panels, int panel_width, int height) {
  constexpr int legend_height = 40;
  Image image(panel_width * int(panels.size()), height + legend_height, kBackground);
  const Writer text{image, LabelFont()};
  for (size_t k = 0; k < panels.size(); ++k) {
    const PlotPanel& panel = panels[k];
    // The frame: margins for the tick labels left and below, the title above.
    const int left = int(k) * panel_width + 60, right = int(k + 1) * panel_width - 20;
    const int top = 30, bottom = height - 45;
    const auto x_of = [&](double x) {
      const double t = panel.log_x ? (std::log10(x) - std::log10(panel.x_min)) /
                                         (std::log10(panel.x_max) - std::log10(panel.x_min))
                                   : (x - panel.x_min) / (panel.x_max - panel.x_min);
      return left + int(std::lround(t * (right - left)));
    };
    const auto y_of = [&](double y) {
      const double t = (std::log10(y) - std::log10(panel.y_min)) /
                       (std::log10(panel.y_max) - std::log10(panel.y_min));
      return bottom - int(std::lround(t * (bottom - top)));
    };
    // Grid and labels at the decades of y, and of x on a log axis (five steps on a linear one).
    for (int e = int(std::ceil(std::log10(panel.y_min) - 1e-9)); e <= int(std::floor(std::log10(panel.y_max) + 1e-9)); ++e) {
      const int y = y_of(std::pow(10.0, e));
      fill(image, left, y, right, y + 1, kGrid);
      const std::string label = decade_label(e);
      text.at(left - 6 - text.width(label), y - int(kTextPixels) / 2, label);
    }
    std::vector<double> x_ticks;
    if (panel.log_x)
      for (int e = int(std::ceil(std::log10(panel.x_min) - 1e-9)); e <= int(std::floor(std::log10(panel.x_max) + 1e-9)); ++e)
        x_ticks.push_back(std::pow(10.0, e));
    else
      for (int i = 0; i <= 5; ++i) x_ticks.push_back(panel.x_min + (panel.x_max - panel.x_min) * i / 5.0);
    for (const double tick : x_ticks) {
      const int x = x_of(tick);
      fill(image, x, top, x + 1, bottom, kGrid);
      const std::string label = fmt::format("{:g}", tick);
      text.at(x - text.width(label) / 2, bottom + 6, label);
    }
    fill(image, left, top, left + 1, bottom + 1, kInk);      // axes
    fill(image, left, bottom, right + 1, bottom + 1, kInk);
    text.at(left, top - 26, panel.title, kTitlePixels);
    text.at((left + right - text.width(panel.x_label)) / 2, bottom + 22, panel.x_label);
    text.at(left + 4, top + 4, panel.y_label);

    for (const PlotSeries& series : panel.series) {
      bool has_previous = false;
      glm::ivec2 previous(0);
      for (const glm::dvec2& p : series.points) {
        const bool drawable = (!panel.log_x || p.x > 0.0) && p.y > 0.0 && p.x <= panel.x_max;
        if (!drawable) continue;
        // Clamped to the frame: a curve leaving the bottom stays on its edge.
        const glm::ivec2 q(std::clamp(x_of(std::max(p.x, panel.x_min)), left, right),
                           std::clamp(y_of(std::clamp(p.y, panel.y_min, panel.y_max)), top, bottom));
        // A staircase: a method's value holds until its next iteration ends, so a Jacobi sweep
        // shows as nothing changing for N rows, then a drop.
        if (has_previous) {
          line(image, previous, {q.x, previous.y}, series.colour);
          line(image, {q.x, previous.y}, q, series.colour);
        }
        previous = q;
        has_previous = true;
      }
    }
  }
  // The legend: a swatch and the name of each series of the first panel.
  if (!panels.empty()) {
    int x = 60;
    const int y = height + 12;
    for (const PlotSeries& series : panels.front().series) {
      fill(image, x, y, x + 24, y + 12, series.colour);
      text.at(x + 30, y - 1, series.name);
      x += 30 + text.width(series.name) + 30;
    }
  }
  return image;
}

}  // namespace luz::app
