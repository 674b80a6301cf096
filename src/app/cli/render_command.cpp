#include "app/cli/render_command.h"

#include <algorithm>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>

#include <fmt/format.h>

#include "app/common/i18n.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "core/exposure.h"
#include "io/gltf_loader.h"
#include "io/image_io.h"
#include "app/common/model_registry.h"
#include "app/common/options_tables.h"
#include "app/cli/render_grid.h"

namespace luz::app {
namespace {

constexpr int kDefaultHeight = 600;
constexpr int kMaxSide = 16384;

// Width over height: the camera's, else 4:3 (a glTF camera may leave it to the viewport).
float aspect_of(const Camera& camera) { return camera.aspect > 0.0f ? camera.aspect : 4.0f / 3.0f; }

// The output keeps the camera's aspect ratio unless --size says otherwise.
void output_size(const RenderSettings& settings, const Camera& camera, int& width, int& height) {
  if (settings.width > 0) {
    width = settings.width;
    height = settings.height;
    return;
  }
  height = kDefaultHeight;
  width = std::max(1, int(std::lround(float(height) * aspect_of(camera))));
}

std::string camera_list(const Scene& scene) {
  std::string list;
  for (size_t i = 0; i < scene.cameras.size(); ++i)
    list += fmt::format("{}{} \"{}\"", i ? ", " : "", i, scene.cameras[i].name);
  return list;
}

// The ray tree's JSON, whole or not at all, like the image.
void write_text(const std::filesystem::path& path, const std::string& text) {
  if (!io::write_atomically(path, [&] { return text; }).empty())
    throw Error(ErrorKind::output, trf("{}: cannot be written", path.string()));
}

}  // namespace

bool parse_pixel(const std::string& text, int& x, int& y) {
  static const std::regex pattern(R"((\d{1,5}),(\d{1,5}))");
  std::smatch match;
  if (!std::regex_match(text, match, pattern)) return false;
  x = std::stoi(match[1]);
  y = std::stoi(match[2]);
  return true;
}

bool parse_size(const std::string& text, int& width, int& height) {
  static const std::regex pattern(R"((\d{1,5})[xX](\d{1,5}))");
  std::smatch match;
  if (!std::regex_match(text, match, pattern)) return false;
  width = std::stoi(match[1]);
  height = std::stoi(match[2]);
  return width >= 1 && height >= 1 && width <= kMaxSide && height <= kMaxSide;
}

bool parse_rgb(const std::string& text, Rgb& colour) {
  static const std::regex number(R"(\s*([0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?)\s*)");
  const size_t first = text.find(','), second = first == std::string::npos ? first : text.find(',', first + 1);
  if (second == std::string::npos || text.find(',', second + 1) != std::string::npos) return false;
  const std::string parts[3] = {text.substr(0, first), text.substr(first + 1, second - first - 1),
                                text.substr(second + 1)};
  Rgb parsed(0.0f);
  for (int i = 0; i < 3; ++i) {
    if (!std::regex_match(parts[i], number)) return false;
    parsed[i] = std::stof(parts[i]);
    if (!std::isfinite(parsed[i])) return false;
  }
  colour = parsed;
  return true;
}

const Camera& chosen_camera(const RenderSettings& settings, const Scene& scene) {
  if (settings.camera.empty()) return scene.cameras.front();
  const int index = scene.find_camera(settings.camera);
  if (index < 0)
    throw Error(ErrorKind::usage, trf("{}: no camera \"{}\" (cameras: {})", settings.scene, settings.camera,
                                      camera_list(scene)));
  return scene.cameras[size_t(index)];
}

Image exposure_key_picture(const Scene& scene, const Camera& camera) {
  RenderSettings reference;
  reference.model = "path";
  reference.quiet = true;
  const FoundOption spp = *find_option("path.spp");
  spp.row->set(options_of(reference, *spp.table), kExposureKeySamples);
  reference.given_flags.push_back({"--spp", "sampling"});
  const int width = std::clamp(int(std::lround(float(kExposureKeyHeight) * aspect_of(camera))), 1,
                               4 * kExposureKeyHeight);
  return find_model("path")->render(scene, camera, width, kExposureKeyHeight, reference).image;
}

float chosen_exposure(const RenderSettings& settings, const Scene& scene, const Camera& camera, const Image& picture) {
  if (settings.exposure) return *settings.exposure;
  if (settings.exposure_auto) {
    const PictureKey key = picture_key(exposure_key_picture(scene, camera));
    if (almost_no_light(key))
      fmt::print(stderr, "{}\n", trf("warning: {}: {}", settings.out, almost_no_light_note(key)));
    if (const std::optional<float> fitted = fitted_exposure(key)) return *fitted;
    fmt::print(stderr, "{}\n", trf("warning: {}: nothing in the picture is lit: --exposure auto keeps {:+g} EV",
                                   settings.out, scene.exposure));
    return scene.exposure;
  }
  if (io::is_png_output(settings.out))
    if (const std::string problem = exposure_problem(picture, scene.exposure, photometric_hint(scene)); !problem.empty())
      fmt::print(stderr, "{}\n", trf("warning: {}: {}; --exposure auto fits it", settings.out, problem));
  return scene.exposure;
}

std::filesystem::path ray_tree_path(const std::filesystem::path& out) {
  std::filesystem::path path = out;
  return path.replace_extension(".ray-tree.json");
}

void* options_of(RenderSettings& settings, const OptionTable& table) {
  if (&table == &local_table()) return &settings.local;
  if (&table == &whitted_table()) return &settings.whitted;
  if (&table == &radiosity_table()) return &settings.radiosity;
  return settings.model_options.of(table);
}

const void* options_of(const RenderSettings& settings, const OptionTable& table) {
  return options_of(const_cast<RenderSettings&>(settings), table);  // the same field, read only
}

int run_render(const RenderSettings& settings) {
  try {
    if (settings.local.fog.mode == FogMode::linear && !(settings.local.fog.far > settings.local.fog.near))
      throw Error(ErrorKind::usage, trf("--fog linear: --fog-far ({}) must be beyond --fog-near ({})",
                                        settings.local.fog.far, settings.local.fog.near));
    if (is_model_list(settings.model)) return run_render_grid(settings);  // side by side
    const ModelEntry* model = find_model(settings.model);
    if (!model) throw Error(ErrorKind::usage, trf("--model {}: no such model ({})", settings.model, model_names()));
    for (const RenderSettings::GivenFlag& given : settings.given_flags) {
      const bool taken = std::any_of(model->flag_groups.begin(), model->flag_groups.end(),
                                     [&](const char* group) { return given.group == group; });
      if (!taken)
        throw Error(ErrorKind::usage, trf("{}: only with --model {}", given.flag, models_accepting(given.group)));
    }
    if (!io::is_supported_output(settings.out))
      throw Error(ErrorKind::usage, trf("--out {}: the output must end in .png or .exr", settings.out));
    using Clock = std::chrono::steady_clock;
    const auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
    const auto loading = Clock::now();
    io::LoadedScene loaded = io::load_gltf(settings.scene);
    const double load_seconds = seconds_since(loading);
    for (const std::string& warning : loaded.warnings) fmt::print(stderr, "{}\n", trf("warning: {}", warning));
    const Scene& scene = loaded.scene;

    const Camera& camera = chosen_camera(settings, scene);
    int width = 0, height = 0;
    output_size(settings, camera, width, height);

    const auto start = Clock::now();
    Rendered rendered = model->render(scene, camera, width, height, settings);
    const double model_seconds = seconds_since(start);
    const float exposure = chosen_exposure(settings, scene, camera, rendered.image);
    const auto writing = Clock::now();
    try {
      io::write_image(rendered.image, settings.out, exposure);
    } catch (const Error&) {
      // The --csv history belongs to a run that succeeded: without its picture it goes too.
      std::error_code ignored;
      if (!settings.csv.empty()) std::filesystem::remove(settings.csv, ignored);
      throw;
    }
    if (rendered.ray_tree) write_text(ray_tree_path(settings.out), *rendered.ray_tree);
    const double write_seconds = seconds_since(writing);
    const double seconds = seconds_since(start);
    if (!settings.quiet) {
      fmt::print("{}\n", trf("{}: {} {}x{}, camera \"{}\", exposure {:+g} EV, {:.3f} s", settings.out,
                             model_labels(settings.model), width, height, camera.name, exposure, seconds));
      fmt::print("{}", rendered.summary);
      fmt::print("{}\n", trf("phases: scene loaded in {:.3f} s, the model's picture (its set-up included) {:.3f} s, "
                             "written in {:.3f} s", load_seconds, model_seconds, write_seconds));
      if (rendered.ray_tree) fmt::print("{}\n", trf("ray tree: {}", ray_tree_path(settings.out).string()));
    }
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
