// `luz render`'s flags. The options' flags come from the options tables (options_tables.h):
// each row's flag, its help with the struct's default, its range and its check (a float must be
// finite: nan and inf are usage errors). The few flags that are not one number or switch (a
// colour, a file, a pixel) are written out below.
#include "app/cli/render_flags.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/common/i18n.h"
#include "app/common/model_registry.h"
#include "app/common/options_tables.h"
#include "app/cli/render_grid.h"
#include "app/common/numbers.h"
#include "gl/offscreen_context.h"

namespace luz::app {
namespace {

template <class Options>
std::string help_of(const OptionRow<Options>& row) {
  if (row.kind == OptionKind::on_off) return tr(row.help);
  return trf("{} ({}; default {})", tr(row.help), accepted_text(row, Wording::translated), default_text(row));
}

// One flag from a row, writing into `options`.
template <class Options>
CLI::Option* add_row(CLI::App& render, const OptionRow<Options>& row, Options& options) {
  if (row.kind == OptionKind::on_off) {
    const bool off = row.get(Options{}) != 0.0;  // the flag turns the default around
    return render.add_flag_callback(row.flag, [&row, &options, off] { row.set(options, off ? 0.0 : 1.0); },
                                    help_of(row));
  }
  CLI::Option* option = render.add_option_function<std::string>(
      row.flag,
      [&row, &options](const std::string& text) {
        // The sampling flags are shared by the tracers: the Whitted tracer's square --spp is its
        // render's check, since the path tracer takes any count.
        const bool shared = std::string_view(row.group) == "sampling";
        const std::optional<double> value = parse_value(row, text, !shared);
        if (!value) throw CLI::ValidationError(row.flag, trf("{}: expected {}", text, accepted_text(row, Wording::translated)));
        row.set(options, *value);
      },
      help_of(row));
  if (row.kind == OptionKind::choice) {
    std::string names;
    for (const char* c : row.choices) names += (names.empty() ? "" : "|") + std::string(c);
    option->type_name(names);
  } else {
    option->type_name(row.kind == OptionKind::integer ? "INT" : "NUMBER");
  }
  return option;
}

template <class Options>
void add_rows(CLI::App& render, std::span<const OptionRow<Options>> rows, Options& options, RenderFlags& flags) {
  for (const OptionRow<Options>& row : rows)
    if (row.flag) flags.grouped.push_back({row.group, add_row(render, row, options)});
}

}  // namespace

std::vector<CLI::Option*> add_path_flags(CLI::App& render, PathFlags& flags) {
  return {
      render.add_option("--seed", flags.seed,
                        tr("path: seed of the random numbers (the same seed gives the same picture)"))
          ->capture_default_str(),
      render.add_option("--error-out", flags.error_out,
                        tr("path: write the per-pixel standard error of the mean to this .exr")),
  };
}

RenderFlags add_render_flags(CLI::App& render, RenderSettings& settings) {
  RenderFlags flags;
  render.add_option(tr("SCENE"), settings.scene, tr("glTF 2.0 scene (.gltf or .glb)"))->required();
  render.add_option("--model", settings.model, tr("Illumination model, or 2 or 4 of them side by side (flat,phong)"))
      ->check(CLI::Validator([](std::string& text) { return model_option_problem(text); },
                             fmt::format("{{{}}}[,...]", model_names(","))))
      ->capture_default_str();
  render.add_option("--out", settings.out, tr("Output image: .png (sRGB, exposed) or .exr (linear radiance)"))->required();
  render.add_option_function<std::string>(
      "--size",
      [&settings](const std::string& text) {
        if (!parse_size(text, settings.width, settings.height))
          throw CLI::ValidationError("--size", tr("expected WxH with 1 <= W, H <= 16384, e.g. 800x600"));
      },
      tr("Image size WxH (default: 600 pixels high, the camera's aspect ratio)"));
  render.add_option("--camera", settings.camera, tr("Scene camera by name or index (default: the first)"));
  render.add_option_function<std::string>(
      "--exposure",
      [&settings](const std::string& text) {
        settings.exposure_auto = text == "auto";
        if (settings.exposure_auto) return;
        if (!is_number(text))
          throw CLI::ValidationError("--exposure", trf("{}: expected a finite number or auto", text));
        settings.exposure = std::stof(text);
      },
      tr("Exposure in EV for PNG output, or auto: the picture's log-average luminance shown as middle grey "
         "(default: the scene's)"))
      ->type_name("EV|auto");
  render.add_flag("-q,--quiet", settings.quiet, tr("Print nothing on success"));
  render.add_option_function<std::string>(
      "--gl", [](const std::string& name) { gl::set_default_backend(*gl::parse_backend(name)); },
      tr("Headless OpenGL: egl or osmesa (default: $LUZ_GL, else EGL when it works, else OSMesa)"))
      ->check(CLI::IsMember({"egl", "osmesa", "auto"}));

  add_rows(render, local_rows(), settings.local, flags);
  flags.grouped.push_back({"local", render.add_option_function<std::string>(
      "--fog-colour",
      [&settings](const std::string& text) {
        if (!parse_rgb(text, settings.local.fog.colour))
          throw CLI::ValidationError("--fog-colour", tr("expected R,G,B radiance, three numbers >= 0, e.g. 0.3,0.3,0.35"));
      },
      [] {
        const Rgb c = LocalOptions{}.fog.colour;
        return trf("Fog colour as R,G,B radiance (default {:g},{:g},{:g})", c.r, c.g, c.b);
      }())});
  flags.grouped.push_back({"local", render.add_option("--environment", settings.local.reflection.environment,
      tr("Equirectangular image of the surroundings, seen in reflections where no object is"))});

  add_rows(render, whitted_rows(), settings.whitted, flags);
  flags.grouped.push_back({"whitted", render.add_option_function<std::string>(
      "--ray-tree",
      [&settings](const std::string& text) {
        int x = 0, y = 0;
        if (!parse_pixel(text, x, y)) throw CLI::ValidationError("--ray-tree", tr("expected a pixel X,Y, e.g. 320,240"));
        settings.ray_tree = std::make_pair(x, y);
      },
      tr("whitted/hybrid: write pixel X,Y's ray tree as JSON beside the image, to OUT-STEM.ray-tree.json"))});

  for (CLI::Option* option : add_path_flags(render, settings.path)) flags.grouped.push_back({"path", option});
  flags.grouped.push_back({"time", render.add_option("--time", settings.seconds,
      tr("path: render passes of one sample per pixel until SECONDS are up (with --spp: at most that "
         "many samples); radiosity/hybrid: stop shooting when SECONDS of solving are up, if --shots or "
         "--converge has not stopped it first (0.001 .. 10000000)"))
      ->type_name("SECONDS")->check(CLI::Range(0.001, 1e7).description(""))});

  add_rows(render, radiosity_rows(), settings.radiosity, flags);
  flags.grouped.push_back({"radiosity", render.add_option("--csv", settings.csv,
      tr("radiosity/hybrid: write the unshot power after every shot to this CSV file"))});
  // One stopping rule: a number of shots or a threshold.
  CLI::Option* shots = render.get_option("--shots");
  shots->excludes(render.get_option("--converge"));
  return flags;
}

void note_given_flags(const RenderFlags& flags, RenderSettings& settings) {
  for (const RenderFlags::Grouped& g : flags.grouped)
    if (g.option->count() > 0) settings.given_flags.push_back({g.option->get_name(), g.group});
}

}  // namespace luz::app
