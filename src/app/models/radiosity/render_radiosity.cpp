#include "app/models/radiosity/render_radiosity.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <unistd.h>

#include "app/common/i18n.h"
#include "core/error.h"
#include "gl/offscreen_context.h"
#include "io/atomic_file.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/radiosity_renderer.h"
#include "radiosity/shooting.h"
#include "radiosity/vertex_colours.h"

namespace luz::app {
namespace {

// 0 .. 1: shots against --shots, else the unshot fraction on a log scale down to --converge;
// with --time, the share of it used if that is further along.
double progress_of(const ProgressiveSolver& solver, const RadiosityOptions& options, double seconds,
                   std::optional<double> limit) {
  double progress = 0.0;
  if (options.max_shots > 0) progress = double(solver.shots()) / double(options.max_shots);
  if (options.converge > 0.0f && solver.unshot_fraction() > 0.0)
    progress = std::max(progress, std::log(solver.unshot_fraction()) / std::log(double(options.converge)));
  if (limit) progress = std::max(progress, seconds / *limit);
  return std::clamp(progress, 0.0, 1.0);
}

void draw_progress(const ProgressiveSolver& solver, const RadiosityOptions& options, double seconds,
                   std::optional<double> limit) {
  constexpr int width = 30;
  const int filled = int(std::lround(progress_of(solver, options, seconds, limit) * width));
  // xgettext:no-c-format
  fmt::print(stderr, "\r{}", trf("radiosity [{}{}] shot {}, unshot {:.3f}% of the emitted power ",
                                 std::string(size_t(filled), '#'), std::string(size_t(width - filled), '-'),
                                 solver.shots(), 100.0 * solver.unshot_fraction()));
  std::fflush(stderr);
}

void write_csv(const std::string& path, const ProgressiveSolver& solver) {
  const std::string failure = io::write_atomically(path, [&] {
    std::string csv = "shot,unshot_power,fraction,seconds\n";
    for (const ShotRecord& r : solver.history())
      csv += fmt::format("{},{:.9g},{:.9g},{:.6f}\n", r.shot, r.unshot_power, r.fraction, r.seconds);
    return csv;
  });
  if (!failure.empty()) throw Error(ErrorKind::output, trf("--csv {}: cannot write the file", path));
}

// The work budget bounds a run at the defaults only: a stopping rule given on the command line
// (or the budget itself) is the user's.
bool work_bounded(const RenderSettings& settings) {
  if (settings.radiosity.work_budget <= 0.0) return false;
  return std::none_of(settings.given_flags.begin(), settings.given_flags.end(), [](const RenderSettings::GivenFlag& g) {
    return g.flag == "--shots" || g.flag == "--converge" || g.flag == "--time";
  });
}

}  // namespace

RadiosityOptions radiosity_options(const RenderSettings& settings) {
  RadiosityOptions options = settings.radiosity;
  options.textures = settings.local.terms.textures;
  return options;
}

void run_radiosity_solver(ProgressiveSolver& solver, const RenderSettings& settings) {
  const RadiosityOptions& options = solver.options();
  const PatchMesh& mesh = solver.mesh();
  for (const std::string& warning : solver.warnings()) fmt::print(stderr, "{}\n", trf("warning: {}", warning));

  const bool bar = !settings.quiet && isatty(fileno(stderr));
  // The solver's own clock: its history stamps every shot with the seconds since it started.
  const auto solving = [&] { return solver.history().back().seconds; };
  auto last_draw = std::chrono::steady_clock::now();
  // A shot that starts finishes, so the time may run over by one shot; the first always runs.
  bool out_of_time = false, out_of_work = false;
  const bool bounded = work_bounded(settings);
  while (solver.step()) {
    if (bar && std::chrono::steady_clock::now() - last_draw > std::chrono::milliseconds(100)) {
      draw_progress(solver, options, solving(), settings.seconds);
      last_draw = std::chrono::steady_clock::now();
    }
    out_of_time = settings.seconds && solving() >= *settings.seconds && !solver.done();
    out_of_work = bounded && solver.element_shots() >= options.work_budget && !solver.done();
    if (out_of_time || out_of_work) break;
  }
  if (bar) {
    draw_progress(solver, options, solving(), settings.seconds);
    fmt::print(stderr, "\n");
  }
  if (!settings.csv.empty()) write_csv(settings.csv, solver);
  if (!settings.quiet)
    // xgettext:no-c-format
    fmt::print("{}\n", trf("radiosity: {} patches (longest edge {:.3g} m) of {} elements, hemicube {}, {} shots, "
                           "unshot {:.3f}% of the emitted power, {:.2f} s solving", mesh.shooters.size(),
                           mesh.max_edge, mesh.size(), options.hemicube_res, solver.shots(),
                           100.0 * solver.unshot_fraction(), solving()));
  if (!settings.quiet && out_of_time)
    fmt::print("{}\n", trf("radiosity: stopped by --time {:g} before --converge or --shots", *settings.seconds));
  // A picture short of what the defaults promise is a warning: -q keeps it, as it keeps every warning.
  if (out_of_work) {
    // xgettext:no-c-format
    const std::string stopped = trf("radiosity: stopped early, at the work budget of {:.3g} element-shots ({} shots on "
                                    "{} elements): {:.2f}% of the emitted power is still unshot (the defaults stop "
                                    "below {:.2g}%); to go further give --time SECONDS or --converge EPS (or a larger "
                                    "--work-budget)",
                                    options.work_budget, solver.shots(), mesh.size(), 100.0 * solver.unshot_fraction(),
                                    100.0 * double(options.converge));
    fmt::print(stderr, "{}\n", trf("warning: {}", stopped));
  }
}

Image render_radiosity(const Scene& scene, const Camera& camera, int width, int height,
                       const RenderSettings& settings) {
  const RadiosityOptions options = radiosity_options(settings);
  if (const RadiositySolution* shared = settings.radiosity_solution.get()) {
    RadiosityRenderer renderer(scene, shared->mesh);
    // The heat map is no radiance for a texture to modulate.
    if (shared->heat_map) renderer.update(*shared->heat_map, options, false);
    else renderer.update(shared->radiance, options);
    return renderer.render(camera, width, height, options);
  }
  PatchMesh mesh = PatchMesh::build(scene, options);
  ProgressiveSolver solver(scene, mesh, options);
  run_radiosity_solver(solver, settings);

  RadiosityRenderer renderer(scene, mesh);
  renderer.update(RadianceField::of(solver), options);
  return renderer.render(camera, width, height, options);
}

std::shared_ptr<const RadiositySolution> solve_radiosity(const Scene& scene, const RenderSettings& settings,
                                                         const SolveExtent& extent) {
  auto solution = std::make_shared<RadiositySolution>();
  const RadiosityOptions options = radiosity_options(settings);
  solution->mesh = PatchMesh::build(scene, options);
  gl::OffscreenContext context;  // the hemicubes draw through GL
  ProgressiveSolver solver(scene, solution->mesh, options);
  if (extent.shots) {
    for (int shot = 0; shot < *extent.shots && solver.step(); ++shot) {
    }
  } else {
    run_radiosity_solver(solver, settings);
  }
  solution->radiance = RadianceField::of(solver);
  if (extent.heat_map) {
    // The PNG multiplies by 2^exposure: divided out here, the picture shows the map's colours.
    RadianceField heat = extent.heat_map(solver);
    const float undo = std::exp2(-extent.exposure);
    for (Rgb& c : heat.patch) c *= undo;
    for (Rgb& c : heat.corner) c *= undo;
    solution->heat_map = std::move(heat);
  }
  return solution;
}

}  // namespace luz::app
