// The renderer's fast path (a tile's primary and shadow rays traced ahead as Embree streams, see
// renderer.cpp render_tile) against the plain recursion of slide 26: trace() of each primary ray
// with nothing traced ahead, the same samples and the same random numbers. Two ways to the same
// picture, on every shipped scene, with area-light sampling and supersampling on.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/image.h"
#include "io/gltf_loader.h"
#include "raytracing/renderer.h"
#include "raytracing/sampling.h"
#include "raytracing/whitted.h"
#include "support.h"

namespace luz::rt {
namespace {

// The picture by the recursion alone: each sample's Random seeded as the renderer seeds it.
Image recursive_reference(const Scene& scene, const Intersector& intersector, const Camera& camera,
                          int width, int height, const WhittedOptions& options) {
  Counters counters;
  Whitted whitted(scene, intersector, options, counters);
  const PrimaryRays camera_rays(camera, width, height);
  const int samples = options.spp;  // a square
  const Rgb weight(1.0f / float(samples));
  std::vector<glm::vec2> offsets;
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      Random jitter(x, y, -1);
      stratified_pixel_samples(samples, jitter, offsets);
      Rgb sum(0.0f);
      for (int s = 0; s < samples; ++s) {
        whitted.reseed(Random(x, y, s));
        const Ray ray = camera_rays.through(glm::vec2(float(x), float(y)) + offsets[size_t(s)]);
        sum += whitted.trace(ray, 1, RayKind::primary, weight);
      }
      image.at(x, y) = sum * weight;
    }
  return image;
}

class StreamsEqualRecursion : public ::testing::TestWithParam<std::string> {};

TEST_P(StreamsEqualRecursion, OnEveryShippedScene) {
  const Scene scene = io::load_gltf(test::scene_dir() / (GetParam() + ".gltf")).scene;
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.spp = 4;
  options.light_samples = 2;
  options.max_depth = 5;
  const int width = 64, height = 48;
  const Image streamed = tracer.render(scene.cameras[0], width, height, options);
  const Image reference = recursive_reference(scene, tracer.intersector(options), scene.cameras[0],
                                              width, height, options);
  // Embree's stream and single-ray traversals find the same hit; allow for the last bit of t.
  float worst = 0.0f;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float a = streamed.at(x, y)[c], b = reference.at(x, y)[c];
        worst = std::max(worst, std::abs(a - b) / std::max(1.0f, std::abs(b)));
      }
  EXPECT_LE(worst, 1e-6f) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Shipped, StreamsEqualRecursion,
                         ::testing::Values("cornell_box", "cornell_spheres", "local_effects",
                                           "phong_spheres", "whitted"));

}  // namespace
}  // namespace luz::rt
