#include "app/handout/handout_pdf.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <cairo-pdf.h>
#include <cairo.h>
#include <fmt/format.h>

#include "app/common/i18n.h"
#include "app/models/radiosity/radiosity_session.h"
#include "core/error.h"

namespace luz::app {
namespace {

// A4 in PostScript points (1/72 inch), and the page's margin.
constexpr double kPageWidth = 595.276, kPageHeight = 841.890, kMargin = 42.0;
constexpr double kSlotHeight = (kPageHeight - 2 * kMargin - 18.0) / kStepsPerPage;  // 18: the footer
constexpr double kPictureHeight = 0.62 * kSlotHeight;
constexpr const char* kFont = "DejaVu Sans";

void font(cairo_t* cr, double size, bool bold) {
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

// `text` broken at spaces into lines no wider than `width` (a longer word stands alone).
std::vector<std::string> wrap(cairo_t* cr, const std::string& text, double width) {
  std::vector<std::string> lines;
  std::string line;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find_first_of(" \n", start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && text_width(cr, longer) > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
    if (end < text.size() && text[end] == '\n') {
      lines.push_back(line);
      line.clear();
    }
    start = end + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace

struct HandoutPdf::Cairo {
  cairo_surface_t* surface = nullptr;
  cairo_t* cr = nullptr;
  ~Cairo() {
    if (cr) cairo_destroy(cr);
    if (surface) cairo_surface_destroy(surface);
  }
};

HandoutPdf::HandoutPdf(const std::filesystem::path& path, std::string lesson_title)
    : cairo_(std::make_unique<Cairo>()), path_(path), lesson_title_(std::move(lesson_title)) {
  cairo_->surface = cairo_pdf_surface_create(path.c_str(), kPageWidth, kPageHeight);
  if (cairo_surface_status(cairo_->surface) != CAIRO_STATUS_SUCCESS)
    throw Error(ErrorKind::output, trf("{}: cannot be written", path.string()));
  cairo_pdf_surface_set_metadata(cairo_->surface, CAIRO_PDF_METADATA_TITLE, lesson_title_.c_str());
  cairo_pdf_surface_set_metadata(cairo_->surface, CAIRO_PDF_METADATA_CREATOR, "luz lesson --handout");
  cairo_->cr = cairo_create(cairo_->surface);
}

HandoutPdf::~HandoutPdf() = default;

void HandoutPdf::footer() {
  cairo_t* cr = cairo_->cr;
  font(cr, 8.0, false);
  cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
  const std::string page = fmt::format("{} · {}", lesson_title_, pages_ + 1);
  cairo_move_to(cr, kPageWidth - kMargin - text_width(cr, page), kPageHeight - kMargin + 10.0);
  cairo_show_text(cr, page.c_str());
}

// The heat map's fixed scale, as the panel shows it: the ramp with its decades, in units of the
// scene's mean emitted exitance. Returns where the legend ends.
double HandoutPdf::heat_map_legend(double y) {
  cairo_t* cr = cairo_->cr;
  const double width = kPageWidth - 2 * kMargin, bar = 8.0;
  font(cr, 8.0, false);
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_move_to(cr, kMargin, y + 8.0);
  cairo_show_text(cr, tr("unshot exitance of a patch / the scene's mean emitted exitance (fixed scale):"));
  y += 11.0;
  const int steps = 64;
  const double decades = std::log10(kHeatMapHighest / kHeatMapLowest);
  for (int i = 0; i < steps; ++i) {
    const Rgb c = heat_colour(kHeatMapLowest * std::pow(10.0, decades * (i + 0.5) / steps));
    cairo_set_source_rgb(cr, srgb_encode(c.r), srgb_encode(c.g), srgb_encode(c.b));
    cairo_rectangle(cr, kMargin + width * i / steps, y, width / steps + 0.5, bar);
    cairo_fill(cr);
  }
  y += bar + 9.0;
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  for (int k = 0; k <= int(decades); ++k) {
    const std::string label = fmt::format("{:g}", kHeatMapLowest * std::pow(10.0, k));
    const double w = text_width(cr, label);
    cairo_move_to(cr, kMargin + std::clamp(width * k / decades - 0.5 * w, 0.0, width - w), y);
    cairo_show_text(cr, label.c_str());
  }
  const std::string black = tr("black: nothing left to shoot");
  cairo_move_to(cr, kMargin + width - text_width(cr, black), y + 11.0);
  cairo_show_text(cr, black.c_str());
  return y + 18.0;
}

void HandoutPdf::add(const HandoutStep& step, const Image& picture, float exposure) {
  cairo_t* cr = cairo_->cr;
  const double width = kPageWidth - 2 * kMargin;
  double y = kMargin + on_page_ * kSlotHeight;

  font(cr, 9.0, false);
  cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
  cairo_move_to(cr, kMargin, y + 9.0);
  cairo_show_text(cr, step.heading.c_str());
  y += 14.0;
  font(cr, 13.0, true);
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  for (const std::string& line : wrap(cr, step.title, width)) {
    cairo_move_to(cr, kMargin, y + 13.0);
    cairo_show_text(cr, line.c_str());
    y += 16.0;
  }
  y += 4.0;

  // The picture, as its PNG shows it, fitted into the slot's picture box at its aspect ratio.
  std::vector<uint8_t> rgb(size_t(picture.width) * size_t(picture.height) * 3);
  srgb_bytes(picture.pixels, std::exp2(exposure), rgb);
  cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_RGB24, picture.width, picture.height);
  cairo_surface_flush(image);
  unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  for (int row = 0; row < picture.height; ++row) {
    auto* out = reinterpret_cast<uint32_t*>(data + ptrdiff_t(row) * stride);
    for (int x = 0; x < picture.width; ++x) {
      const uint8_t* p = &rgb[(size_t(row) * size_t(picture.width) + size_t(x)) * 3];
      out[x] = uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | uint32_t(p[2]);
    }
  }
  cairo_surface_mark_dirty(image);
  const double scale = std::min(width / picture.width, kPictureHeight / picture.height);
  const double shown_width = scale * picture.width, shown_height = scale * picture.height;
  cairo_save(cr);
  cairo_translate(cr, kMargin + (width - shown_width) / 2, y);
  cairo_scale(cr, scale, scale);
  cairo_set_source_surface(cr, image, 0.0, 0.0);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_surface_destroy(image);
  y += shown_height + 8.0;
  if (step.heat_map) y = heat_map_legend(y);

  // The text below, smaller where it would run past the slot.
  const double bottom = kMargin + (on_page_ + 1) * kSlotHeight - 8.0;
  double size = 10.0;
  std::vector<std::string> lines;
  for (;; size -= 0.5) {
    font(cr, size, false);
    lines = wrap(cr, step.text, width);
    if (y + double(lines.size()) * 1.3 * size <= bottom || size <= 6.0) break;
  }
  for (const std::string& line : lines) {
    cairo_move_to(cr, kMargin, y + size);
    cairo_show_text(cr, line.c_str());
    y += 1.3 * size;
  }

  if (++on_page_ == kStepsPerPage) {
    footer();
    cairo_show_page(cr);
    ++pages_;
    on_page_ = 0;
  }
}

void HandoutPdf::finish() {
  if (on_page_ > 0) {
    footer();
    cairo_show_page(cairo_->cr);
    ++pages_;
    on_page_ = 0;
  }
  cairo_surface_finish(cairo_->surface);
  if (cairo_surface_status(cairo_->surface) != CAIRO_STATUS_SUCCESS || cairo_status(cairo_->cr) != CAIRO_STATUS_SUCCESS)
    throw Error(ErrorKind::output, trf("{}: cannot be written", path_.string()));
}

}  // namespace luz::app
