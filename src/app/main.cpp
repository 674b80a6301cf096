// luz: the single command. `luz [SCENE]` opens the viewer; `luz render` makes one picture
// headless. Exit codes: 0 success, 1 bad input, 2 usage error.
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli/bench/bench_command.h"
#include "app/cli/command_language.h"
#include "app/cli/compare_command.h"
#include "app/handout/handout_command.h"
#include "app/common/i18n.h"
#include "app/classroom/lesson.h"
#include "app/cli/man_page.h"
#include "app/common/model_registry.h"
#include "app/viewer/panes.h"
#include "app/cli/bench/bench_local.h"
#include "app/cli/render_command.h"
#include "app/cli/render_flags.h"
#include "app/viewer/viewer_settings.h"
#include "app/cli/solvers_command.h"
#include "app/script/script.h"
#include "app/viewer/viewer.h"
#include "core/error.h"
#include "core/resources.h"
#include "core/version.h"
#include "gl/window_context.h"

namespace {

using luz::app::RenderSettings;
using luz::i18n::tr;
using luz::i18n::trf;

// A float flag takes finite numbers only: CLI11 reads "nan" and "inf" as numbers.
const CLI::Validator finite_number(
    [](std::string& text) {
      double value = 0.0;
      if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value))
        return trf("{}: expected a finite number", text);
      return std::string();
    },
    "NUMBER");

// No display: the viewer cannot open; `luz render` makes the same pictures without one.
int no_display(const std::string& scene) {
  fmt::print(stderr, "{}", trf("luz: no display to open the viewer on (DISPLAY and WAYLAND_DISPLAY are "
                               "unset or unreachable).\nluz: for pictures without a display use `luz "
                               "render`, e.g.\n  luz render {} --model phong --out picture.png\n(see "
                               "`luz render --help`)\n", scene));
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  // The catalogue follows LC_ALL / LC_MESSAGES / LANG, and --lang over them. No setlocale():
  // the C locale keeps the decimal point that scenes and flags are read with.
  luz::app::choose_language(argc, argv);
  CLI::App app{tr("Luz: an interactive lab for realistic image synthesis (\"Síntesis realista de imágenes\").\n"
                  "With no subcommand, opens the viewer on SCENE (default: the Cornell box that ships).")};
  luz::app::speak_the_language(app);
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", luz::version_text(), tr("Display program version information and exit"));
  std::string man_page_file;  // the build writes luz.1 from the options declared here (hidden)
  app.add_option("--man-page", man_page_file)->group("");
  app.footer(tr("Exit codes: 0 success, 1 bad input (the message names the file), 2 usage error."));
  const auto lang = [](const std::string& name) { luz::i18n::set_language(*luz::i18n::parse_language(name)); };
  app.add_option_function<std::string>("--lang", lang, tr("Language of the messages and labels: es or en "
                                                          "(default: from LC_ALL, LC_MESSAGES, LANG)"))
      ->check(CLI::IsMember({"es", "en"}));
  luz::app::ViewerSettings viewer;
  std::string script_file;
  std::optional<std::string> lesson_file;
  app.add_option("--lesson", lesson_file, tr("Open a lesson (default: lessons/sintesis.json) at its first step"))
      ->expected(0, 1)->default_str("");
  app.add_option(tr("SCENE"), viewer.scene, tr("glTF scene for the viewer"));
  app.add_option("--script", script_file,
                 tr("Run the viewer from a script of commands (key, click, screenshot, ...; see README)"));
  app.add_option_function<std::string>(
      "--size",
      [&viewer](const std::string& text) {
        if (!luz::app::parse_size(text, viewer.width, viewer.height))
          throw CLI::ValidationError("--size", tr("expected WxH with 1 <= W, H <= 16384, e.g. 1280x720"));
      },
      tr("Viewer window size WxH"));

  app.add_option_function<std::string>(
      "--model",
      [&viewer](const std::string& text) {
        viewer.models = luz::app::split_model_list(text);
        if (const std::string problem = luz::app::pane_list_problem(viewer.models); !problem.empty())
          throw CLI::ValidationError("--model", text + ": " + problem);
      },
      tr("Viewer: the model shown, or 2 to 4 of them side by side, e.g. --model flat,gouraud,phong,whitted"));
  app.add_option_function<std::string>(
      "--ui-scale",
      [&viewer](const std::string& text) {
        double scale = 0.0;
        if (!CLI::detail::lexical_cast(text, scale) || !std::isfinite(scale) || scale < luz::app::kMinUiScale ||
            scale > luz::app::kMaxUiScale)
          throw CLI::ValidationError("--ui-scale", trf("{}: expected a size in {} .. {} (1: the default)", text,
                                                       luz::app::kMinUiScale, luz::app::kMaxUiScale));
        viewer.ui_scale = float(scale);
      },
      tr("Viewer: size of the interface (text, panel, windows), e.g. 1.5 for a projector; Ctrl+= / Ctrl+- change "
         "it"));

  RenderSettings settings;
  CLI::App* render = app.add_subcommand("render", tr("Render one picture headless (OSMesa, no display needed)"));
  std::string models_help = std::string(tr("Models (--model NAME; the key that shows it in the viewer):")) + "\n";
  for (const luz::app::ModelEntry& m : luz::app::models())
    models_help += fmt::format("  {:<10} [{}] {}\n", m.name, m.key, luz::i18n::tr(m.help));
  render->footer(models_help +
                 tr("A model takes the flags of its groups: slide 19's switches only the local models, the tracer's "
                    "whitted and hybrid, --spp and --depth the three tracers (whitted, hybrid, path), the solver's "
                    "radiosity and hybrid (all but --flat-patches and --outlines). --model A,B or A,B,C,D puts the "
                    "models side by side.") + std::string("\n"));
  render->add_option_function<std::string>("--lang", lang, tr("Language of the messages and the panes' labels: es or en"))
      ->check(CLI::IsMember({"es", "en"}));
  const luz::app::RenderFlags render_flags = luz::app::add_render_flags(*render, settings);

  luz::app::SolversSettings solvers_settings;
  CLI::App* solvers = app.add_subcommand(
      "solvers", tr("Slide 36: Jacobi, Gauss-Seidel and Southwell on the full form-factor matrix, beside "
                    "slide 39's shooting; writes their convergence curves"));
  solvers->add_option(tr("SCENE"), solvers_settings.scene, tr("glTF 2.0 scene (.gltf or .glb)"))->required();
  solvers->add_option("--csv", solvers_settings.csv,
                      tr("Curves as CSV: method,iteration,rows,seconds,residual,error"))->required();
  solvers->add_option("--png", solvers_settings.png, tr("Plot of the curves (residual and error against rows)"));
  CLI::Option* solver_patch_size = solvers->add_option("--patch-size", solvers_settings.patch_size,
                                                       tr("Longest patch edge, metres"))->check(finite_number)->check(CLI::PositiveNumber);
  CLI::Option* solver_patches = solvers->add_option("--patches", solvers_settings.patches,
      trf("About this many patches (at most {})", luz::app::kMaxSolverPatches))
      ->check(CLI::PositiveNumber)->capture_default_str();
  solver_patch_size->excludes(solver_patches);
  solvers->add_option_function<int>(
      "--hemicube-res",
      [&solvers_settings](int n) {
        if (n % 2 != 0) throw CLI::ValidationError("--hemicube-res", tr("must be even"));
        solvers_settings.hemicube_res = n;
      },
      trf("Hemicube resolution ({} .. {}, even; default {})", luz::kMinHemicubeRes,
          luz::kMaxHemicubeRes, solvers_settings.hemicube_res))
      ->type_name("INT")
      ->check(CLI::Range(luz::kMinHemicubeRes, luz::kMaxHemicubeRes).description(""));
  solvers->add_option("--form-factors", solvers_settings.form_factors,
                      tr("analytic (Lambert's contour integral, the hemicube for visibility: rows and shot columns "
                         "reciprocal) or hemicube (both from the hemicube)"))
      ->transform(CLI::CheckedTransformer(std::map<std::string, luz::FormFactorMethod>{
          {"analytic", luz::FormFactorMethod::analytic}, {"hemicube", luz::FormFactorMethod::hemicube}}).description(""))
      ->type_name("analytic|hemicube")
      ->capture_default_str();
  solvers->add_option("--iterations", solvers_settings.iterations,
                      tr("Jacobi and Gauss-Seidel sweeps; Southwell and shooting use as many rows"))
      ->type_name("1..10000")->check(CLI::Range(1, 10000).description(""))->capture_default_str();
  solvers->add_flag("-q,--quiet", solvers_settings.quiet, tr("Print nothing on success"));

  luz::app::WhittedBenchSettings bench_settings;
  CLI::App* bench = app.add_subcommand("bench", tr("Benchmarks (timings, never pass/fail)"));
  bench->require_subcommand(1);
  CLI::App* bench_whitted = bench->add_subcommand("whitted", tr("The Whitted tracer against the same rays traced bare through Embree"));
  luz::app::add_bench_flags(*bench_whitted, bench_settings);
  luz::app::LocalBenchSettings local_bench;
  CLI::App* bench_local = bench->add_subcommand(
      "local", tr("Flat, Gouraud and Phong ms per frame, with slide 19's effects, against the same triangles drawn bare"));
  luz::app::add_local_bench_flags(*bench_local, local_bench);
  luz::app::RadiosityBenchSettings radiosity_bench;
  CLI::App* bench_radiosity = bench->add_subcommand(
      "radiosity", tr("Shots/s and time to converge on the Cornell box at about 1k, 4k, 16k, 64k patches"));
  bench_radiosity->add_option("--scene", radiosity_bench.scene, tr("Scene (default: the Cornell box)"));
  bench_radiosity->add_option("--patches", radiosity_bench.patches, tr("Target patch counts"))
      ->capture_default_str();
  bench_radiosity->add_option("--hemicube-res", radiosity_bench.hemicube_res, tr("Hemicube resolution"))
      ->check(CLI::Range(luz::kMinHemicubeRes, luz::kMaxHemicubeRes))->capture_default_str();
  bench_radiosity->add_option("--hemicube-passes", radiosity_bench.hemicube_passes,
                              tr("Draw the hemicube in five passes or one instanced pass"))
      ->transform(CLI::CheckedTransformer(std::map<std::string, luz::HemicubePasses>{
          {"five", luz::HemicubePasses::five}, {"one", luz::HemicubePasses::one}}))
      ->capture_default_str();
  bench_radiosity->add_option("--hemicube-sums", radiosity_bench.hemicube_sums,
                              tr("Sum the hemicube's delta form factors on the cpu or the gpu"))
      ->transform(CLI::CheckedTransformer(std::map<std::string, luz::HemicubeSums>{
          {"cpu", luz::HemicubeSums::cpu}, {"gpu", luz::HemicubeSums::gpu}}))
      ->capture_default_str();
  bench_radiosity->add_option("--reference", radiosity_bench.reference,
                              tr("Converged picture (linear EXR, first camera): print the error against it over "
                                 "time for uniform, substructured, analytic, overshot and ray-cast shooting instead"));
  bench_radiosity->add_option("--ways", radiosity_bench.ways,
                              tr("With --reference: the ways to compare (uniform, hemicube, analytic, overshoot, "
                                 "rays, rays-ambient, adaptive; default all)"))
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(luz::app::kRadiosityWays),
                                                     std::end(luz::app::kRadiosityWays))));
  bench_radiosity->add_option("--seconds", radiosity_bench.seconds, tr("Time cap per patch count"))
      ->check(finite_number)->check(CLI::PositiveNumber)->capture_default_str();

  luz::app::CompareSettings compare_settings;
  CLI::App* compare = app.add_subcommand(
      "compare", tr("How far picture A is from reference B: mean error, rel-RMSE, mean relative error over lit pixels"));
  luz::app::add_compare_flags(*compare, compare_settings);

  luz::app::HandoutSettings handout_settings;
  CLI::App* lesson = app.add_subcommand(
      "lesson", tr("The lesson as a handout, headless: every step's picture with its slide, title and text, as a PDF "
                   "of A4 pages and/or one PNG per step"));
  lesson->add_option_function<std::string>("--lang", lang, tr("Language of the titles, texts and labels: es or en"))
      ->check(CLI::IsMember({"es", "en"}));
  luz::app::add_handout_flags(*lesson, handout_settings);
  // Every command takes --lang after its name too (`luz solvers SCENE --lang es`), as render does.
  const std::function<void(CLI::App&)> take_lang_after = [&](CLI::App& command) {
    for (CLI::App* sub : command.get_subcommands({})) {
      if (!sub->get_option_no_throw("--lang"))
        sub->add_option_function<std::string>("--lang", lang, tr("Language of the messages: es or en"))
            ->check(CLI::IsMember({"es", "en"}));
      take_lang_after(*sub);
    }
  };
  take_lang_after(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message
    return 2;
  }

  if (!man_page_file.empty()) return luz::app::write_man_page(app, man_page_file);
  if (render->parsed()) {
    luz::app::note_given_flags(render_flags, settings);
    return luz::app::run_render(settings);
  }
  if (solvers->parsed()) return luz::app::run_solvers(solvers_settings);
  if (compare->parsed()) return luz::app::run_compare(compare_settings);
  if (lesson->parsed()) return luz::app::run_handout(handout_settings);
  if (bench_whitted->parsed()) return luz::app::run_bench_whitted(bench_settings);
  if (bench_radiosity->parsed()) return luz::app::run_radiosity_bench(radiosity_bench);
  if (bench_local->parsed()) return luz::app::run_bench_local(local_bench);

  if (lesson_file) {  // a malformed lesson is a usage error, found before any window opens
    try {
      viewer.lesson = luz::app::parse_lesson(lesson_file->empty() ? luz::app::default_lesson()
                                                                  : std::filesystem::path(*lesson_file));
      viewer.scene = viewer.lesson->steps.front().scene;
    } catch (const luz::Error& error) {
      fmt::print(stderr, "luz: {}\n", error.what());
      return 2;
    }
  }
  if (viewer.scene.empty()) viewer.scene = luz::default_scene().string();
  if (!script_file.empty()) {  // a bad script is a usage error, found before any window opens
    try {
      viewer.script = luz::app::parse_script(script_file);  // it waits for the lesson's first step
    } catch (const luz::Error& error) {
      fmt::print(stderr, "luz: {}\n", error.what());
      return 2;
    }
  }
  if (!luz::gl::WindowContext::display_available()) return no_display(viewer.scene);
  return luz::app::run_viewer(viewer);
}
