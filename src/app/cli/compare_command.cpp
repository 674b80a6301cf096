// luz compare. Sections: [legend] [command]
#include "app/cli/compare_command.h"

#include <cmath>
#include <cstdio>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/common/i18n.h"
#include "app/common/line_plot.h"
#include "core/error.h"
#include "core/image_compare.h"
#include "io/image_io.h"

namespace luz::app {

// ---- [legend] -----------------------------------------------------------------------------------
namespace {

// The heat map above a legend: a colour bar from -range to +range, labelled at both ends and 0.
Image with_legend(const Image& heatmap, float range) {
  const int scale = std::max(2, heatmap.width / 160);  // font pixels: legible at any size
  const int bar = 8 * scale, label = 7 * scale, margin = 2 * scale;
  Image out(heatmap.width, heatmap.height + margin + bar + label + margin, Rgb(0.0f));
  for (int y = 0; y < heatmap.height; ++y)
    for (int x = 0; x < heatmap.width; ++x) out.at(x, y) = heatmap.at(x, y);
  const int top = heatmap.height + margin;
  for (int x = 0; x < out.width; ++x) {
    const Rgb c = diverging_colour(2.0f * (float(x) + 0.5f) / float(out.width) - 1.0f);
    for (int y = top; y < top + bar; ++y) out.at(x, y) = c;
  }
  const int percent = int(std::lround(100.0 * double(range)));
  const std::string low = fmt::format("-{}%", percent), high = fmt::format("+{}%", percent);
  const Rgb white(1.0f);
  const int text_y = top + bar + scale;
  draw_text(out, scale, text_y, low, white, scale);
  draw_text(out, (out.width - text_width("0", scale)) / 2, text_y, "0", white, scale);
  draw_text(out, out.width - text_width(high, scale), text_y, high, white, scale);
  return out;
}

}  // namespace

// ---- [command] ----------------------------------------------------------------------------------
void add_compare_flags(CLI::App& compare, CompareSettings& settings) {
  compare.add_option("A", settings.a, tr("The picture compared (.exr: linear radiance)"))->required();
  compare.add_option("B", settings.b, tr("The reference (e.g. luz render --model path)"))->required();
  compare.add_option("--heatmap", settings.heatmap,
                     tr("Write the signed relative difference (A - B) / B as a PNG with a legend "
                        "(blue: A darker, red: A brighter; grey: unlit)"));
  compare.add_flag("--mask-emitters", settings.mask_emitters,
                   tr("Leave out pixels 10x brighter than the median lit pixel (emitters) and their neighbours"));
  compare.add_flag("-q,--quiet", settings.quiet, tr("Print nothing on success"));
}

int run_compare(const CompareSettings& settings) {
  try {
    if (!settings.heatmap.empty() && std::filesystem::path(settings.heatmap).extension() != ".png")
      throw Error(ErrorKind::usage, trf("--heatmap {}: the heat map is written as .png",
                                        settings.heatmap));
    const Image a = io::read_image(settings.a);
    const Image b = io::read_image(settings.b);
    if (a.width != b.width || a.height != b.height)
      throw Error(ErrorKind::bad_value, trf("{}: {}x{} pixels, but the reference {} has {}x{}",
                                            settings.a, a.width, a.height, settings.b,
                                            b.width, b.height));
    CompareOptions options;
    options.mask_emitters = settings.mask_emitters;
    const ImageComparison c = compare_images(a, b, options);
    if (!settings.heatmap.empty()) {
      const float range = heatmap_range(c);
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
      if (!settings.heatmap.empty()) line(trf("heat map: {}", settings.heatmap));
    }
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
