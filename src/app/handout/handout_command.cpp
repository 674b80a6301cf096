#include "app/handout/handout_command.h"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "app/handout/handout_pdf.h"
#include "app/common/i18n.h"
#include "app/classroom/lesson.h"
#include "app/handout/lesson_picture.h"
#include "app/models/radiosity/radiosity_session.h"
#include "app/cli/render_grid.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/gltf_loader.h"
#include "io/image_io.h"

namespace luz::app {
namespace fs = std::filesystem;
namespace {

struct StepRange {
  size_t first = 1, last = 0;  // from 1, both included
};

// "A-B" or "A" within 1 .. steps; a usage error otherwise.
StepRange parse_steps(const std::string& text, size_t steps) {
  if (text.empty()) return {1, steps};
  const auto number = [&](std::string_view part, size_t& out) {
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
    return ec == std::errc() && end == part.data() + part.size();
  };
  const size_t dash = text.find('-');
  StepRange range;
  const bool read = dash == std::string::npos
                        ? number(text, range.first) && (range.last = range.first, true)
                        : number(std::string_view(text).substr(0, dash), range.first) &&
                              number(std::string_view(text).substr(dash + 1), range.last);
  if (!read || range.first < 1 || range.first > range.last || range.last > steps)
    throw Error(ErrorKind::usage, trf("--steps {}: expected A-B with 1 <= A <= B <= {} (the lesson's steps)", text, steps));
  return range;
}

std::string png_name(size_t number) { return fmt::format("step-{:02}.png", number); }

// The outputs are written beside their final names and renamed when every step is done; on
// any failure the temporary ones go.
class Outputs {
public:
  Outputs(const HandoutSettings& settings, const std::string& lesson_title, StepRange range) : settings_(settings) {
    try {
      open(lesson_title, range);
    } catch (...) {
      remove_temporaries();  // the destructor does not run for an object never made
      throw;
    }
  }
  ~Outputs() { remove_temporaries(); }

  void add(size_t number, const HandoutStep& step, const Image& picture, float exposure) {
    if (pdf_) pdf_->add(step, picture, exposure);
    if (!png_partial_.empty()) {
      const std::string name = png_name(number);
      io::write_image(picture, png_partial_ / name, exposure);
      pngs_.push_back(name);
    }
  }

  // Ends the PDF and moves everything to its final name; returns the PDF's pages.
  int finish() {
    int pages = 0;
    if (pdf_) {
      pdf_->finish();
      pages = pdf_->pages();
      pdf_.reset();
      move(pdf_partial_, settings_.pdf);
      pdf_partial_.clear();
    }
    if (!png_partial_.empty()) {
      std::error_code error;
      fs::create_directories(settings_.png_dir, error);
      for (const std::string& name : pngs_) move(png_partial_ / name, fs::path(settings_.png_dir) / name);
    }
    return pages;
  }

private:
  void open(const std::string& lesson_title, StepRange range) {
    const HandoutSettings& settings = settings_;
    if (!settings.pdf.empty()) {
      pdf_partial_ = settings.pdf + ".partial";
      pdf_.emplace(pdf_partial_, lesson_title);
    }
    if (!settings.png_dir.empty()) {
      fs::path folder = fs::path(settings.png_dir).lexically_normal();
      if (!folder.has_filename()) folder = folder.parent_path();  // "pictures/"
      png_partial_ = folder.string() + ".partial";
      std::error_code error;
      fs::remove_all(png_partial_, error);
      if (!fs::create_directories(png_partial_, error) || error)
        throw Error(ErrorKind::output, trf("{}: cannot be written", settings.png_dir));
    }
    std::vector<fs::path> temporaries;
    if (!pdf_partial_.empty()) temporaries.push_back(pdf_partial_);
    if (!png_partial_.empty()) {
      for (size_t number = range.first; number <= range.last; ++number) temporaries.push_back(png_partial_ / png_name(number));
      temporaries.push_back(png_partial_);
    }
    guard_.emplace(temporaries);
  }
  void remove_temporaries() {
    pdf_.reset();  // Cairo writes what it holds when the surface goes: before the file is removed
    std::error_code ignored;
    if (!pdf_partial_.empty()) fs::remove(pdf_partial_, ignored);
    if (!png_partial_.empty()) fs::remove_all(png_partial_, ignored);
  }
  static void move(const fs::path& from, const fs::path& to) {
    std::error_code error;
    fs::rename(from, to, error);
    if (error) throw Error(ErrorKind::output, trf("{}: cannot be written", to.string()));
  }
  const HandoutSettings& settings_;
  fs::path pdf_partial_, png_partial_;
  std::optional<HandoutPdf> pdf_;
  std::vector<std::string> pngs_;
  std::optional<io::RemovedOnSignal> guard_;  // last: gone first
};

int write_handout(const HandoutSettings& settings, const Lesson& lesson, StepRange range) {
  try {
    const std::vector<StepPicture> pictures = step_pictures(lesson);
    const i18n::Language language = i18n::language();
    Outputs outputs(settings, lesson.title.in(language), range);

    const auto start = std::chrono::steady_clock::now();
    std::string loaded_path;
    std::optional<io::LoadedScene> loaded;
    const size_t count = range.last - range.first + 1;
    for (size_t number = range.first; number <= range.last; ++number) {
      const LessonStep& step = lesson.steps[number - 1];
      StepPicture picture = pictures[number - 1];
      if (!settings.quiet)
        fmt::print(stderr, "{}\n", trf("luz: step {} of {} (slide {}): {}", number - range.first + 1, count, step.slide,
                                       step.title.in(language)));
      if (picture.settings.scene != loaded_path) {
        loaded = io::load_gltf(picture.settings.scene);
        loaded_path = picture.settings.scene;
      }
      const Scene& scene = loaded->scene;
      const Camera& camera = chosen_camera(picture.settings, scene);
      picture.settings.width = settings.width;
      picture.settings.height = settings.height;
      picture.settings.seconds = settings.seconds;
      if (picture.shows_radiosity()) {
        picture.radiosity.exposure = picture.settings.exposure.value_or(scene.exposure);
        if (picture.heat_map) picture.radiosity.heat_map = unshot_heat_map;
        picture.settings.radiosity_solution = solve_radiosity(scene, picture.settings, picture.radiosity);
      }
      const Sheet sheet = render_sheet(picture.settings, scene, camera, picture.models);
      const HandoutStep page{trf("Slide {} · step {} of {}", step.slide, number, lesson.steps.size()),
                             step.title.in(language), step.text.in(language),
                             picture.heat_map && picture.models == std::vector<std::string>{"radiosity"}};
      outputs.add(number, page, sheet.image, sheet.exposure);
    }
    const int pages = outputs.finish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!settings.quiet) {
      if (!settings.pdf.empty()) fmt::print("{}\n", trf("{}: {} steps on {} pages, {:.1f} s", settings.pdf, count, pages, seconds));
      if (!settings.png_dir.empty()) fmt::print("{}\n", trf("{}: {} pictures", settings.png_dir, count));
    }
    return 0;
  } catch (const Error& error) {
    // What a step asks that cannot be done (a camera the scene lacks) is the lesson file's fault.
    fmt::print(stderr, "luz: {}\n", error.what());
    return 1;
  }
}

}  // namespace

void add_handout_flags(CLI::App& lesson, HandoutSettings& settings) {
  lesson.add_option("LESSON", settings.lesson, tr("The lesson file (default: lessons/sintesis.json)"));
  lesson.add_option("--handout", settings.pdf,
                    trf("Write the lesson as a PDF handout: A4 pages, {} steps on each, every step's slide, "
                        "title, picture and text", kStepsPerPage));
  lesson.add_option("--png-dir", settings.png_dir, tr("Write every step's picture into this folder (step-01.png, ...)"));
  lesson.add_option_function<std::string>(
      "--size",
      [&settings](const std::string& text) {
        if (!parse_size(text, settings.width, settings.height))
          throw CLI::ValidationError("--size", tr("expected WxH with 1 <= W, H <= 16384, e.g. 1280x720"));
      },
      tr("Each step's picture WxH (panes share it; default: luz render's size)"));
  lesson.add_option("--steps", settings.steps, tr("Only steps A to B (from 1), e.g. --steps 1-4"));
  lesson.add_option("--time", settings.seconds,
                    tr("Seconds each step's radiosity solve or path tracing may take at most (the stopping rule "
                       "may end it sooner)"))
      ->check(CLI::PositiveNumber)->capture_default_str();
  lesson.add_flag("-q,--quiet", settings.quiet, tr("Print nothing on success"));
}

int run_handout(const HandoutSettings& settings) {
  try {
    if (settings.pdf.empty() && settings.png_dir.empty())
      throw Error(ErrorKind::usage, tr("luz lesson: give --handout FILE.pdf, --png-dir DIR or both"));
    if (!settings.pdf.empty() && fs::path(settings.pdf).extension() != ".pdf")
      throw Error(ErrorKind::usage, trf("--handout {}: the handout is written as .pdf", settings.pdf));
    Lesson lesson;
    try {
      lesson = parse_lesson(settings.lesson.empty() ? default_lesson() : fs::path(settings.lesson));
    } catch (const Error& error) {
      throw Error(ErrorKind::bad_value, error.what());  // a bad file, not a bad command line
    }
    const StepRange range = parse_steps(settings.steps, lesson.steps.size());
    return write_handout(settings, lesson, range);
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
