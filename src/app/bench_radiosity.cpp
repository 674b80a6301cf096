// `luz bench radiosity`: shots per second and time to converge on the Cornell box at several
// patch counts, with each shot split into drawing the hemicube, reading it back, accumulating
// the form factors and updating the unshot values (slide 39's loop).
#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "app/bench_command.h"
#include "app/resources.h"
#include "core/error.h"
#include "gl/functions.h"
#include "gl/offscreen_context.h"
#include "io/gltf_loader.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/shooting.h"

namespace luz::app {
namespace {

std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

}  // namespace

int run_radiosity_bench(const RadiosityBenchSettings& settings) {
  try {
    const std::string path = settings.scene.empty() ? default_scene().string() : settings.scene;
    const io::LoadedScene loaded = io::load_gltf(path);
    gl::OffscreenContext context;
    fmt::print("luz bench radiosity: {}, hemicube {}, until unshot < {:g} of the emitted power or "
               "{:g} s\n{}; {}\n\n", path, settings.hemicube_res, settings.converge,
               settings.seconds, cpu_model(), gl_version_string());
    fmt::print("| patches | shots | shots/s | draw ms | read ms | accumulate ms | update ms | "
               "time to {:g}% | unshot at the end |\n", 100.0 * settings.converge);
    fmt::print("| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (const int target : settings.patches) {
      const float size = PatchMesh::patch_size_for(loaded.scene, size_t(target));
      const PatchMesh mesh = PatchMesh::build(loaded.scene, size);
      RadiosityOptions options;
      options.hemicube_res = settings.hemicube_res;
      options.converge = settings.converge;
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
      fmt::print("| {} | {} | {:.0f} | {:.2f} | {:.3f} | {:.3f} | {:.3f} | {} | {:.2f}% |\n",
                 mesh.size(), solver.shots(), solver.shots() / elapsed, 1e3 * sum.draw / shots,
                 1e3 * sum.read / shots, 1e3 * sum.accumulate / shots, 1e3 * update / shots,
                 converged ? fmt::format("{:.1f} s", elapsed) : std::string("not within the cap"),
                 100.0 * solver.unshot_fraction());
      std::fflush(stdout);
    }
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
