// luz compare. Sections: [legend] [command]
#include "app/cli/compare_command.h"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <cmath>
#include <cstdio>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/common/i18n.h"
#include "app/common/label_text.h"
#include "core/error.h"
#include "core/image_compare.h"
#include "io/image_io.h"

namespace luz::app {

// ---- [legend] -----------------------------------------------------------------------------------
namespace {

// The legend's text height: readable on a printed page and beside a projector's picture.
float legend_text_height(const Image& heatmap) {
  return std::max(16.0f, float(std::max(heatmap.width, heatmap.height)) / 36.0f);
}

// The heat map above its legend: a colour bar from -range to +range, its ends and 0 written
// under it inside the picture's width, and a line saying what the colours mean (smaller where
// the picture is too narrow for it).
Image with_legend(const Image& heatmap, float range) {
  const LabelFont font;
  const float size = legend_text_height(heatmap);
  const int pad = int(std::ceil(0.4f * size));
  const int percent = int(std::lround(100.0 * double(range)));
  const std::string low = fmt::format("-{}%", percent), high = fmt::format("+{}%", percent);
  const std::string meaning = tr("blue: A darker than B, red: A brighter; grey: unlit");
  float meaning_size = size;
  while (meaning_size > 8.0f && font.measure(meaning, meaning_size).width > heatmap.width - 2 * pad) meaning_size -= 1.0f;
  const LabelFont::Extent label = font.measure(high, size), line = font.measure(meaning, meaning_size);
  const int bar = int(std::ceil(0.8f * size)), label_height = label.ascent + label.descent;
  const int line_height = line.ascent + line.descent;
  Image out(heatmap.width, heatmap.height + pad + bar + pad + label_height + pad + line_height + pad, Rgb(0.0f));
  for (int y = 0; y < heatmap.height; ++y)
    for (int x = 0; x < heatmap.width; ++x) out.at(x, y) = heatmap.at(x, y);
  const int top = heatmap.height + pad;
  for (int x = 0; x < out.width; ++x) {
    const Rgb c = diverging_colour(2.0f * (float(x) + 0.5f) / float(out.width) - 1.0f);
    for (int y = top; y < top + bar; ++y) out.at(x, y) = c;
  }
  const Rgb white(1.0f);
  const int text_y = top + bar + pad;
  font.draw(out, pad, text_y, low, size, white);
  font.draw(out, (out.width - font.measure("0", size).width) / 2, text_y, "0", size, white);
  font.draw(out, out.width - label.width - pad, text_y, high, size, white);
  font.draw(out, pad, text_y + label_height + pad, meaning, meaning_size, white);
  return out;
}

// --range: a percentage > 0, or auto.
std::optional<float> parse_range(const std::string& text) {
  if (text == "auto") return std::nullopt;
  std::string number = text;
  if (number.ends_with('%')) number.pop_back();
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (number.empty() || *end != '\0' || !std::isfinite(value) || value <= 0.0 || value > 1000.0)
    throw Error(ErrorKind::usage, trf("--range {}: expected a percentage in (0, 1000], e.g. 50, or auto", text));
  return float(value / 100.0);
}

}  // namespace

// ---- [command] ----------------------------------------------------------------------------------
void add_compare_flags(CLI::App& compare, CompareSettings& settings) {
  compare.add_option("A", settings.a, tr("The picture compared (.exr: linear radiance)"))->required();
  compare.add_option("B", settings.b, tr("The reference (e.g. luz render --model path)"))->required();
  compare.add_option("--heatmap", settings.heatmap,
                     tr("Write the signed relative difference (A - B) / B as a PNG with a legend "
                        "(blue: A darker, red: A brighter; grey: unlit)"));
  compare.add_option("--range", settings.range,
                     // xgettext:no-c-format
                     tr("The heat map's scale: red and blue saturate at +-this percentage (auto: the smallest of 1, 2, "
                        "5, 10, 20, 50, 100 that holds 95% of the lit pixels)"))
      ->capture_default_str();
  compare.add_flag("--mask-emitters", settings.mask_emitters,
                   tr("Leave out pixels 10x brighter than the median lit pixel (emitters) and their neighbours"));
  compare.add_flag("-q,--quiet", settings.quiet, tr("Print nothing on success"));
}

int run_compare(const CompareSettings& settings) {
  try {
    if (!settings.heatmap.empty() && std::filesystem::path(settings.heatmap).extension() != ".png")
      throw Error(ErrorKind::usage, trf("--heatmap {}: the heat map is written as .png",
                                        settings.heatmap));
    const std::optional<float> fixed_range = parse_range(settings.range);
    LabelFont{};  // a missing font is found before the pictures are read
    const Image a = io::read_image(settings.a);
    const Image b = io::read_image(settings.b);
    if (a.width != b.width || a.height != b.height)
      throw Error(ErrorKind::bad_value, trf("{}: {}x{} pixels, but the reference {} has {}x{}",
                                            settings.a, a.width, a.height, settings.b,
                                            b.width, b.height));
    CompareOptions options;
    options.mask_emitters = settings.mask_emitters;
    const ImageComparison c = compare_images(a, b, options);
    const float range = fixed_range.value_or(heatmap_range(c));
    if (!settings.heatmap.empty()) {
      io::write_image(with_legend(relative_difference_heatmap(c, a.width, a.height, range), range),
                      settings.heatmap, 0.0f);
    }
    if (!settings.quiet) {
      const size_t pixels = size_t(a.width) * size_t(a.height);
      const auto line = [](const std::string& text) { fmt::print("{}\n", text); };
      line(trf("{} against {} (reference), {}x{}", settings.a, settings.b, a.width, a.height));
      if (settings.mask_emitters) line(trf("emitter pixels left out: {}", c.masked_pixels));
      line(trf("mean error (A - B):   R {:+.6f}  G {:+.6f}  B {:+.6f}", c.mean_error.r, c.mean_error.g,
               c.mean_error.b));
      line(trf("mean absolute error:  R {:.6f}  G {:.6f}  B {:.6f}", c.mean_absolute_error.r,
               c.mean_absolute_error.g, c.mean_absolute_error.b));
      line(trf("rel-RMSE:             {:.6f}", c.rel_rmse));
      // xgettext:no-c-format
      line(trf("mean relative error over lit pixels: {:.4f} ({:.2f}%, {} of {} pixels lit)", c.mean_relative_error,
               100.0 * c.mean_relative_error, c.lit_pixels, pixels));
      // xgettext:no-c-format
      if (!settings.heatmap.empty()) line(trf("heat map: {} (blue -{:g}% .. red +{:g}%)", settings.heatmap,
                                              100.0 * double(range), 100.0 * double(range)));
    }
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
