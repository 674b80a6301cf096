// The shaders written once in GLSL 330 core, compiled as GLSL ES 3.00 (gl/glsl_dialect.h), the
// web page's dialect, on the desktop's Mesa (a 4.3+ core context takes both): the programs the
// page needs compile, and the local models draw the same pictures bit for bit in both dialects
// (highp is the desktop's 32-bit float).
// The OpenGL context comes from the GlEnvironment of gl_environment.cpp (same binary).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "gl/glsl_dialect.h"
#include "gl/shader.h"
#include "io/gltf_loader.h"
#include "local/local_renderer.h"
#include "glsl_dialect_scope.h"
#include "support.h"

namespace luz {
namespace {

TEST(GlslDialect, TheDesktopContextSpeaksGlsl330) {
  EXPECT_EQ(gl::current_glsl_dialect(), gl::GlslDialect::desktop_330);
  const DialectScope es(gl::GlslDialect::es_300);
  EXPECT_EQ(gl::current_glsl_dialect(), gl::GlslDialect::es_300);
}

TEST(GlslDialect, TheHeaderIsTheFilesVersionOnTheDesktopAndEsWithPrecisionsForThePage) {
  EXPECT_EQ(gl::glsl_header(gl::GlslDialect::desktop_330, "#version 330 core"), "#version 330 core");
  const std::string es = gl::glsl_header(gl::GlslDialect::es_300, "#version 330 core");
  EXPECT_EQ(es.rfind("#version 300 es\n", 0), 0u) << es;
  for (const char* line : {"precision highp float;", "precision highp int;", "precision highp usampler2D;",
                           "#define LUZ_GLSL_ES 1"})
    EXPECT_NE(es.find(line), std::string::npos) << line;
}

// The fixed programs the page's local models and window use, compiled and linked as GLSL ES
// (the inspector's picking names a triangle by gl_VertexID / 3, not gl_PrimitiveID, which ES
// lacks). Flat shading's program is drawn below.
TEST(GlslDialect, TheLocalModelsFixedProgramsCompileAsGlslEs) {
  const DialectScope es(gl::GlslDialect::es_300);
  const std::vector<std::vector<std::string>> programs = {
      {"shadow.vert", "shadow.frag"}, {"display.vert", "display.frag"}, {"bare.vert", "bare.frag"},
      {"ray_tree.vert", "ray_tree.frag"}, {"pick.vert", "pick.frag"}};
  for (const auto& stages : programs) {
    const std::vector<std::string> shared =
        stages.front() == "display.vert" ? std::vector<std::string>{"srgb.glsl"} : std::vector<std::string>{};
    EXPECT_NO_THROW({ gl::Program program(stages, shared); }) << stages.front();
  }
}

// What GLSL ES lacks fails with the driver's message, not silently: the geometry stage (flat
// shading draws flat.vert there instead).
TEST(GlslDialect, WhatGlslEsLacksIsRefused) {
  const DialectScope es(gl::GlslDialect::es_300);
  EXPECT_THROW(gl::Program({"local.vert", "flat.geom", "flat.frag"}, {"srgb.glsl", "lighting.glsl"}), Error);
}

struct Case {
  const char* scene;
  Shading shading;
  bool shadows;
  bool fog;
  bool transparency = false;
};

// The three shading models on the shipped scenes, with and without shadows, fog and
// transparency: the same floats in both dialects, where flat shading is flat.geom on the desktop
// and flat.vert in GLSL ES, and transparency dual-source blending against two draws.
TEST(GlslDialect, LocalModelsDrawTheSamePictureInBothDialects) {
  const std::vector<Case> cases = {
      {"cornell_box.gltf", Shading::phong, false, false},  {"cornell_box.gltf", Shading::gouraud, false, false},
      {"cornell_box.gltf", Shading::phong, true, false},   {"phong_spheres.gltf", Shading::phong, false, true},
      {"local_effects.gltf", Shading::phong, true, false}, {"local_effects.gltf", Shading::gouraud, false, true},
      {"cornell_box.gltf", Shading::flat, false, false},   {"local_effects.gltf", Shading::flat, true, true},
      {"whitted.gltf", Shading::phong, true, false, true}, {"local_effects.gltf", Shading::phong, true, true, true},
      {"cornell_spheres.gltf", Shading::flat, true, false, true},
      {"local_effects.gltf", Shading::gouraud, false, false, true}};
  for (const Case& c : cases) {
    const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / c.scene);
    LocalOptions options;
    options.shading = c.shading;
    options.shadows.on = c.shadows;
    options.shadows.map_size = 256;
    options.fog.mode = c.fog ? FogMode::linear : FogMode::off;
    options.transparency.on = c.transparency;
    const Camera& camera = loaded.scene.cameras.front();
    constexpr int width = 160, height = 120;
    const auto draw = [&](gl::GlslDialect dialect) {
      const DialectScope scope(dialect);
      LocalRenderer renderer(loaded.scene);
      return renderer.render(camera, width, height, options);
    };
    const Image desktop = draw(gl::GlslDialect::desktop_330), es = draw(gl::GlslDialect::es_300);
    ASSERT_EQ(desktop.pixels.size(), es.pixels.size());
    // Flat shading's two programs hand the fragment its position through different stages, whose
    // interpolation may round the fog's distance differently in the last bit: there, the same
    // floats within float rounding (a relative 1e-6, a few units in the last place); everywhere
    // else bit for bit.
    const float rounding = c.shading == Shading::flat && c.fog ? 1e-6f : 0.0f;
    size_t different = 0, lit = 0;
    for (size_t i = 0; i < desktop.pixels.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        const float a = desktop.pixels[i][k], b = es.pixels[i][k];
        if (std::abs(a - b) > rounding * std::max(std::abs(a), std::abs(b))) {
          ++different;
          break;
        }
      }
      lit += desktop.pixels[i].r + desktop.pixels[i].g + desktop.pixels[i].b > 0.0f;
    }
    EXPECT_EQ(different, 0u) << c.scene << " " << to_string(c.shading) << (c.shadows ? " shadows" : "")
                             << (c.fog ? " fog" : "") << (c.transparency ? " transparency" : "");
    EXPECT_GT(lit, desktop.pixels.size() / 4) << c.scene << ": the picture shows the scene";
  }
}

}  // namespace
}  // namespace luz
