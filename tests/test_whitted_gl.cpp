// Two implementations of the same formula must agree: the tracer at depth 1 (no reflected or
// transmitted rays) without shadow rays, and the GL Phong rasteriser (shaders/lighting.glsl),
// on the shipped scenes from their cameras, one sample per pixel centre.
//
// Compared away from silhouettes: only pixels whose 3x3 neighbourhood sees one mesh (or only the
// background) through the tracer's primary rays, since a silhouette pixel is a different surface
// in each renderer depending on rasterisation rules. Tolerance per channel:
// |tracer - GL| <= 0.5% of the GL value + 1e-4 of the image's largest value: both evaluate the
// same float formula at the same point with the same normal, so what is left is float rounding in
// different orders and the GPU's pow/normalize (Mesa llvmpipe), amplified where a tight highlight
// (n = 200) turns quickly.
#include <algorithm>
#include <cmath>
#include <memory>
#include <ostream>

#include <gtest/gtest.h>

#include "core/image.h"
#include "io/gltf_loader.h"
#include "local/local_renderer.h"
#include "raytracing/renderer.h"
#include "support.h"

namespace luz {
namespace {

struct Case {
  const char* scene;
  int width, height;
  bool blinn;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.scene << " " << c.width << "x" << c.height << (c.blinn ? " blinn" : "");
}

class TracerAgreesWithGl : public testing::TestWithParam<Case> {};

TEST_P(TracerAgreesWithGl, AtDepthOneWithoutShadowsAwayFromSilhouettes) {
  const Case c = GetParam();
  const Scene scene = io::load_gltf(test::scene_dir() / (std::string(c.scene) + ".gltf")).scene;
  const Camera& camera = scene.cameras[0];

  LocalOptions local;
  local.shading = Shading::phong;
  local.terms.blinn = c.blinn;
  LocalRenderer raster(scene);
  const Image gl = raster.render(camera, c.width, c.height, local);

  rt::WhittedOptions options;
  options.max_depth = 0;  // "depth 0": the local model only
  options.shadows = false;
  options.terms.blinn = c.blinn;
  rt::WhittedRenderer tracer(scene);
  const Image traced = tracer.render(camera, c.width, c.height, options);
  EXPECT_EQ(tracer.counters().total_rays(), tracer.counters()[rt::RayKind::primary]);

  std::vector<int> mesh(size_t(c.width) * c.height);
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x)
      mesh[size_t(y) * c.width + x] =
          tracer.primary_hit(camera, c.width, c.height, {float(x) + 0.5f, float(y) + 0.5f}, options).mesh;

  float largest = 0.0f;
  for (const Rgb& p : gl.pixels) largest = std::max({largest, p.r, p.g, p.b});
  int compared = 0, off = 0;
  for (int y = 1; y + 1 < c.height; ++y)
    for (int x = 1; x + 1 < c.width; ++x) {
      const int m = mesh[size_t(y) * c.width + x];
      bool interior = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) interior &= mesh[size_t(y + dy) * c.width + x + dx] == m;
      if (!interior) continue;
      ++compared;
      for (int ch = 0; ch < 3; ++ch) {
        const float a = traced.at(x, y)[ch], b = gl.at(x, y)[ch];
        if (std::abs(a - b) > 0.005f * b + 1e-4f * largest) {
          if (++off <= 10)
            ADD_FAILURE() << c.scene << " pixel " << x << "," << y << " channel " << ch
                          << ": tracer " << a << ", GL " << b;
        }
      }
    }
  EXPECT_EQ(off, 0);
  // The checkerboard's squares are two meshes, so their edges are left out too.
  EXPECT_GT(compared, c.width * c.height * 2 / 3) << "most of the picture is compared";
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, TracerAgreesWithGl,
                         testing::Values(Case{"whitted", 160, 120, false},
                                         Case{"whitted", 160, 120, true},
                                         Case{"cornell_box", 120, 120, false},
                                         Case{"phong_spheres", 160, 120, false}),
                         [](const testing::TestParamInfo<Case>& param) {
                           return std::string(param.param.scene) + (param.param.blinn ? "_blinn" : "");
                         });

}  // namespace
}  // namespace luz
