// The line plotter of line_plot.h. Sections: [font] [drawing] [plot]
#include "app/common/line_plot.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <fmt/format.h>

namespace luz::app {

// ---- [font] ------------------------------------------------------------------------------------
namespace {

// 5x7 glyphs, one byte per column, bit 0 the top row.
struct Glyph {
  char c;
  uint8_t columns[5];
};
constexpr Glyph kFont[] = {
    {'0', {0x3E, 0x51, 0x49, 0x45, 0x3E}}, {'1', {0x00, 0x42, 0x7F, 0x40, 0x00}},
    {'2', {0x42, 0x61, 0x51, 0x49, 0x46}}, {'3', {0x21, 0x41, 0x45, 0x4B, 0x31}},
    {'4', {0x18, 0x14, 0x12, 0x7F, 0x10}}, {'5', {0x27, 0x45, 0x45, 0x45, 0x39}},
    {'6', {0x3C, 0x4A, 0x49, 0x49, 0x30}}, {'7', {0x01, 0x71, 0x09, 0x05, 0x03}},
    {'8', {0x36, 0x49, 0x49, 0x49, 0x36}}, {'9', {0x06, 0x49, 0x49, 0x29, 0x1E}},
    {'A', {0x7E, 0x11, 0x11, 0x11, 0x7E}}, {'B', {0x7F, 0x49, 0x49, 0x49, 0x36}},
    {'C', {0x3E, 0x41, 0x41, 0x41, 0x22}}, {'D', {0x7F, 0x41, 0x41, 0x22, 0x1C}},
    {'E', {0x7F, 0x49, 0x49, 0x49, 0x41}}, {'F', {0x7F, 0x09, 0x09, 0x09, 0x01}},
    {'G', {0x3E, 0x41, 0x49, 0x49, 0x7A}}, {'H', {0x7F, 0x08, 0x08, 0x08, 0x7F}},
    {'I', {0x00, 0x41, 0x7F, 0x41, 0x00}}, {'J', {0x20, 0x40, 0x41, 0x3F, 0x01}},
    {'K', {0x7F, 0x08, 0x14, 0x22, 0x41}}, {'L', {0x7F, 0x40, 0x40, 0x40, 0x40}},
    {'M', {0x7F, 0x02, 0x0C, 0x02, 0x7F}}, {'N', {0x7F, 0x04, 0x08, 0x10, 0x7F}},
    {'O', {0x3E, 0x41, 0x41, 0x41, 0x3E}}, {'P', {0x7F, 0x09, 0x09, 0x09, 0x06}},
    {'Q', {0x3E, 0x41, 0x51, 0x21, 0x5E}}, {'R', {0x7F, 0x09, 0x19, 0x29, 0x46}},
    {'S', {0x46, 0x49, 0x49, 0x49, 0x31}}, {'T', {0x01, 0x01, 0x7F, 0x01, 0x01}},
    {'U', {0x3F, 0x40, 0x40, 0x40, 0x3F}}, {'V', {0x1F, 0x20, 0x40, 0x20, 0x1F}},
    {'W', {0x3F, 0x40, 0x38, 0x40, 0x3F}}, {'X', {0x63, 0x14, 0x08, 0x14, 0x63}},
    {'Y', {0x07, 0x08, 0x70, 0x08, 0x07}}, {'Z', {0x61, 0x51, 0x49, 0x45, 0x43}},
    {'-', {0x08, 0x08, 0x08, 0x08, 0x08}}, {'.', {0x00, 0x60, 0x60, 0x00, 0x00}},
    {'(', {0x00, 0x1C, 0x22, 0x41, 0x00}}, {')', {0x00, 0x41, 0x22, 0x1C, 0x00}},
    {'/', {0x20, 0x10, 0x08, 0x04, 0x02}}, {'=', {0x14, 0x14, 0x14, 0x14, 0x14}},
    {'|', {0x00, 0x00, 0x7F, 0x00, 0x00}}, {',', {0x00, 0x80, 0x60, 0x00, 0x00}},
    {'+', {0x08, 0x08, 0x3E, 0x08, 0x08}}, {':', {0x00, 0x36, 0x36, 0x00, 0x00}},
    {'*', {0x14, 0x08, 0x3E, 0x08, 0x14}},
};

const Glyph* glyph_of(char c) {
  const char upper = char(std::toupper(static_cast<unsigned char>(c)));
  for (const Glyph& g : kFont)
    if (g.c == upper) return &g;
  return nullptr;
}

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

int text_width(const std::string& text, int scale) { return int(text.size()) * 6 * scale; }

const Rgb kBackground(1.0f), kInk(0.0f), kGrid(0.8f);

}  // namespace

void draw_text(Image& image, int x, int y, const std::string& text, const Rgb& colour, int scale) {
  for (const char c : text) {
    if (const Glyph* g = glyph_of(c))
      for (int column = 0; column < 5; ++column)
        for (int row = 0; row < 8; ++row)
          if (g->columns[column] & (1u << row))
            fill(image, x + column * scale, y + row * scale, x + (column + 1) * scale,
                 y + (row + 1) * scale, colour);
    x += 6 * scale;
  }
}

// ---- [plot] ------------------------------------------------------------------------------------
Image plot(const std::vector<PlotPanel>& panels, int panel_width, int height) {
  constexpr int legend_height = 40;
  Image image(panel_width * int(panels.size()), height + legend_height, kBackground);
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
      const std::string label = e == 0 ? "1" : fmt::format("1E{}", e);
      draw_text(image, left - 6 - text_width(label, 1), y - 3, label, kInk);
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
      draw_text(image, x - text_width(label, 1) / 2, bottom + 6, label, kInk);
    }
    fill(image, left, top, left + 1, bottom + 1, kInk);      // axes
    fill(image, left, bottom, right + 1, bottom + 1, kInk);
    draw_text(image, left, top - 22, panel.title, kInk, 2);
    draw_text(image, (left + right - text_width(panel.x_label, 1)) / 2, bottom + 22, panel.x_label, kInk);
    draw_text(image, left + 4, top + 4, panel.y_label, kInk);

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
      draw_text(image, x + 30, y + 2, series.name, kInk);
      x += 30 + text_width(series.name, 1) + 30;
    }
  }
  return image;
}

}  // namespace luz::app
