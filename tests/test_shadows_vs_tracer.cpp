// The Whitted tracer stays the reference for slide 19's shadows (issue 7): with shadows on, the
// shadow-mapped GL Phong image and the tracer at depth 0 (the local model and its shadow rays,
// no reflected or transmitted rays) agree on the shipped scenes, from their cameras.
//
// Both decide S_i per light at the same point: the tracer by a shadow ray to the light (to an
// emissive triangle's centroid, --light-samples 1), the rasteriser by a shadow map from the same
// light position (an emitter's cube map from its centroid: SCENES.md's "one sample at the
// centroid"). Transparent surfaces block in both (README, slide 19: "Transparent surfaces shadow
// like opaque ones"; the tracer's shadow rays stop at any surface).
//
// Compared away from silhouettes and away from shadow edges: only pixels whose 3x3 neighbourhood
// sees one mesh through the tracer's primary rays AND has one shadow status, the set of lights
// whose shadow rays the tracer found blocked (from each pixel's ray tree). A shadow map's edge
// lies within a texel or two of the exact one (texels, bias), which is the edge pixels' business,
// not this test's. Tolerance per channel, as test_whitted_gl.cpp: |tracer - GL| <= 0.5% of the
// GL value + 1e-4 of the image's largest value. Where both agree a point is lit or shadowed they
// evaluate the same float formula, so the agreement is near exact; a point one of them wrongly
// shadows (acne from too small a bias) or wrongly lights (a leak) is off by a light's whole term.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

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
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.scene << " " << c.width << "x" << c.height; }

// What a pixel's primary hit is, for the masks: the mesh it sees and which lights' shadow rays
// are blocked there (a bit per light index, folded modulo 64: the shipped scenes have fewer).
struct PixelStatus {
  int mesh = -1;
  uint64_t blocked = 0;
  bool operator==(const PixelStatus&) const = default;
};

class ShadowsAgreeWithTracer : public testing::TestWithParam<Case> {};

TEST_P(ShadowsAgreeWithTracer, AtDepthZeroAwayFromSilhouettesAndShadowEdges) {
  const Case c = GetParam();
  const Scene scene = io::load_gltf(test::scene_dir() / (std::string(c.scene) + ".gltf")).scene;
  const Camera& camera = scene.cameras[0];

  LocalOptions local;
  local.shading = Shading::phong;
  local.shadows.on = true;  // the defaults otherwise: bias, slope, offset, 1024-texel maps
  LocalRenderer raster(scene);
  const Image gl = raster.render(camera, c.width, c.height, local);

  rt::WhittedOptions options;
  options.max_depth = 0;  // "depth 0": the local model (depth 1: the same, see whitted_options.h)
  options.shadows = true;
  options.light_samples = 1;
  rt::WhittedRenderer tracer(scene);
  const Image traced = tracer.render(camera, c.width, c.height, options);
  const rt::Counters counters = tracer.counters();
  EXPECT_GT(counters[rt::RayKind::shadow], 0u);
  EXPECT_EQ(counters[rt::RayKind::reflected] + counters[rt::RayKind::transmitted], 0u);

  // The mask: each pixel's mesh and blocked lights, from its ray tree (one primary ray, its
  // shadow rays).
  std::vector<PixelStatus> status(size_t(c.width) * c.height);
  size_t shadowed_pixels = 0;
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      PixelStatus& s = status[size_t(y) * c.width + x];
      s.mesh = tracer.primary_hit(camera, c.width, c.height, {float(x) + 0.5f, float(y) + 0.5f}, options).mesh;
      const rt::RayTree tree = tracer.trace_pixel(camera, c.width, c.height, x, y, options);
      for (const rt::RayTreeNode& node : tree.nodes)
        if (node.kind == rt::RayKind::shadow && node.hit) s.blocked |= uint64_t(1) << (node.light % 64);
      shadowed_pixels += s.blocked != 0;
    }

  float largest = 0.0f;
  for (const Rgb& p : gl.pixels) largest = std::max({largest, p.r, p.g, p.b});
  int compared = 0, compared_in_shadow = 0, off = 0;
  for (int y = 1; y + 1 < c.height; ++y)
    for (int x = 1; x + 1 < c.width; ++x) {
      const PixelStatus& s = status[size_t(y) * c.width + x];
      bool interior = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) interior &= status[size_t(y + dy) * c.width + x + dx] == s;
      if (!interior) continue;
      ++compared;
      compared_in_shadow += s.blocked != 0;
      for (int ch = 0; ch < 3; ++ch) {
        const float a = traced.at(x, y)[ch], b = gl.at(x, y)[ch];
        if (std::abs(a - b) > 0.005f * b + 1e-4f * largest) {
          if (++off <= 10)
            ADD_FAILURE() << c.scene << " pixel " << x << "," << y << " channel " << ch << ": tracer " << a
                          << ", GL with shadow maps " << b << (s.blocked ? " (in shadow)" : " (lit)");
        }
      }
    }
  EXPECT_EQ(off, 0) << "pixels off out of " << compared << " compared";
  // The test compares what it is about: most of the picture, and shadowed pixels among it.
  EXPECT_GT(compared, c.width * c.height / 2) << "most of the picture is compared";
  EXPECT_GT(compared_in_shadow, int(shadowed_pixels) / 3) << "most shadowed pixels are compared";
  EXPECT_GT(compared_in_shadow, c.width * c.height / 100) << "the scene has shadows to compare";
  std::printf("%s: %d pixels compared, %d of them in shadow (of %zu shadowed)\n", c.scene, compared,
              compared_in_shadow, shadowed_pixels);
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, ShadowsAgreeWithTracer,
                         testing::Values(Case{"cornell_box", 120, 120}, Case{"whitted", 160, 120},
                                         Case{"local_effects", 160, 120}),
                         [](const testing::TestParamInfo<Case>& param) { return std::string(param.param.scene); });

}  // namespace
}  // namespace luz
