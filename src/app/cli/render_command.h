#pragma once
// `luz render`: one picture of a scene, headless through OSMesa.
#include <memory>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/common/option_values.h"
#include "core/scene.h"
#include "local/local_options.h"
#include "radiosity/radiosity_options.h"
#include "raytracing/whitted_options.h"

namespace CLI { class App; class Option; }

namespace luz::app {

struct RadiositySolution;

struct RenderSettings {
  std::string scene;
  std::string model = "phong";   // a name of the registry (model_registry.h)
  std::string out;
  int width = 0;                 // 0: from the camera's aspect ratio (see output_size)
  int height = 0;
  std::string camera;            // name or index; empty = the scene's first
  std::optional<float> exposure; // overrides the scene's
  bool exposure_auto = false;    // --exposure auto: fitted to the picture (core/exposure.h)
  LocalOptions local;
  RadiosityOptions radiosity;
  std::string csv;               // radiosity: the residual history, one row per shot
  // --time: the path tracer's passes, or radiosity's shooting, stop when it is up.
  std::optional<double> seconds;
  bool quiet = false;
  // --model whitted: the tracer's options (the --no-TERM switches and --blinn come from `local`)
  // and the pixel whose ray tree is written beside the image.
  rt::WhittedOptions whitted;
  std::optional<std::pair<int, int>> ray_tree;
  // The options of a model's own table (the path tracer's, option_row.h): its flags write them.
  OptionValues model_options;
  // The flags of a flag group that were given, with their group: a group the model does not
  // take (model_registry.h) is a usage error.
  struct GivenFlag {
    std::string flag;
    std::string group;
  };
  std::vector<GivenFlag> given_flags;
  // A radiosity solution already solved for this scene and these flags (render_radiosity.h):
  // the radiosity and hybrid pictures show it instead of solving again. Empty: each solves.
  std::shared_ptr<const RadiositySolution> radiosity_solution;
};

// Where the struct of an options table is: the shared tables' (local, whitted, radiosity) are
// fields above, a model's own is in model_options.
void* options_of(RenderSettings& settings, const OptionTable& table);
const void* options_of(const RenderSettings& settings, const OptionTable& table);

// Parses "WxH"; false when malformed or out of range.
bool parse_size(const std::string& text, int& width, int& height);

// Parses "X,Y" (a pixel); false when malformed.
bool parse_pixel(const std::string& text, int& x, int& y);
// Parses "R,G,B" (three finite numbers >= 0); false when malformed.
bool parse_rgb(const std::string& text, Rgb& colour);

// The camera --camera names (by name or index), else the scene's first; a usage error naming the
// scene's cameras when there is none of that name.
const Camera& chosen_camera(const RenderSettings& settings, const Scene& scene);

// What --exposure auto fits: one picture of the scene from `camera`, the same whichever model is
// asked for, so that separate runs of the models (and a grid's panes) share one exposure and
// compare. It is the reference model's, the path tracer's (seed 0), with the light every model
// shows, direct and interreflected: kExposureKeyHeight rows of kExposureKeySamples samples, whose
// fit is within 0.3 EV of a 4096-sample picture's on the shipped scenes (docs/scene_format.md);
// fewer samples leave dark noisy pixels that pull the log-average down.
inline constexpr int kExposureKeyHeight = 60;
inline constexpr int kExposureKeySamples = 64;
Image exposure_key_picture(const Scene& scene, const Camera& camera);

// The PNG's exposure: --exposure's number, the one fitted to exposure_key_picture with --exposure
// auto, else the scene's. Where no number was given, a `picture` far off the exposure it gets is
// warned of on stderr, with the way out.
float chosen_exposure(const RenderSettings& settings, const Scene& scene, const Camera& camera, const Image& picture);

// Where --ray-tree's JSON goes: beside the image, `<out without extension>.ray-tree.json`.
std::filesystem::path ray_tree_path(const std::filesystem::path& out);

// Loads, renders and writes; returns the exit code (0, 1 bad input, 2 usage) after printing
// any message to stderr.
int run_render(const RenderSettings& settings);

}  // namespace luz::app
