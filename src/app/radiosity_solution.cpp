#include "app/radiosity_solution.h"

#include <cmath>

#include "app/radiosity_command.h"
#include "app/radiosity_view.h"
#include "gl/offscreen_context.h"
#include "radiosity/shooting.h"

namespace luz::app {

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
    // The PNG multiplies by 2^exposure: divided out here, the ramp shows heat_colour()'s colours.
    RadianceField heat = unshot_heat_map(solver);
    const float undo = std::exp2(-extent.exposure);
    for (Rgb& c : heat.patch) c *= undo;
    for (Rgb& c : heat.vertex) c *= undo;
    solution->heat_map = std::move(heat);
  }
  return solution;
}

}  // namespace luz::app
