// luz: the single command. `luz [SCENE]` opens the viewer; `luz render` makes one picture
// headless. Exit codes: 0 success, 1 bad input, 2 usage error.
#include <cstdlib>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/bench_command.h"
#include "app/render_command.h"
#include "app/solvers_command.h"
#include "app/resources.h"
#include "app/script.h"
#include "app/viewer.h"
#include "core/error.h"
#include "raytracing/sampling.h"
#include "gl/offscreen_context.h"
#include "gl/window_context.h"

namespace {

using luz::app::RenderSettings;

// Slide 19's "other possibilities" of the local models: each a switch of LocalOptions, off unless
// its flag is given (distance attenuation and spot distributions belong to the scene's lights).
// Returns them so main() can tell which were given: they are a usage error with the other models.
std::vector<CLI::Option*> add_effect_flags(CLI::App& render, luz::LocalOptions& local) {
  const size_t before = render.get_options().size();
  const std::map<std::string, luz::FogMode> fog_modes = {{"linear", luz::FogMode::linear},
                                                         {"exponential", luz::FogMode::exponential}};
  render.add_option("--fog", local.fog.mode, "Atmospheric attenuation (depth cueing) toward the fog colour")
      ->transform(CLI::CheckedTransformer(fog_modes, CLI::ignore_case))
      ->option_text("linear|exponential");
  render.add_option_function<std::string>(
      "--fog-colour",
      [&local](const std::string& text) {
        if (!luz::app::parse_rgb(text, local.fog.colour))
          throw CLI::ValidationError("--fog-colour", "expected R,G,B radiance, three numbers >= 0, e.g. 0.3,0.3,0.35");
      },
      "Fog colour as R,G,B radiance (default 0.25,0.27,0.3)");
  render.add_option("--fog-near", local.fog.near, "Linear fog: no fog closer than D metres (default 2)")
      ->check(CLI::NonNegativeNumber);
  render.add_option("--fog-far", local.fog.far, "Linear fog: only fog beyond D metres (default 20)")
      ->check(CLI::NonNegativeNumber);
  render.add_option("--fog-density", local.fog.density, "Exponential fog: f = exp(-K d), K per metre (default 0.1)")
      ->check(CLI::NonNegativeNumber);
  render.add_flag("--shadows", local.shadows.on, "Blocking of the sources by occlusion (S_i), with shadow maps");
  render.add_option("--shadow-bias", local.shadows.constant_bias, "Constant shadow bias in metres (default 0.002)")
      ->check(CLI::NonNegativeNumber);
  render.add_option("--shadow-slope-bias", local.shadows.slope_bias,
                    "Slope-scaled shadow bias, texels per unit of tan(theta) (default 1)")
      ->check(CLI::NonNegativeNumber);
  render.add_option("--shadow-normal-offset", local.shadows.normal_offset,
                    "Shadow lookup moved this many texels along the normal (default 1)")
      ->check(CLI::NonNegativeNumber);
  render.add_option("--shadow-map-size", local.shadows.map_size, "Texels per side of each shadow map (default 1024)")
      ->check(CLI::Range(16, 8192));
  render.add_flag("--transparency", local.transparency.on, "Non-refractive transparency: I + kt * what lies behind");
  render.add_flag("--reflection-map", local.reflection.on,
                  "Reflection maps: kr * Ir from a cube map around each object with kr > 0");
  render.add_option("--reflection-map-size", local.reflection.resolution, "Texels per side of each cube face (default 256)")
      ->check(CLI::Range(8, 4096));
  render.add_option("--environment", local.reflection.environment,
                    "Equirectangular image of the surroundings, seen in reflections where no object is");
  const std::vector<CLI::Option*> all = render.get_options();
  return {all.begin() + std::ptrdiff_t(before), all.end()};
}

// Returns the flags of slide 19's switches (see add_effect_flags).
std::vector<CLI::Option*> add_render_flags(CLI::App& render, RenderSettings& settings) {
  render.add_option("SCENE", settings.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
  render.add_option("--model", settings.model, "Illumination model")
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(luz::app::kModels), std::end(luz::app::kModels))))
      ->capture_default_str();
  render.add_option("--out", settings.out, "Output image: .png (sRGB, exposed) or .exr (linear radiance)")
      ->required();
  render.add_option_function<std::string>(
      "--size",
      [&settings](const std::string& text) {
        if (!luz::app::parse_size(text, settings.width, settings.height))
          throw CLI::ValidationError("--size", "expected WxH with 1 <= W, H <= 16384, e.g. 800x600");
      },
      "Image size WxH (default: 600 pixels high, the camera's aspect ratio)");
  render.add_option("--camera", settings.camera, "Scene camera by name or index (default: the first)");
  render.add_option("--exposure", settings.exposure, "Exposure in EV for PNG output (default: the scene's)");
  auto switch_off = [&render](const char* flag, bool& term, const char* help) {
    render.add_flag_callback(flag, [&term] { term = false; }, help);
  };
  switch_off("--no-ambient", settings.local.ambient, "Switch off the ambient term I_A = Ia*ka");
  switch_off("--no-diffuse", settings.local.diffuse, "Switch off the diffuse term I_D = IL*kd*cos(theta)");
  switch_off("--no-specular", settings.local.specular, "Switch off the specular term I_S = IL*ks*cos^n(alpha)");
  switch_off("--no-emission", settings.local.emission, "Do not show the emitted radiance Le of emissive surfaces");
  switch_off("--no-textures", settings.local.textures, "Ignore baseColorTexture");
  render.add_flag("--blinn", settings.local.blinn, "Blinn's half vector N.H instead of Phong's R.V");
  render.add_flag("-q,--quiet", settings.quiet, "Print nothing on success");
  render.add_option_function<std::string>(
      "--gl", [](const std::string& name) { luz::gl::set_default_backend(*luz::gl::parse_backend(name)); },
      "Headless OpenGL: egl or osmesa (default: $LUZ_GL, else EGL when it works, else OSMesa)")
      ->check(CLI::IsMember({"egl", "osmesa", "auto"}));
  return add_effect_flags(render, settings.local);
}

// The tracer's flags (--model whitted). Returns them so main() can tell which were given: they
// are a usage error with another model.
std::vector<CLI::Option*> add_whitted_flags(CLI::App& render, RenderSettings& settings) {
  luz::rt::WhittedOptions& w = settings.whitted;
  std::vector<CLI::Option*> flags;
  flags.push_back(render.add_option("--depth", w.max_depth,
      "whitted/hybrid: maximum ray depth as on slide 26 (primary rays have depth 1; 1 or 0: no "
      "reflected or transmitted rays)")->check(CLI::Range(0, 64))->capture_default_str());
  flags.push_back(render.add_option("--spp", w.spp,
      "whitted/hybrid: samples per pixel on a jittered sqrt(N) x sqrt(N) grid; a square: 1, 4, 9, 16, ...")
      ->check(CLI::Validator([](std::string& text) {
        int n = 0;
        if (!CLI::detail::lexical_cast(text, n) || !luz::rt::is_square(n) || n > 4096)
          return std::string("expected a square number of samples: 1, 4, 9, 16, ... (at most 4096)");
        return std::string();
      }, "SQUARE"))->capture_default_str());
  flags.push_back(render.add_flag_callback("--adaptive", [&w] { w.sampling = luz::rt::Sampling::adaptive; },
      "whitted/hybrid: Whitted's adaptive supersampling (pixel corners, subdivided where they differ; instead of --spp)"));
  flags.push_back(render.add_flag("--fresnel", w.fresnel,
      "whitted/hybrid: Fresnel's reflectance F splits kt: reflection kr + kt*F, transmission kt*(1-F)"));
  flags.push_back(render.add_option("--light-samples", w.light_samples,
      "whitted/hybrid: shadow rays per emissive triangle (1: its centroid; N: soft shadows)")
      ->check(CLI::Range(1, 1024))->capture_default_str());
  flags.push_back(render.add_flag("--brute-force", w.brute_force,
      "whitted/hybrid: test every ray against every triangle instead of Embree's BVH (counts the tests)"));
  flags.push_back(render.add_flag_callback("--no-shadows", [&w] { w.shadows = false; },
      "whitted/hybrid: no shadow rays (every light unoccluded)"));
  flags.push_back(render.add_option_function<std::string>(
      "--ray-tree",
      [&settings](const std::string& text) {
        int x = 0, y = 0;
        if (!luz::app::parse_pixel(text, x, y))
          throw CLI::ValidationError("--ray-tree", "expected a pixel X,Y, e.g. 320,240");
        settings.ray_tree = std::make_pair(x, y);
      },
      "whitted/hybrid: write pixel X,Y's ray tree as JSON beside the image, to OUT-STEM.ray-tree.json"));
  return flags;
}

// Flags of --model radiosity only; returned so main() can tell which were given.
std::vector<CLI::Option*> add_radiosity_flags(CLI::App& render, RenderSettings& settings) {
  luz::RadiosityOptions& r = settings.radiosity;
  const luz::RadiosityOptions defaults;  // the help quotes the struct's defaults, never its own
  std::vector<CLI::Option*> flags;
  CLI::Option* shots = render.add_option_function<int>(
      "--shots", [&r](int n) { r.max_shots = n; r.converge = 0.0f; },
      "radiosity/hybrid: stop after N shots (lights included)")
      ->check(CLI::Range(1, std::numeric_limits<int>::max()));  // PositiveNumber prints DBL_MAX's 309 digits
  CLI::Option* converge = render.add_option_function<float>(
      "--converge", [&r](float eps) { r.converge = eps; r.max_shots = 0; },
      fmt::format("radiosity/hybrid: stop when the unshot power is below EPS x the emitted power "
                  "(default {})", defaults.converge))
      ->check(CLI::Range(1e-9, 1.0));
  shots->excludes(converge);
  flags = {shots, converge};
  flags.push_back(render.add_option("--patch-size", r.patch_size,
                                    fmt::format("radiosity/hybrid: longest patch edge, metres (default: "
                                                "about {} patches)", defaults.target_patches))
                      ->check(CLI::PositiveNumber));
  flags.push_back(render.add_option_function<int>(
      "--hemicube-res",
      [&r](int n) {
        if (n % 2 != 0) throw CLI::ValidationError("--hemicube-res", "must be even");
        r.hemicube_res = n;
      },
      fmt::format("radiosity/hybrid: hemicube resolution, pixels across its top face ({} .. {}, even; "
                  "default {})", luz::kMinHemicubeRes, luz::kMaxHemicubeRes, defaults.hemicube_res))
      ->check(CLI::Range(luz::kMinHemicubeRes, luz::kMaxHemicubeRes)));
  flags.push_back(render.add_flag("--ambient-estimate", r.ambient_estimate,
                                  "radiosity/hybrid: add Cohen's ambient term for the light not yet shot"));
  flags.push_back(render.add_flag("--flat-patches", r.flat_patches,
                                  "radiosity: one colour per patch instead of Gouraud shading"));
  flags.push_back(render.add_flag("--outlines", r.outlines, "radiosity: draw the patch edges"));
  flags.push_back(render.add_option("--csv", settings.csv,
                                    "radiosity/hybrid: write the unshot power after every shot to this CSV file"));
  return flags;
}

// No display: the viewer cannot open; `luz render` makes the same pictures without one.
int no_display(const std::string& scene) {
  fmt::print(stderr, "luz: no display to open the viewer on (DISPLAY and WAYLAND_DISPLAY are unset "
                     "or unreachable).\nluz: for pictures without a display use `luz render`, e.g.\n"
                     "  luz render {} --model phong --out picture.png\n(see `luz render --help`)\n", scene);
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Luz: an interactive lab for realistic image synthesis (\"Síntesis realista de imágenes\").\n"
               "With no subcommand, opens the viewer on SCENE (default: the Cornell box that ships)."};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", "luz " LUZ_VERSION);
  app.footer("Exit codes: 0 success, 1 bad input (the message names the file), 2 usage error.");
  luz::app::ViewerSettings viewer;
  std::string script_file;
  app.add_option("SCENE", viewer.scene, "glTF scene for the viewer");
  app.add_option("--script", script_file,
                 "Run the viewer from a script of commands (key, click, screenshot, ...; see README)");
  app.add_option_function<std::string>(
      "--size",
      [&viewer](const std::string& text) {
        if (!luz::app::parse_size(text, viewer.width, viewer.height))
          throw CLI::ValidationError("--size", "expected WxH with 1 <= W, H <= 16384, e.g. 1280x720");
      },
      "Viewer window size WxH");

  RenderSettings settings;
  CLI::App* render = app.add_subcommand("render", "Render one picture headless (OSMesa, no display needed)");
  render->footer("--model hybrid (slides 41-43) takes the whitted flags and the radiosity flags "
                 "(all but --flat-patches and --outlines): the diffuse part of every hit from the "
                 "radiosity solution, highlights, kr*Ir and kt*It from rays, no ambient term.");
  const std::vector<CLI::Option*> effect_flags = add_render_flags(*render, settings);
  const std::vector<CLI::Option*> whitted_flags = add_whitted_flags(*render, settings);
  const std::vector<CLI::Option*> radiosity_flags = add_radiosity_flags(*render, settings);

  luz::app::SolversSettings solvers_settings;
  CLI::App* solvers = app.add_subcommand(
      "solvers", "Slide 36: Jacobi, Gauss-Seidel and Southwell on the full form-factor matrix, beside "
                 "slide 39's shooting; writes their convergence curves");
  solvers->add_option("SCENE", solvers_settings.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
  solvers->add_option("--csv", solvers_settings.csv,
                      "Curves as CSV: method,iteration,rows,seconds,residual,error")->required();
  solvers->add_option("--png", solvers_settings.png, "Plot of the curves (residual and error against rows)");
  CLI::Option* solver_patch_size = solvers->add_option("--patch-size", solvers_settings.patch_size,
                                                       "Longest patch edge, metres")->check(CLI::PositiveNumber);
  CLI::Option* solver_patches = solvers->add_option("--patches", solvers_settings.patches,
      fmt::format("About this many patches (at most {})", luz::app::kMaxSolverPatches))
      ->check(CLI::PositiveNumber)->capture_default_str();
  solver_patch_size->excludes(solver_patches);
  solvers->add_option_function<int>(
      "--hemicube-res",
      [&solvers_settings](int n) {
        if (n % 2 != 0) throw CLI::ValidationError("--hemicube-res", "must be even");
        solvers_settings.hemicube_res = n;
      },
      fmt::format("Hemicube resolution ({} .. {}, even; default {})", luz::kMinHemicubeRes,
                  luz::kMaxHemicubeRes, solvers_settings.hemicube_res))
      ->check(CLI::Range(luz::kMinHemicubeRes, luz::kMaxHemicubeRes));
  solvers->add_option("--iterations", solvers_settings.iterations,
                      "Jacobi and Gauss-Seidel sweeps; Southwell and shooting use as many rows")
      ->check(CLI::Range(1, 10000))->capture_default_str();
  solvers->add_flag("-q,--quiet", solvers_settings.quiet, "Print nothing on success");

  luz::app::WhittedBenchSettings bench_settings;
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks (timings, never pass/fail)");
  bench->require_subcommand(1);
  CLI::App* bench_whitted = bench->add_subcommand("whitted", "The Whitted tracer against the same rays traced bare through Embree");
  luz::app::add_bench_flags(*bench_whitted, bench_settings);
  luz::app::RadiosityBenchSettings radiosity_bench;
  CLI::App* bench_radiosity = bench->add_subcommand(
      "radiosity", "Shots/s and time to converge on the Cornell box at about 1k, 4k, 16k, 64k patches");
  bench_radiosity->add_option("--scene", radiosity_bench.scene, "Scene (default: the Cornell box)");
  bench_radiosity->add_option("--patches", radiosity_bench.patches, "Target patch counts")
      ->capture_default_str();
  bench_radiosity->add_option("--hemicube-res", radiosity_bench.hemicube_res, "Hemicube resolution")
      ->check(CLI::Range(luz::kMinHemicubeRes, luz::kMaxHemicubeRes))->capture_default_str();
  bench_radiosity->add_option("--seconds", radiosity_bench.seconds, "Time cap per patch count")
      ->check(CLI::PositiveNumber)->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message
    return 2;
  }

  if (render->parsed()) {
    for (const CLI::Option* flag : whitted_flags)
      if (flag->count() > 0) settings.whitted_only_flags.push_back(flag->get_name());
    for (const CLI::Option* flag : radiosity_flags)
      if (flag->count() > 0) settings.radiosity_only_flags.push_back(flag->get_name());
    for (const CLI::Option* flag : effect_flags)
      if (flag->count() > 0) settings.local_only_flags.push_back(flag->get_name());
    return luz::app::run_render(settings);
  }
  if (solvers->parsed()) return luz::app::run_solvers(solvers_settings);
  if (bench_whitted->parsed()) return luz::app::run_bench_whitted(bench_settings);
  if (bench_radiosity->parsed()) return luz::app::run_radiosity_bench(radiosity_bench);

  if (viewer.scene.empty()) viewer.scene = luz::app::default_scene().string();
  if (!script_file.empty()) {  // a bad script is a usage error, found before any window opens
    try {
      viewer.script = luz::app::parse_script(script_file);
    } catch (const luz::Error& error) {
      fmt::print(stderr, "luz: {}\n", error.what());
      return 2;
    }
  }
  if (!luz::gl::WindowContext::display_available()) return no_display(viewer.scene);
  return luz::app::run_viewer(viewer);
}
