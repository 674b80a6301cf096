// `luz solvers`: the convergence curves of slide 36's methods and slide 39's shooting.
#include "app/cli/solvers_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "app/common/line_plot.h"
#include "app/common/i18n.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "gl/offscreen_context.h"
#include "io/gltf_loader.h"
#include "io/image_io.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/solver_comparison.h"

namespace luz::app {

// One colour and name per method, shared with the viewer's window.----------------
Rgb method_colour(Method method) {
  switch (method) {
    case Method::jacobi: return {0.85f, 0.1f, 0.1f};
    case Method::gauss_seidel: return {0.1f, 0.25f, 0.9f};
    case Method::southwell: return {0.1f, 0.6f, 0.1f};
    case Method::shooting: return {0.95f, 0.55f, 0.0f};
  }
  return Rgb(0.0f);
}

const char* method_label(Method method) {
  switch (method) {
    case Method::jacobi: return "Jacobi";
    case Method::gauss_seidel: return "Gauss-Seidel";
    case Method::southwell: return "Southwell";
    case Method::shooting: return tr("shooting (slide 39)");
  }
  return "?";
}
namespace {

void write_csv(const std::string& path, const SolverComparison& race) {
  const std::string failure = io::write_atomically(path, [&] {
    std::string csv = "method,iteration,rows,seconds,residual,error\n";
    for (const Method m : kMethods)
      for (const SolverSample& s : race.curve(m))
        csv += fmt::format("{},{},{},{:.6f},{:.9g},{:.9g}\n", to_string(m), s.iteration, s.rows, s.seconds,
                           s.residual, s.error);
    return csv;
  });
  if (!failure.empty()) throw Error(ErrorKind::output, trf("--csv {}: cannot write the file", path));
}

// Two panels, residual and error against the rows used (log axes), one line per method.
Image plot_curves(const SolverComparison& race, size_t patches) {
  std::vector<PlotPanel> panels(2);
  double smallest = 1.0;
  for (const Method m : kMethods)
    for (const SolverSample& s : race.curve(m))
      for (const double v : {s.residual, s.error})
        if (v > 0.0) smallest = std::min(smallest, v);
  for (int k = 0; k < 2; ++k) {
    PlotPanel& panel = panels[size_t(k)];
    panel.title = k == 0 ? tr("residual |E - (I - rho F) B| / |E|") : tr("error |B - B*| / |B*|");
    panel.x_label = trf("form-factor rows used ({} patches)", patches);
    panel.y_label = "";
    panel.x_min = 1.0;
    panel.x_max = double(std::max<size_t>(race.max_rows(), 10));
    panel.y_max = 2.0;
    panel.y_min = std::max(std::pow(10.0, std::floor(std::log10(smallest))), 1e-12);
    for (const Method m : kMethods) {
      PlotSeries series{method_label(m), method_colour(m), {}};
      for (const SolverSample& s : race.curve(m))
        // Rows 0 has no place on a log axis: the start is drawn at 1 row.
        series.points.push_back({double(std::max<size_t>(s.rows, 1)), k == 0 ? s.residual : s.error});
      panel.series.push_back(std::move(series));
    }
  }
  return plot(panels, 640, 440);
}

}  // namespace

int run_solvers(const SolversSettings& settings) {
  try {
    if (!settings.png.empty() && std::filesystem::path(settings.png).extension() != ".png")
      throw Error(ErrorKind::usage, trf("--png {}: the plot must end in .png", settings.png));
    io::LoadedScene loaded = io::load_gltf(settings.scene);
    for (const std::string& warning : loaded.warnings) fmt::print(stderr, "{}\n", trf("warning: {}", warning));
    const Scene& scene = loaded.scene;

    RadiosityOptions options;
    options.patch_size = settings.patch_size;
    options.target_patches = settings.patches;
    options.elements_per_edge = 1;  // the matrix methods solve on the patches themselves
    options.hemicube_res = settings.hemicube_res;
    options.form_factors = settings.form_factors;
    PatchMesh mesh = PatchMesh::build(scene, options);
    if (mesh.size() > kMaxSolverPatches)
      throw Error(ErrorKind::bad_value,
                  trf("{}: {} patches; the full form-factor matrix of slide 36 grows as the "
                      "square of that, so luz solvers takes at most {} (use a larger "
                      "--patch-size or fewer --patches)", settings.scene, mesh.size(),
                      kMaxSolverPatches));

    gl::OffscreenContext context;
    const size_t max_rows = size_t(settings.iterations) * mesh.size();
    SolverComparison race(scene, mesh, options, max_rows);
    while (race.step()) {}
    write_csv(settings.csv, race);
    if (!settings.png.empty()) io::write_image(plot_curves(race, mesh.size()), settings.png, 0.0f);

    if (!settings.quiet) {
      fmt::print("{}\n", trf("solvers: {} patches, {} form-factor entries ({}), the matrix in {:.2f} s ({} "
                             "hemicubes of {})", mesh.size(), race.system().F.nonzeros(),
                             to_string(settings.form_factors), race.matrix_seconds(), mesh.size(),
                             settings.hemicube_res));
      for (const Method m : kMethods) {
        const SolverSample& last = race.curve(m).back();
        fmt::print("{}\n", trf("  {:<13} {:>6} iterations {:>8} rows {:8.3f} s   residual {:.2e}   error {:.2e}",
                               to_string(m), last.iteration, last.rows, last.seconds, last.residual, last.error));
      }
    }
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
