#include "app/render_command.h"
#include "app/radiosity_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
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

}  // namespace

bool parse_size(const std::string& text, int& width, int& height) {
  static const std::regex pattern(R"((\d{1,5})[xX](\d{1,5}))");
  std::smatch match;
  if (!std::regex_match(text, match, pattern)) return false;
  width = std::stoi(match[1]);
  height = std::stoi(match[2]);
  return width >= 1 && height >= 1 && width <= kMaxSide && height <= kMaxSide;
}

int run_render(const RenderSettings& settings) {
  try {
    if (settings.model != "radiosity" && !settings.radiosity_flags.empty())
      throw Error(ErrorKind::usage, fmt::format("{} only applies to --model radiosity",
                                                settings.radiosity_flags.front()));
    if (!io::is_supported_output(settings.out))
      throw Error(ErrorKind::usage, fmt::format("--out {}: the output must end in .png or .exr", settings.out));
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
    gl::OffscreenContext context;
    Image image;
    if (settings.model == "radiosity") {
      image = render_radiosity(scene, camera, width, height, settings);
    } else {
      LocalOptions options = settings.local;
      options.shading = shading_of(settings.model);
      LocalRenderer renderer(scene);
      image = renderer.render(camera, width, height, options);
      for (const std::string& warning : renderer.warnings()) fmt::print(stderr, "warning: {}\n", warning);
    }
    const float exposure = settings.exposure.value_or(scene.exposure);
    io::write_image(image, settings.out, exposure);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!settings.quiet)
      fmt::print("{}: {} {}x{}, camera \"{}\", exposure {:+g} EV, {:.3f} s\n", settings.out,
                 settings.model, width, height, camera.name, exposure, seconds);
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
