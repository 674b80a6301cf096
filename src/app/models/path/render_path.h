#pragma once
// `luz render --model path`: the path tracer of src/raytracing (slide 14's equation, the
// reference model), for a number of samples per pixel or until a time is up, with the mean
// picture and the per-pixel standard error of that mean.
#include <optional>
#include <string>
#include <vector>

#include "app/cli/render_command.h"
#include "core/camera.h"
#include "core/image.h"
#include "core/scene.h"
#include "raytracing/path_options.h"

namespace luz::app {

struct Rendered;

struct PathResult {
  Image mean;            // the picture: the mean of the samples
  Image standard_error;  // per pixel and channel, of that mean
  int spp = 0;           // samples per pixel taken
  double seconds = 0.0;
  std::string summary;   // one line for the end of the run
};

// Renders `options.spp` samples per pixel, or with `seconds` passes of one sample per pixel
// until the time is up (options.spp then caps the count when `spp_given`). Shows progress on
// stderr when `progress` (a terminal).
PathResult render_path(const Scene& scene, const Camera& camera, int width, int height,
                       const rt::PathOptions& options, std::optional<double> seconds,
                       bool spp_given, bool progress);

// The registry's render (model_registry.cpp): the tracer's own defaults unless --spp or --depth
// were given; writes --error-out (a usage error unless it is an .exr) and returns the mean with
// its summary line.
Rendered render_path_model(const Scene& scene, const Camera& camera, int width, int height,
                           const RenderSettings& settings);

}  // namespace luz::app
