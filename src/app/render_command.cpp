#include "app/render_command.h"
#include "app/radiosity_command.h"
#include "app/render_hybrid.h"
#include "app/render_whitted.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include <fmt/format.h>

#include "core/error.h"
#include "gl/offscreen_context.h"
#include "io/gltf_loader.h"
#include "io/image_io.h"
#include "local/local_renderer.h"

namespace luz::app {
namespace {

constexpr int kDefaultHeight = 600;
constexpr int kMaxSide = 16384;

Shading shading_of(const std::string& model) {
  if (model == "flat") return Shading::flat;
  if (model == "gouraud") return Shading::gouraud;
  return Shading::phong;
}

// The output keeps the camera's aspect ratio unless --size says otherwise.
void output_size(const RenderSettings& settings, const Camera& camera, int& width, int& height) {
  if (settings.width > 0) {
    width = settings.width;
    height = settings.height;
    return;
  }
  const float aspect = camera.aspect > 0.0f ? camera.aspect : 4.0f / 3.0f;
  height = kDefaultHeight;
  width = std::max(1, int(std::lround(float(height) * aspect)));
}

std::string camera_list(const Scene& scene) {
  std::string list;
  for (size_t i = 0; i < scene.cameras.size(); ++i)
    list += fmt::format("{}{} \"{}\"", i ? ", " : "", i, scene.cameras[i].name);
  return list;
}

// The ray tree's JSON, written beside its final name and renamed, like the image.
void write_text(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path temporary = path.string() + ".partial";
  {
    std::ofstream file(temporary, std::ios::binary);
    file << text;
    if (!file.flush())
      throw Error(ErrorKind::output, fmt::format("{}: cannot be written", path.string()));
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw Error(ErrorKind::output, fmt::format("{}: cannot be written", path.string()));
  }
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

int run_render(const RenderSettings& settings) {
  try {
    if (settings.local.fog.mode == FogMode::linear && !(settings.local.fog.far > settings.local.fog.near))
      throw Error(ErrorKind::usage, fmt::format("--fog linear: --fog-far ({}) must be beyond --fog-near ({})",
                                                settings.local.fog.far, settings.local.fog.near));
    // The hybrid takes both models' flags, except the radiosity picture's own display switches.
    const bool hybrid = settings.model == "hybrid";
    for (const std::string& flag : settings.radiosity_only_flags) {
      const bool display_only = flag == "--flat-patches" || flag == "--outlines";
      if (settings.model != "radiosity" && (!hybrid || display_only))
        throw Error(ErrorKind::usage, fmt::format("{}: only with --model radiosity{}", flag,
                                                  display_only ? "" : " or hybrid"));
    }
    if (!io::is_supported_output(settings.out))
      throw Error(ErrorKind::usage, fmt::format("--out {}: the output must end in .png or .exr", settings.out));
    const bool local = settings.model == "flat" || settings.model == "gouraud" || settings.model == "phong";
    if (!local && !settings.local_only_flags.empty())
      throw Error(ErrorKind::usage, fmt::format("{}: only with --model flat, gouraud or phong (slide 19's "
                                                "switches of the local models)", settings.local_only_flags.front()));
    if (settings.model != "whitted" && !hybrid && !settings.whitted_only_flags.empty())
      throw Error(ErrorKind::usage, fmt::format("{}: only with --model whitted or hybrid",
                                                settings.whitted_only_flags.front()));
    io::LoadedScene loaded = io::load_gltf(settings.scene);
    for (const std::string& warning : loaded.warnings) fmt::print(stderr, "warning: {}\n", warning);
    const Scene& scene = loaded.scene;

    int camera_index = 0;
    if (!settings.camera.empty()) {
      camera_index = scene.find_camera(settings.camera);
      if (camera_index < 0)
        throw Error(ErrorKind::usage, fmt::format("{}: no camera \"{}\" (cameras: {})", settings.scene,
                                                  settings.camera, camera_list(scene)));
    }
    const Camera& camera = scene.cameras[size_t(camera_index)];
    int width = 0, height = 0;
    output_size(settings, camera, width, height);

    const auto start = std::chrono::steady_clock::now();
    Image image;
    WhittedResult traced;
    if (settings.model == "whitted") {
      traced = render_whitted(scene, camera, width, height, settings);  // no GL needed
      image = std::move(traced.image);
    } else if (hybrid) {
      traced = render_hybrid(scene, camera, width, height, settings);
      image = std::move(traced.image);
    } else if (settings.model == "radiosity") {
      gl::OffscreenContext context;
      image = render_radiosity(scene, camera, width, height, settings);
    } else {
      gl::OffscreenContext context;
      LocalOptions options = settings.local;
      options.shading = shading_of(settings.model);
      LocalRenderer renderer(scene);
      image = renderer.render(camera, width, height, options);
      for (const std::string& warning : renderer.warnings()) fmt::print(stderr, "warning: {}\n", warning);
    }
    const float exposure = settings.exposure.value_or(scene.exposure);
    try {
      io::write_image(image, settings.out, exposure);
    } catch (const Error&) {
      // The --csv history belongs to a run that succeeded: without its picture it goes too.
      std::error_code ignored;
      if (!settings.csv.empty()) std::filesystem::remove(settings.csv, ignored);
      throw;
    }
    if (traced.ray_tree) write_text(ray_tree_path(settings.out), *traced.ray_tree);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!settings.quiet) {
      fmt::print("{}: {} {}x{}, camera \"{}\", exposure {:+g} EV, {:.3f} s\n", settings.out,
                 settings.model, width, height, camera.name, exposure, seconds);
      fmt::print("{}", traced.summary);
      if (traced.ray_tree) fmt::print("ray tree: {}\n", ray_tree_path(settings.out).string());
    }
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
