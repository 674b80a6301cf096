#include "app/models/hybrid/render_hybrid.h"

#include <optional>

#include "app/models/radiosity/render_radiosity.h"
#include "gl/offscreen_context.h"
#include "hybrid/radiosity_diffuse.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/shooting.h"
#include "radiosity/vertex_colours.h"

namespace luz::app {

Rendered render_hybrid(const Scene& scene, const Camera& camera, int width, int height,
                            const RenderSettings& settings) {
  check_square_spp(settings);  // before the solve, not after it
  // The view-independent part: radiosity, solved as `--model radiosity` solves it.
  if (const RadiositySolution* shared = settings.radiosity_solution.get()) {
    const hybrid::RadiosityDiffuse diffuse(shared->mesh, shared->radiance);
    return render_whitted(scene, camera, width, height, settings, &diffuse);
  }
  const RadiosityOptions options = radiosity_options(settings);
  PatchMesh mesh = PatchMesh::build(scene, options);
  std::optional<hybrid::RadiosityDiffuse> diffuse;
  {
    gl::OffscreenContext context;  // the hemicubes draw through GL; released before tracing
    ProgressiveSolver solver(scene, mesh, options);
    run_radiosity_solver(solver, settings);
    diffuse.emplace(mesh, RadianceField::of(solver));
  }
  // The view-dependent part: rays, with the diffuse part of every hit read from radiosity.
  return render_whitted(scene, camera, width, height, settings, &*diffuse);
}

}  // namespace luz::app
