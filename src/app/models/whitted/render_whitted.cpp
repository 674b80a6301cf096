#include "app/models/whitted/render_whitted.h"

#include <cstdio>
#include <string>
#include <utility>
#include <unistd.h>

#include <fmt/format.h>

#include "app/common/i18n.h"
#include "core/error.h"
#include "raytracing/renderer.h"
#include "raytracing/sampling.h"

namespace luz::app {

namespace {

// "whitted [##########..........]  52%" on stderr, rewritten in place; only on a terminal.
class ProgressBar {
public:
  ProgressBar(bool on, std::string label) : on_(on), label_(std::move(label)) {}
  void update(int done, int total) {
    if (!on_) return;
    const int percent = total > 0 ? 100 * done / total : 100;
    if (percent == shown_) return;
    shown_ = percent;
    constexpr int width = 40;
    const int filled = width * percent / 100;
    fmt::print(stderr, "\r{} [{}{}] {:3}%", label_, std::string(size_t(filled), '#'),
               std::string(size_t(width - filled), '.'), percent);
    if (done == total) fmt::print(stderr, "\n");
    std::fflush(stderr);
  }

private:
  bool on_;
  std::string label_;
  int shown_ = -1;
};

}  // namespace

rt::WhittedOptions tracer_options(const rt::WhittedOptions& whitted, const LocalOptions& local) {
  rt::WhittedOptions options = whitted;
  options.terms = local.terms;
  return options;
}

void check_square_spp(const RenderSettings& settings) {
  if (!rt::is_square(settings.whitted.spp))
    throw Error(ErrorKind::usage, trf("--spp {}: expected a square number of samples: 1, 4, 9, 16, ... "
                                      "(at most 4096)", settings.whitted.spp));
}

Rendered render_whitted(const Scene& scene, const Camera& camera, int width, int height,
                             const RenderSettings& settings, const rt::DiffuseSource* diffuse) {
  check_square_spp(settings);
  if (settings.ray_tree) {
    const auto [x, y] = *settings.ray_tree;
    if (x < 0 || y < 0 || x >= width || y >= height)
      throw Error(ErrorKind::usage, trf("--ray-tree {},{}: outside the {}x{} image", x, y,
                                        width, height));
  }
  const rt::WhittedOptions options = tracer_options(settings.whitted, settings.local);
  rt::WhittedRenderer tracer(scene);
  tracer.set_diffuse_source(diffuse);
  ProgressBar bar(!settings.quiet && isatty(STDERR_FILENO), settings.model);
  Rendered result;
  result.image = tracer.render(camera, width, height, options,
                               [&bar](const rt::TileDone& done) { bar.update(done.done, done.total); });
  result.summary = tracer.counters().to_string();
  if (settings.ray_tree)
    result.ray_tree = tracer.trace_pixel(camera, width, height, settings.ray_tree->first,
                                         settings.ray_tree->second, options).to_json();
  return result;
}

}  // namespace luz::app
