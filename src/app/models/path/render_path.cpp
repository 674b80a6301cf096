#include "app/models/path/render_path.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <unistd.h>

#include <fmt/format.h>

#include "app/cli/render_command.h"
#include "app/common/model_registry.h"
#include "app/common/i18n.h"
#include "app/models/path/path_options.h"
#include "core/error.h"
#include "io/image_io.h"
#include "raytracing/path_tracer.h"
#include "raytracing/sampling.h"

namespace luz::app {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

PathResult render_path(const Scene& scene, const Camera& camera, int width, int height,
                       const rt::PathOptions& options, std::optional<double> seconds,
                       bool spp_given, bool progress) {
  const auto start = Clock::now();
  rt::PathRenderer tracer(scene);
  rt::PathFilm film(width, height);
  const int spp = std::max(1, options.spp);
  const auto shown = [&](const std::string& line) {
    if (!progress) return;
    fmt::print(stderr, "\r{}\x1b[K", line);
    std::fflush(stderr);
  };

  if (!seconds) {
    // One pass of spp samples, the bar advancing tile by tile.
    int last = -1;
    tracer.add_samples(film, camera, options, spp, [&](const rt::Tile&, int done, int total) {
      const int percent = 100 * done / total;
      if (percent == last) return;
      last = percent;
      constexpr int bar = 40;
      shown(fmt::format("path [{}{}] {:3}%  {} spp", std::string(size_t(bar * percent / 100), '#'),
                        std::string(size_t(bar - bar * percent / 100), '.'), percent, spp));
    });
  } else {
    // Passes of one sample per pixel until the time is up (a pass that starts finishes; the
    // first always runs, so the picture is never empty).
    const int cap = spp_given ? spp : std::numeric_limits<int>::max();
    do {
      tracer.add_samples(film, camera, options, 1);
      shown(fmt::format("path {:.1f} / {:g} s  {} spp", since(start), *seconds, film.min_samples()));
    } while (film.min_samples() < cap && since(start) < *seconds);
  }
  if (progress) fmt::print(stderr, "\n");

  PathResult result;
  result.mean = film.mean();
  result.standard_error = film.standard_error();
  result.spp = film.min_samples();
  result.seconds = since(start);
  double error = 0.0;
  for (const Rgb& e : result.standard_error.pixels) error += double(e.r + e.g + e.b) / 3.0;
  error /= double(std::max<size_t>(1, result.standard_error.pixels.size()));
  const double samples = double(width) * double(height) * double(result.spp);
  result.summary = trf("path: {} spp, depth {}, seed {}: {:.3g} samples/s, mean standard "
                       "error {:.4g}", result.spp, rt::max_depth_of(options), options.seed,
                       samples / std::max(result.seconds, 1e-9), error) + "\n";
  return result;
}

namespace {

bool given(const RenderSettings& settings, std::string_view flag) {
  return std::any_of(settings.given_flags.begin(), settings.given_flags.end(),
                     [&](const RenderSettings::GivenFlag& g) { return g.flag == flag; });
}

}  // namespace

Rendered render_path_model(const Scene& scene, const Camera& camera, int width, int height,
                           const RenderSettings& settings) {
  const PathSettings& path_settings = settings.model_options.get<PathSettings>(path_table());
  const std::string& error_out = path_settings.error_out;
  if (!error_out.empty()) {
    std::string extension = std::filesystem::path(error_out).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension != ".exr")
      throw Error(ErrorKind::usage, trf("--error-out {}: the standard error is written as "
                                        ".exr (linear float)", error_out));
  }
  rt::PathOptions options = path_settings;
  options.textures = settings.local.terms.textures;
  // With --time, a given --spp caps the passes; else the time alone stops them.
  const bool spp_given = given(settings, "--spp");
  const PathResult path = render_path(scene, camera, width, height, options, settings.seconds,
                                      spp_given, !settings.quiet && isatty(STDERR_FILENO));
  if (!error_out.empty()) io::write_image(path.standard_error, error_out, 0.0f);
  Rendered result{path.mean, path.summary, std::nullopt};
  if (!error_out.empty()) result.summary += trf("standard error: {}", error_out) + "\n";
  return result;
}

}  // namespace luz::app
