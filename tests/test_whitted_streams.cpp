// Three ways to the same picture, on every shipped scene, with area-light sampling and
// supersampling on:
//   - slide 26's loop (WhittedRenderer::render_per_pixel): for each pixel, trace() of each of its
//     primary rays with nothing traced ahead, on one thread;
//   - the recursive renderer (a tile's primary and shadow rays traced ahead as Embree streams,
//     see renderer.cpp render_tile, then the recursion);
//   - the wavefront renderer (wavefront.h: every generation of rays as streams).
// The same samples and, from each ray's place in its ray tree, the same random numbers.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/image.h"
#include "io/gltf_loader.h"
#include "raytracing/diffuse_source.h"
#include "raytracing/renderer.h"
#include "raytracing/whitted.h"
#include "support.h"

namespace luz::rt {
namespace {

// The largest difference between two pictures, relative where a value exceeds 1.
float worst_difference(const Image& a, const Image& b) {
  float worst = 0.0f;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float u = a.at(x, y)[c], v = b.at(x, y)[c];
        worst = std::max(worst, std::abs(u - v) / std::max(1.0f, std::abs(v)));
      }
  return worst;
}

// A stand-in for the radiosity solution of the hybrid: some radiance that varies with the
// mesh, the triangle and the point on it, so that a hit shaded with another hit's would show.
class FakeDiffuse : public DiffuseSource {
public:
  Rgb diffuse_radiance(int mesh, int triangle, glm::vec2 b) const override {
    return Rgb(0.1f * float(mesh % 5) + 0.3f * b.x, 0.05f * float(triangle % 7), 0.2f + 0.4f * b.y);
  }
};

const std::string kShippedScenes[] = {"cornell_box", "cornell_spheres", "local_effects",
                                      "phong_spheres", "whitted"};
constexpr int kWidth = 64, kHeight = 48;

class StreamsEqualRecursion : public ::testing::TestWithParam<std::string> {};

// The tiled renderers, recursive and wavefront, against slide 26's loop. Within 1e-6 (relative
// above 1), not to the bit: Embree's stream and single-ray traversals find the same hit but may
// differ in the last bit of t, and the wavefront adds throughput x local colour where the
// recursion nests local + kr (...), which rounds differently.
TEST_P(StreamsEqualRecursion, OnEveryShippedScene) {
  const Scene scene = io::load_gltf(test::scene_dir() / (GetParam() + ".gltf")).scene;
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.light_samples = 2;
  options.max_depth = 5;
  for (const int spp : {4, 1}) {  // jittered samples; one at the centre, the light still sampled
    options.spp = spp;
    const Image reference = tracer.render_per_pixel(scene.cameras[0], kWidth, kHeight, options);
    for (const RendererKind renderer : {RendererKind::recursive, RendererKind::wavefront}) {
      options.renderer = renderer;
      const Image tiled = tracer.render(scene.cameras[0], kWidth, kHeight, options);
      EXPECT_LE(worst_difference(tiled, reference), 1e-6f)
          << GetParam() << ", spp " << spp << (renderer == RendererKind::wavefront ? ", wavefront" : "");
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Shipped, StreamsEqualRecursion, ::testing::ValuesIn(kShippedScenes));

// The wavefront renderer against the recursive one: the same picture (within float rounding:
// the wavefront adds throughput x local colour where the recursion nests local + kr (...)), the
// same rays of every kind, and the same rays logged for the benchmark.
struct Setting {
  const char* name;
  int spp;
  int light_samples;
  bool fresnel;
  bool shadows;
  bool hybrid;  // with a (fake) diffuse source
};

const Setting kSettings[] = {
    {"plain", 1, 1, false, true, false},
    {"soft_fresnel", 4, 2, true, true, false},
    {"no_shadows", 9, 3, true, false, false},
    {"hybrid", 4, 2, true, true, true},
};

class WavefrontEqualsRecursion
    : public ::testing::TestWithParam<std::tuple<std::string, Setting>> {};

TEST_P(WavefrontEqualsRecursion, PictureAndRays) {
  const auto& [name, setting] = GetParam();
  const Scene scene = io::load_gltf(test::scene_dir() / (name + ".gltf")).scene;
  WhittedRenderer tracer(scene);
  const FakeDiffuse diffuse;
  if (setting.hybrid) tracer.set_diffuse_source(&diffuse);
  WhittedOptions options;
  options.max_depth = 5;
  options.spp = setting.spp;
  options.light_samples = setting.light_samples;
  options.fresnel = setting.fresnel;
  options.shadows = setting.shadows;

  tracer.keep_rays(true);
  options.renderer = RendererKind::recursive;
  const Image recursive = tracer.render(scene.cameras[0], kWidth, kHeight, options);
  const Counters recursive_counters = tracer.counters();
  const std::vector<RecordedRay> recursive_rays = tracer.take_rays();
  options.renderer = RendererKind::wavefront;
  const Image wavefront = tracer.render(scene.cameras[0], kWidth, kHeight, options);
  const Counters wavefront_counters = tracer.counters();
  const std::vector<RecordedRay> wavefront_rays = tracer.take_rays();

  EXPECT_LE(worst_difference(wavefront, recursive), 1e-6f);
  for (int k = 0; k < kRayKinds; ++k)
    EXPECT_EQ(wavefront_counters[RayKind(k)], recursive_counters[RayKind(k)]) << to_string(RayKind(k));
  EXPECT_EQ(wavefront_counters.samples, recursive_counters.samples);
  EXPECT_GT(recursive_counters[RayKind::primary], 0u);
  if (setting.shadows && !setting.hybrid) {  // the hybrid's lights add highlights only: maybe none
    EXPECT_GT(recursive_counters[RayKind::shadow], 0u);
  }
  // The benchmark's log holds the same rays, in another order.
  ASSERT_EQ(wavefront_rays.size(), recursive_rays.size());
  ASSERT_EQ(wavefront_rays.size(), recursive_counters.total_rays());
  const auto key = [](const RecordedRay& r) {
    return std::tuple(int(r.kind), r.ray.origin.x, r.ray.origin.y, r.ray.origin.z, r.ray.direction.x,
                      r.ray.direction.y, r.ray.direction.z, r.ray.tfar);
  };
  const auto sorted = [&](const std::vector<RecordedRay>& rays) {
    std::vector<decltype(key(rays[0]))> keys;
    for (const RecordedRay& r : rays) keys.push_back(key(r));
    std::sort(keys.begin(), keys.end());
    return keys;
  };
  EXPECT_TRUE(sorted(wavefront_rays) == sorted(recursive_rays));
}

INSTANTIATE_TEST_SUITE_P(Shipped, WavefrontEqualsRecursion,
                         ::testing::Combine(::testing::ValuesIn(kShippedScenes), ::testing::ValuesIn(kSettings)),
                         [](const auto& test) {
                           return std::get<0>(test.param) + "_" + std::get<1>(test.param).name;
                         });

// Each term of the formula switched off in turn (and Blinn's highlight for Phong's): the
// wavefront's lanes read what is left of each material once per render, so each switch must
// reach them as it reaches the recursion, and change the picture.
TEST(WavefrontEqualsRecursion, EachTermSwitchedOff) {
  const std::pair<const char*, bool TermSwitches::*> switches[] = {
      {"ambient", &TermSwitches::ambient},   {"diffuse", &TermSwitches::diffuse},
      {"specular", &TermSwitches::specular}, {"emission", &TermSwitches::emission},
      {"blinn", &TermSwitches::blinn}};
  for (const char* name : {"cornell_spheres", "whitted"}) {
    const Scene scene = io::load_gltf(test::scene_dir() / (std::string(name) + ".gltf")).scene;
    WhittedRenderer tracer(scene);
    WhittedOptions options;
    options.max_depth = 3;
    options.renderer = RendererKind::wavefront;
    const Image all_on = tracer.render(scene.cameras[0], kWidth, kHeight, options);
    for (const auto& [term, flag] : switches) {
      WhittedOptions changed = options;
      changed.terms.*flag = !(options.terms.*flag);
      const Image wavefront = tracer.render(scene.cameras[0], kWidth, kHeight, changed);
      changed.renderer = RendererKind::recursive;
      const Image recursive = tracer.render(scene.cameras[0], kWidth, kHeight, changed);
      EXPECT_LE(worst_difference(wavefront, recursive), 1e-6f) << name << ", " << term;
      const bool has_term = std::string(name) != "whitted" || std::string(term) != "emission";  // no emitter
      if (has_term) {
        EXPECT_GT(worst_difference(wavefront, all_on), 1e-3f) << name << ", " << term << " changes nothing";
      }
    }
  }
}

// Whitted's scene with its checkerboard's first material textured and every other mesh coloured
// per vertex: kd from the texture (bilinear, repeating) and from COLOR_0, which no shipped scene
// has, the same in both renderers and read at all.
Scene textured_and_coloured_whitted() {
  Scene scene = io::load_gltf(test::scene_dir() / "whitted.gltf").scene;
  Texture texture;
  texture.width = 3;
  texture.height = 2;
  texture.texels = {Rgb(1, 0.2f, 0.2f), Rgb(0.2f, 1, 0.2f), Rgb(0.2f, 0.2f, 1),
                    Rgb(1, 1, 0.2f), Rgb(0.2f, 1, 1), Rgb(0.5f)};
  scene.textures.push_back(texture);
  scene.materials[0].kd_texture = int(scene.textures.size()) - 1;
  for (Mesh& mesh : scene.meshes) {
    if (mesh.material == 0) {
      mesh.uvs.clear();
      for (const glm::vec3& p : mesh.positions) mesh.uvs.emplace_back(0.37f * p.x, 0.29f * p.z);
    } else {
      mesh.colors.clear();
      for (const glm::vec3& p : mesh.positions)
        mesh.colors.emplace_back(0.5f + 0.5f * std::sin(p.x), 0.5f + 0.5f * std::cos(p.y), 0.7f);
    }
  }
  return scene;
}

TEST(WavefrontEqualsRecursion, TexturedAndVertexColouredSurfaces) {
  const Scene scene = textured_and_coloured_whitted();
  ASSERT_TRUE(std::any_of(scene.meshes.begin(), scene.meshes.end(),
                          [](const Mesh& m) { return m.material == 0; }));
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.max_depth = 5;
  options.spp = 4;
  options.fresnel = true;
  options.renderer = RendererKind::recursive;
  const Image recursive = tracer.render(scene.cameras[0], kWidth, kHeight, options);
  options.renderer = RendererKind::wavefront;
  const Image wavefront = tracer.render(scene.cameras[0], kWidth, kHeight, options);
  EXPECT_LE(worst_difference(wavefront, recursive), 1e-6f);

  const Scene plain = io::load_gltf(test::scene_dir() / "whitted.gltf").scene;
  WhittedRenderer plain_tracer(plain);
  EXPECT_GT(worst_difference(plain_tracer.render(plain.cameras[0], kWidth, kHeight, options), wavefront), 0.1f)
      << "the texture and the vertex colours change the picture";
}

// Through the brute-force intersector, which counts its tests: both renderers make the same ones.
TEST(WavefrontEqualsRecursion, SameIntersectionTests) {
  const Scene scene = io::load_gltf(test::scene_dir() / "cornell_spheres.gltf").scene;
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.brute_force = true;
  options.fresnel = true;
  options.renderer = RendererKind::recursive;
  const Image recursive = tracer.render(scene.cameras[0], 32, 24, options);
  const uint64_t recursive_tests = tracer.counters().intersection_tests;
  options.renderer = RendererKind::wavefront;
  const Image wavefront = tracer.render(scene.cameras[0], 32, 24, options);
  EXPECT_GT(recursive_tests, 0u);
  EXPECT_EQ(tracer.counters().intersection_tests, recursive_tests);
  EXPECT_LE(worst_difference(wavefront, recursive), 1e-6f);
}

// Embree may answer a shadow ray that grazes an edge differently with other rays beside it in a
// packet, so the wavefront sends the first generation's shadow rays in the recursion's order: each
// sample's, light by light, sample by sample. At depth 1 the logs hold just that generation.
TEST(WavefrontEqualsRecursion, ShadowRaysInTheRecursionsOrder) {
  const Scene scene = io::load_gltf(test::scene_dir() / "cornell_spheres.gltf").scene;
  ASSERT_GE(scene.lights.size() + scene.area_lights.size(), 2u);
  WhittedRenderer tracer(scene);
  tracer.keep_rays(true);
  WhittedOptions options;
  options.max_depth = 1;
  options.spp = 4;
  options.light_samples = 2;
  const auto shadow_rays = [&](RendererKind renderer) {
    options.renderer = renderer;
    tracer.render(scene.cameras[0], kWidth, kHeight, options);
    std::vector<std::tuple<float, float, float, float, float, float, float>> rays;
    for (const RecordedRay& r : tracer.take_rays())
      if (r.kind == RayKind::shadow)
        rays.emplace_back(r.ray.origin.x, r.ray.origin.y, r.ray.origin.z, r.ray.direction.x,
                          r.ray.direction.y, r.ray.direction.z, r.ray.tfar);
    return rays;
  };
  const auto recursive = shadow_rays(RendererKind::recursive);
  EXPECT_GT(recursive.size(), size_t(kWidth * kHeight));
  EXPECT_TRUE(shadow_rays(RendererKind::wavefront) == recursive);
}

// render() in steps (the page without threads traces a tile a step, between its frames): the
// same picture bit for bit and the same counts of rays however the tiles are split, each tile
// reported once with the count so far; a cancel between steps leaves the tiles after it black.
TEST(WhittedSteps, TheSamePictureHoweverTheTilesAreSplit) {
  const Scene scene = io::load_gltf(test::scene_dir() / "whitted.gltf").scene;
  WhittedRenderer tracer(scene);
  WhittedOptions options;
  options.max_depth = 5;
  options.tile_size = 16;
  const Image whole = tracer.render(scene.cameras[0], kWidth, kHeight, options);
  const Counters counted = tracer.counters();
  for (const size_t per_step : {size_t(1), size_t(5)}) {
    WhittedRenderer::Steps steps = tracer.begin(scene.cameras[0], kWidth, kHeight, options);
    ASSERT_EQ(steps.tiles(), size_t((kWidth / 16) * (kHeight / 16)));
    std::vector<int> reported;
    size_t calls = 0;
    while (!steps.done()) {
      tracer.trace(steps, per_step, [&](const TileDone& tile) { reported.push_back(tile.done); });
      ++calls;
    }
    EXPECT_EQ(calls, (steps.tiles() + per_step - 1) / per_step);
    const Image stepped = tracer.finish(steps);
    EXPECT_EQ(stepped.pixels, whole.pixels) << per_step << " tiles a step";
    EXPECT_EQ(tracer.counters().rays, counted.rays);
    EXPECT_EQ(tracer.counters().samples, counted.samples);
    EXPECT_GT(tracer.counters().total_rays(), 0u);
    ASSERT_EQ(reported.size(), steps.tiles());
    for (size_t i = 0; i < reported.size(); ++i) EXPECT_EQ(reported[i], int(i + 1));
  }
  // Cancelled after two steps of one tile: the rest skipped, black, and not reported.
  WhittedRenderer::Steps steps = tracer.begin(scene.cameras[0], kWidth, kHeight, options);
  const std::atomic<bool> cancel{true};
  tracer.trace(steps, 2);
  int reported = 0;
  tracer.trace(steps, steps.tiles(), [&](const TileDone&) { ++reported; }, &cancel);
  EXPECT_TRUE(steps.done());
  EXPECT_EQ(reported, 0);
  const Image cancelled = tracer.finish(steps);
  EXPECT_EQ(cancelled.at(kWidth - 1, kHeight - 1), Rgb(0.0f));
  EXPECT_EQ(cancelled.at(0, 0), whole.at(0, 0));
}

// `luz bench whitted` traces the logged rays bare in the calls the renderer made, so the log must
// say which rays went to Embree together: a tile's primary rays in one stream with both
// renderers; the wavefront's later generations in streams too, the recursion's one ray at a time.
TEST(WavefrontEqualsRecursion, TheLogKeepsEachRenderersStreams) {
  const Scene scene = io::load_gltf(test::scene_dir() / "whitted.gltf").scene;
  WhittedRenderer tracer(scene);
  tracer.keep_rays(true);
  WhittedOptions options;
  options.max_depth = 5;
  const size_t tiles = size_t(kWidth / options.tile_size) * size_t(kHeight / options.tile_size);
  const size_t tile_rays = size_t(options.tile_size) * size_t(options.tile_size);
  // For each kind: the rays in streams, the streams' starts, the rays traced alone.
  struct Calls {
    size_t in_stream = 0, streams = 0, alone = 0;
  };
  const auto calls_of = [&](RendererKind renderer) {
    options.renderer = renderer;
    tracer.render(scene.cameras[0], kWidth, kHeight, options);
    std::vector<Calls> calls(kRayKinds);
    std::vector<size_t> longest(kRayKinds), current(kRayKinds);
    for (const RecordedRay& r : tracer.take_rays()) {
      Calls& c = calls[size_t(r.kind)];
      size_t& run = current[size_t(r.kind)];
      if (r.traced == Traced::alone) {
        ++c.alone;
        continue;
      }
      ++c.in_stream;
      if (r.traced == Traced::starts_stream) {
        ++c.streams;
        run = 0;
      }
      EXPECT_GT(c.streams, 0u) << "a stream's ray before any stream started";
      longest[size_t(r.kind)] = std::max(longest[size_t(r.kind)], ++run);
    }
    EXPECT_EQ(longest[size_t(RayKind::primary)], tile_rays);
    return calls;
  };
  for (RendererKind renderer : {RendererKind::recursive, RendererKind::wavefront}) {
    const std::vector<Calls> calls = calls_of(renderer);
    const Calls& primary = calls[size_t(RayKind::primary)];
    EXPECT_EQ(primary.streams, tiles);
    EXPECT_EQ(primary.in_stream, tiles * tile_rays);
    EXPECT_EQ(primary.alone, 0u);
    EXPECT_GT(calls[size_t(RayKind::shadow)].streams, 0u);
    for (RayKind kind : {RayKind::reflected, RayKind::transmitted}) {
      const Calls& c = calls[size_t(kind)];
      if (renderer == RendererKind::recursive) {
        EXPECT_GT(c.alone, 0u) << to_string(kind);
        EXPECT_EQ(c.in_stream, 0u) << to_string(kind);
      } else {
        EXPECT_GT(c.streams, 0u) << to_string(kind);
        EXPECT_EQ(c.alone, 0u) << to_string(kind);
      }
    }
  }
}

}  // namespace
}  // namespace luz::rt
