// `luz render`'s flags. The options' flags come from the registry's options tables
// (option_row.h): each row's flag, its help with the struct's default, its range and its check
// (a float must be finite: nan and inf are usage errors). The few flags that are not one number,
// switch or file row (a colour, an image, a pixel, a CSV) are written out below.
#include "app/cli/render_flags.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/common/i18n.h"
#include "app/common/model_registry.h"
#include "app/common/options_tables.h"
#include "app/common/option_values.h"
#include "app/cli/render_grid.h"
#include "app/common/numbers.h"
#include "gl/offscreen_context.h"

namespace luz::app {
namespace {

std::string help_of(const OptionTable& table, const OptionRow& row) {
  if (row.kind == OptionKind::on_off) return tr(row.help);
  return trf("{} ({}; default {})", tr(row.help), accepted_text(row, Wording::translated), default_text(table, row));
}

// A flag's rows: one, or one in each table that shares the flag (the tracers' --spp).
struct FlagRow {
  const OptionTable* table;
  const OptionRow* row;
};

// One flag from its rows, writing into each row's struct in `settings`. The first row gives the
// help, the kind and the group (a shared flag's rows agree on them). A shared flag's rule (the
// Whitted tracer's square --spp) is its model's render's check, since another model takes any
// value in the range.
CLI::Option* add_flag(CLI::App& render, std::vector<FlagRow> rows, RenderSettings& settings) {
  const FlagRow first = rows.front();
  if (first.row->kind == OptionKind::file)
    return render
        .add_option_function<std::string>(
            first.row->flag,
            [rows, &settings](const std::string& text) {
              for (const FlagRow& r : rows) r.row->set_text(options_of(settings, *r.table), text);
            },
            tr(first.row->help))
        ->type_name("FILE");
  if (first.row->kind == OptionKind::on_off) {
    const bool off = first.row->get(first.table->defaults()) != 0.0;  // the flag turns the default around
    return render.add_flag_callback(
        first.row->flag,
        [rows, &settings, off] {
          for (const FlagRow& r : rows) r.row->set(options_of(settings, *r.table), off ? 0.0 : 1.0);
        },
        help_of(*first.table, *first.row));
  }
  CLI::Option* option = render.add_option_function<std::string>(
      first.row->flag,
      [rows, &settings](const std::string& text) {
        for (const FlagRow& r : rows) {
          const std::optional<double> value = parse_value(*r.row, text, rows.size() == 1);
          if (!value)
            throw CLI::ValidationError(r.row->flag, trf("{}: expected {}", text, accepted_text(*r.row, Wording::translated)));
          r.row->set(options_of(settings, *r.table), *value);
        }
      },
      help_of(*first.table, *first.row));
  if (first.row->kind == OptionKind::choice) {
    std::string names;
    for (const char* c : first.row->choices) names += (names.empty() ? "" : "|") + std::string(c);
    option->type_name(names);
  } else {
    option->type_name(first.row->kind == OptionKind::integer ? "INT" : "NUMBER");
  }
  return option;
}

// The flags of a table's rows, in its order; a flag a table already declared (shared) is left.
void add_rows(CLI::App& render, const OptionTable& table, RenderSettings& settings, RenderFlags& flags) {
  for (const OptionRow& row : table.rows) {
    if (!row.flag || render.get_option_no_throw(row.flag)) continue;
    std::vector<FlagRow> rows = {{&table, &row}};
    for (const OptionTable* other : option_tables())
      for (const OptionRow& r : other->rows)
        if (other != &table && r.flag && std::string_view(r.flag) == row.flag) rows.push_back({other, &r});
    flags.grouped.push_back({row.group, add_flag(render, rows, settings)});
  }
}

}  // namespace

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

  // The shared options tables' rows, each beside the flags that go with its table, then the
  // models' own tables.
  add_rows(render, local_table(), settings, flags);
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

  add_rows(render, whitted_table(), settings, flags);
  flags.grouped.push_back({"whitted", render.add_option_function<std::string>(
      "--ray-tree",
      [&settings](const std::string& text) {
        int x = 0, y = 0;
        if (!parse_pixel(text, x, y)) throw CLI::ValidationError("--ray-tree", tr("expected a pixel X,Y, e.g. 320,240"));
        settings.ray_tree = std::make_pair(x, y);
      },
      tr("whitted/hybrid: write pixel X,Y's ray tree as JSON beside the image, to OUT-STEM.ray-tree.json"))});

  // The models' own tables (the path tracer's --seed and --error-out) beside the tracers' flags
  // they share (--spp, --depth), before --time, which the path tracer and radiosity take.
  for (const OptionTable* table : option_tables())
    if (table != &radiosity_table()) add_rows(render, *table, settings, flags);
  flags.grouped.push_back({"time", render.add_option("--time", settings.seconds,
      tr("path: render passes of one sample per pixel until SECONDS are up (with --spp: at most that "
         "many samples); radiosity/hybrid: stop shooting when SECONDS of solving are up, if --shots or "
         "--converge has not stopped it first (0.001 .. 10000000)"))
      ->type_name("SECONDS")->check(CLI::Range(0.001, 1e7).description(""))});

  add_rows(render, radiosity_table(), settings, flags);
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
