// The catalogue: one line per model. A model brings its folder: its headless render
// (render_NAME.*), its viewer view (NAME_view.*) and, when it has options of its own, its options
// table; its line here names the flag groups and the options tables it takes and its own script
// verbs. The order is the keys', the panel's and --help's.
#include "app/common/model_registry.h"

#include <fmt/format.h>

#include "app/models/hybrid/hybrid_view.h"
#include "app/common/i18n.h"
#include "app/common/options_tables.h"
#include "app/models/local/local_view.h"
#include "app/models/path/path_options.h"
#include "app/models/path/path_view.h"
#include "app/models/radiosity/render_radiosity.h"
#include "app/models/radiosity/radiosity_view.h"
#include "app/cli/render_flags.h"
#include "app/models/hybrid/render_hybrid.h"
#include "app/models/local/render_local.h"
#include "app/models/path/render_path.h"
#include "app/models/whitted/render_whitted.h"
#include "app/models/whitted/whitted_view.h"
#include "gl/offscreen_context.h"

namespace luz::app {
namespace {

// The flag groups each model accepts (render_flags.h). Slide 19's switches belong to the local
// models; the hybrid takes the tracer's and the solver's, but not radiosity's display switches.
// Radiosity has no lights' terms to switch, only the texture its patches' reflectance reads; in
// the hybrid its solution is the diffuse part, holding the emitted light, with no ambient term.
constexpr const char* local_flags[] = {"terms", "ambient-emission", "textures", "local"};
constexpr const char* whitted_flags[] = {"terms", "ambient-emission", "textures", "whitted", "sampling"};
constexpr const char* radiosity_flags[] = {"textures", "radiosity", "radiosity-display", "time"};
constexpr const char* hybrid_flags[] = {"terms", "textures", "whitted", "sampling", "radiosity", "time"};
// The path tracer solves slide 14's equation: the lecture's term switches do not apply to it.
constexpr const char* path_flags[] = {"sampling", "path", "time"};

// The options tables each model takes: the local terms' switches are read by every model that
// draws a texture or a term; the hybrid takes both the tracer's and the solver's.
constexpr OptionTableOf local_options[] = {local_table};
constexpr OptionTableOf whitted_options[] = {local_table, whitted_table};
constexpr OptionTableOf radiosity_options[] = {local_table, radiosity_table};
constexpr OptionTableOf hybrid_options[] = {local_table, whitted_table, radiosity_table};
constexpr OptionTableOf path_options[] = {path_table};

template <Shading shading>
Rendered render_shaded(const Scene& scene, const Camera& camera, int width, int height, const RenderSettings& settings) {
  return render_local(shading, scene, camera, width, height, settings);
}

template <Shading shading>
std::unique_ptr<ModelView> local_view(ViewerServices& viewer) {
  return std::make_unique<LocalView>(viewer, shading);
}

Rendered render_radiosity_model(const Scene& scene, const Camera& camera, int width, int height,
                                const RenderSettings& settings) {
  gl::OffscreenContext context;
  return {render_radiosity(scene, camera, width, height, settings), "", std::nullopt};
}

std::shared_ptr<const RadiositySolution> solve_radiosity_model(const Scene& scene, const RenderSettings& settings) {
  return solve_radiosity(scene, settings);
}

Rendered render_whitted_model(const Scene& scene, const Camera& camera, int width, int height,
                              const RenderSettings& settings) {
  return render_whitted(scene, camera, width, height, settings);  // no GL needed
}

const ModelEntry table[] = {
    {"flat", N_("flat"), 1, N_("flat shading"), local_flags, local_options, render_shaded<Shading::flat>, local_view<Shading::flat>, {}, nullptr},
    {"gouraud", N_("Gouraud"), 2, N_("Gouraud shading"), local_flags, local_options, render_shaded<Shading::gouraud>,
     local_view<Shading::gouraud>, {}, nullptr},
    {"phong", N_("Phong"), 3, N_("Phong shading"), local_flags, local_options, render_shaded<Shading::phong>, local_view<Shading::phong>, {}, nullptr},
    {"whitted", N_("Whitted"), 4, N_("Whitted ray tracing (the raster view until Enter)"), whitted_flags, whitted_options,
     render_whitted_model, [](ViewerServices& v) -> std::unique_ptr<ModelView> { return std::make_unique<WhittedView>(v); },
     traced_verbs(), nullptr, traced_keys()},
    {"radiosity", N_("radiosity"), 5, N_("radiosity (progressive refinement; Space runs it)"), radiosity_flags, radiosity_options,
     render_radiosity_model,
     [](ViewerServices& v) -> std::unique_ptr<ModelView> { return std::make_unique<RadiosityView>(v); },
     radiosity_verbs(), solve_radiosity_model, radiosity_keys()},
    {"hybrid", N_("hybrid"), 6, N_("hybrid: radiosity + ray-traced highlights (the radiosity picture until Enter)"),
     hybrid_flags, hybrid_options, render_hybrid,
     [](ViewerServices& v) -> std::unique_ptr<ModelView> {
       return std::make_unique<HybridView>(v, static_cast<RadiosityView&>(v.view("radiosity")));
     },
     {}, nullptr},
    {"path", N_("path tracer"), 7, N_("path tracing of slide 14's equation, the reference (refines while the view stays)"),
     path_flags, path_options, render_path_model,
     [](ViewerServices& v) -> std::unique_ptr<ModelView> { return std::make_unique<PathView>(v); }, path_verbs(), nullptr},
};

const std::vector<std::string> comparisons[] = {
    {"flat", "gouraud", "phong", "whitted"},  // the local models against Whitted
    {"radiosity", "hybrid"},                  // radiosity against the hybrid
};

}  // namespace

const ModelEntry& reference_model() { return *find_model("path"); }

std::span<const std::vector<std::string>> lecture_comparisons() { return comparisons; }

std::span<const ModelEntry> catalogue() { return table; }

}  // namespace luz::app
