// luz: the single command. `luz [SCENE]` opens the viewer; `luz render` makes one picture
// headless. Exit codes: 0 success, 1 bad input, 2 usage error.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/bench_command.h"
#include "app/render_command.h"
#include "app/resources.h"
#include "app/viewer.h"
#include "gl/window_context.h"

namespace {

using luz::app::RenderSettings;

void add_render_flags(CLI::App& render, RenderSettings& settings) {
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
}

// Flags of --model radiosity only; returned so main() can tell which were given.
std::vector<CLI::Option*> add_radiosity_flags(CLI::App& render, RenderSettings& settings) {
  luz::RadiosityOptions& r = settings.radiosity;
  const luz::RadiosityOptions defaults;  // the help quotes the struct's defaults, never its own
  std::vector<CLI::Option*> flags;
  CLI::Option* shots = render.add_option_function<int>(
      "--shots", [&r](int n) { r.max_shots = n; r.converge = 0.0f; },
      "Radiosity: stop after N shots (lights included)")->check(CLI::PositiveNumber);
  CLI::Option* converge = render.add_option_function<float>(
      "--converge", [&r](float eps) { r.converge = eps; r.max_shots = 0; },
      fmt::format("Radiosity: stop when the unshot power is below EPS x the emitted power "
                  "(default {})", defaults.converge))
      ->check(CLI::Range(1e-9, 1.0));
  shots->excludes(converge);
  flags = {shots, converge};
  flags.push_back(render.add_option("--patch-size", r.patch_size,
                                    fmt::format("Radiosity: longest patch edge, metres (default: "
                                                "about {} patches)", defaults.target_patches))
                      ->check(CLI::PositiveNumber));
  flags.push_back(render.add_option_function<int>(
      "--hemicube-res",
      [&r](int n) {
        if (n % 2 != 0) throw CLI::ValidationError("--hemicube-res", "must be even");
        r.hemicube_res = n;
      },
      fmt::format("Radiosity: hemicube resolution, pixels across its top face ({} .. {}, even; "
                  "default {})", luz::kMinHemicubeRes, luz::kMaxHemicubeRes, defaults.hemicube_res))
      ->check(CLI::Range(luz::kMinHemicubeRes, luz::kMaxHemicubeRes)));
  flags.push_back(render.add_flag("--ambient-estimate", r.ambient_estimate,
                                  "Radiosity: add Cohen's ambient term for the light not yet shot"));
  flags.push_back(render.add_flag("--flat-patches", r.flat_patches,
                                  "Radiosity: one colour per patch instead of Gouraud shading"));
  flags.push_back(render.add_flag("--outlines", r.outlines, "Radiosity: draw the patch edges"));
  flags.push_back(render.add_option("--csv", settings.csv,
                                    "Radiosity: write the unshot power after every shot to this CSV file"));
  return flags;
}

// No display: say so and do what the viewer would have shown, as a file.
int render_without_display(const std::string& scene) {
  const std::string out = std::filesystem::path(scene).stem().string() + ".png";
  fmt::print(stderr, "luz: no display, so no window; rendering {} headless to {} instead "
                     "(see `luz render --help`)\n", scene, out);
  RenderSettings settings;
  settings.scene = scene;
  settings.out = out;
  return luz::app::run_render(settings);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Luz: an interactive lab for realistic image synthesis (\"Síntesis realista de imágenes\").\n"
               "With no subcommand, opens the viewer on SCENE (default: the Cornell box that ships)."};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", "luz " LUZ_VERSION);
  app.footer("Exit codes: 0 success, 1 bad input (the message names the file), 2 usage error.");
  std::string viewer_scene;
  app.add_option("SCENE", viewer_scene, "glTF scene for the viewer");

  RenderSettings settings;
  CLI::App* render = app.add_subcommand("render", "Render one picture headless (OSMesa, no display needed)");
  add_render_flags(*render, settings);
  const std::vector<CLI::Option*> radiosity_flags = add_radiosity_flags(*render, settings);

  // `luz bench radiosity`: one subcommand per benchmark under `bench`.
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks (timings, headless)");
  bench->require_subcommand(1);
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

  if (bench_radiosity->parsed()) return luz::app::run_radiosity_bench(radiosity_bench);
  if (render->parsed()) {
    for (const CLI::Option* flag : radiosity_flags)
      if (flag->count() > 0) settings.radiosity_flags.push_back(flag->get_name());
    return luz::app::run_render(settings);
  }

  const std::string scene = viewer_scene.empty() ? luz::app::default_scene().string() : viewer_scene;
  if (!luz::gl::WindowContext::display_available()) return render_without_display(scene);
  return luz::app::run_viewer(scene);
}
