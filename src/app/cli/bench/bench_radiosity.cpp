// `luz bench radiosity`: shots per second and time to converge on the Cornell box at several
// patch counts, with each shot split into drawing the hemicube, reading it back, accumulating
// the form factors and updating the unshot values (slide 39's loop). With --reference, the
// time-to-error curve instead: the mean relative error over lit pixels against a converged
// picture after 0.25, 0.5, 1, 2, ... seconds of solving, for each way of solving (the time to
// draw the picture at each point is not counted).
#include <algorithm>
#include <cmath>
#include <chrono>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli/bench/bench_command.h"
#include "app/cli/bench/bench_table.h"
#include "core/resources.h"
#include "app/common/i18n.h"
#include "core/error.h"
#include "gl/functions.h"
#include "gl/offscreen_context.h"
#include "io/gltf_loader.h"
#include "io/image_io.h"
#include "radiosity/radiosity_renderer.h"
#include "radiosity/vertex_colours.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/shooting.h"

namespace luz::app {
namespace {

// Mean over lit pixels (reference above 1% of its mean) of |L - R| / R, channels averaged.
double mean_relative_error(const Image& image, const Image& reference) {
  double mean = 0.0;
  for (const Rgb& r : reference.pixels) mean += (double(r.r) + double(r.g) + double(r.b)) / 3.0;
  mean /= double(std::max<size_t>(1, reference.pixels.size()));
  double sum = 0.0;
  size_t lit = 0;
  for (size_t i = 0; i < reference.pixels.size(); ++i) {
    const Rgb& r = reference.pixels[i];
    const Rgb& l = image.pixels[i];
    const double R = (double(r.r) + double(r.g) + double(r.b)) / 3.0;
    if (!(R > 0.01 * mean)) continue;
    double e = 0.0;
    for (int c = 0; c < 3; ++c) e += std::abs(double(l[c]) - double(r[c])) / std::max(double(r[c]), 1e-3 * R);
    sum += e / 3.0;
    ++lit;
  }
  return lit > 0 ? sum / double(lit) : 0.0;
}

struct Way {
  const char* key;   // as --ways names it
  const char* name;  // as the table prints it, translated there
  RadiosityOptions options;
};

// One row of a Markdown table: "| a | b | c |".
std::string markdown_row(const std::vector<std::string>& cells) {
  std::string line = "|";
  for (const std::string& cell : cells) line += " " + cell + " |";
  return line + "\n";
}

// The form-factor method of a row, in the current language.
std::string method_label(FormFactorMethod method, const RadiosityBenchSettings& settings) {
  switch (method) {
    case FormFactorMethod::hemicube: {
      std::string label = tr("hemicube");
      if (settings.hemicube_passes == HemicubePasses::one) label += tr(", one pass");
      if (settings.hemicube_sums == HemicubeSums::gpu) label += tr(", GPU sums");
      return label;
    }
    case FormFactorMethod::rays: return tr("rays");
    case FormFactorMethod::analytic: return tr("analytic");
  }
  return to_string(method);
}

int run_error_curve(const RadiosityBenchSettings& settings, const io::LoadedScene& loaded) {
  const Image reference = io::read_image(settings.reference);
  const Scene& scene = loaded.scene;
  if (scene.cameras.empty()) throw Error(ErrorKind::bad_value, tr("the scene has no camera to compare from"));
  RadiosityOptions fixed;  // the ways but the last keep their mesh as built
  fixed.meshing = Meshing::uniform;
  RadiosityOptions uniform = fixed;
  uniform.elements_per_edge = 1;
  uniform.form_factors = FormFactorMethod::hemicube;
  uniform.target_patches = 4000;
  RadiosityOptions substructured = fixed;
  substructured.form_factors = FormFactorMethod::hemicube;
  RadiosityOptions analytic = fixed;
  analytic.form_factors = FormFactorMethod::analytic;
  RadiosityOptions overshot = analytic;
  overshot.overshoot = 1.5f;
  RadiosityOptions rays = fixed;
  rays.form_factors = FormFactorMethod::rays;
  RadiosityOptions rays_ambient = rays;
  rays_ambient.ambient_estimate = true;
  RadiosityOptions adaptive = rays;
  adaptive.meshing = Meshing::adaptive;
  const Way ways[] = {{"uniform", N_("uniform (every element shoots), hemicube"), uniform},
                      {"hemicube", N_("substructured 4x4, hemicube"), substructured},
                      {"analytic", N_("substructured 4x4, analytic"), analytic},
                      {"overshoot", N_("substructured 4x4, analytic, overshoot 1.5"), overshot},
                      {"rays", N_("substructured 4x4, rays"), rays},
                      {"rays-ambient", N_("substructured 4x4, rays, shown with the ambient estimate"),
                       rays_ambient},
                      {"adaptive", N_("substructured 4x4, rays, adaptive subdivision"), adaptive}};
  const auto chosen = [&](const Way& way) {
    return settings.ways.empty() ||
           std::find(settings.ways.begin(), settings.ways.end(), way.key) != settings.ways.end();
  };
  fmt::print("{}", markdown_row({tr("way"), tr("patches"), tr("elements"), tr("seconds solving"), tr("shots"),
                                 tr("unshot"), tr("error over lit pixels")}));
  fmt::print("| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  for (const Way& way : ways) {
    if (!chosen(way)) continue;
    RadiosityOptions options = way.options;
    options.hemicube_res = settings.hemicube_res;
    options.hemicube_passes = settings.hemicube_passes;
    options.hemicube_sums = settings.hemicube_sums;
    options.converge = 1e-4f;
    PatchMesh mesh = PatchMesh::build(scene, options);
    ProgressiveSolver solver(scene, mesh, options);
    RadiosityRenderer renderer(scene, mesh);
    double solving = 0.0, next = 0.25;
    bool more = true;
    while (more) {
      const auto start = std::chrono::steady_clock::now();
      while ((more = solver.step()) &&
             solving + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < next) {}
      solving += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      renderer.update(RadianceField::of(solver), options);
      const Image image = renderer.render(scene.cameras.front(), reference.width, reference.height, options);
      fmt::print("| {} | {} | {} | {:.2f} | {} | {:.3f}% | {:.2f}% |\n", tr(way.name), mesh.shooters.size(),
                 mesh.size(), solving, solver.shots(), 100.0 * solver.unshot_fraction(),
                 100.0 * mean_relative_error(image, reference));
      std::fflush(stdout);
      next *= 2.0;
      if (solving >= settings.seconds) break;
    }
  }
  return 0;
}

}  // namespace

int run_radiosity_bench(const RadiosityBenchSettings& settings) {
  try {
    const std::string path = settings.scene.empty() ? default_scene().string() : settings.scene;
    const io::LoadedScene loaded = io::load_gltf(path);
    gl::OffscreenContext context;
    if (!settings.reference.empty()) {
      fmt::print("{}\n{}; {}\n\n", trf("luz bench radiosity: {} against {}, hemicube {}, up to {:g} s each", path,
                                       settings.reference, settings.hemicube_res, settings.seconds),
                 cpu_model(), gl_version_string());
      return run_error_curve(settings, loaded);
    }
    fmt::print("{}\n{}; {}\n\n", trf("luz bench radiosity: {}, hemicube {}, until unshot < {:g} of the emitted "
                                       "power or {:g} s", path, settings.hemicube_res, settings.converge,
                                       settings.seconds),
               cpu_model(), gl_version_string());
    fmt::print("{}", markdown_row({tr("form factors"), tr("patches"), tr("shots"), tr("shots/s"), tr("draw ms"),
                                   tr("read ms"), tr("accumulate ms"), tr("update ms"),
                                   trf("time to {:g}%", 100.0 * settings.converge), tr("unshot at the end")}));
    fmt::print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (const FormFactorMethod method : {FormFactorMethod::rays, FormFactorMethod::hemicube}) {
      for (const int target : settings.patches) {
        const float size = PatchMesh::patch_size_for(loaded.scene, size_t(target));
        PatchMesh mesh = PatchMesh::build(loaded.scene, size);  // every element shoots
        RadiosityOptions options;
        options.hemicube_res = settings.hemicube_res;
        options.hemicube_passes = settings.hemicube_passes;
        options.hemicube_sums = settings.hemicube_sums;
        options.converge = settings.converge;
        options.form_factors = method;
        options.meshing = Meshing::uniform;  // shots per second at the patch count asked for
        ProgressiveSolver solver(loaded.scene, mesh, options);
        RowTimes sum;
        double update = 0.0;
        const auto start = std::chrono::steady_clock::now();
        double elapsed = 0.0;
        while (elapsed < settings.seconds && solver.step()) {
          sum.draw += solver.last_row_times().draw;
          sum.read += solver.last_row_times().read;
          sum.accumulate += solver.last_row_times().accumulate;
          update += solver.last_update_seconds();
          elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
        const double shots = std::max(1, solver.shots());
        const bool converged = solver.unshot_fraction() < double(settings.converge);
        fmt::print("| {} | {} | {} | {:.0f} | {:.2f} | {:.3f} | {:.3f} | {:.3f} | {} | {:.2f}% |\n",
                   method_label(method, settings), mesh.size(), solver.shots(), solver.shots() / elapsed,
                   1e3 * sum.draw / shots,
                   1e3 * sum.read / shots, 1e3 * sum.accumulate / shots, 1e3 * update / shots,
                   converged ? fmt::format("{:.1f} s", elapsed) : std::string(tr("not within the cap")),
                   100.0 * solver.unshot_fraction());
        std::fflush(stdout);
      }
    }
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
