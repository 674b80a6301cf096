// `luz bench local`. For each scene, shading and effect: the LocalRenderer draws frames into a
// float framebuffer of the bench's size (what `luz render` and the viewer draw into), each frame
// finished (glFinish) before the clock stops, while the camera orbits the scene by a degree a
// frame, as a class orbiting it does. The limit is measured in the same run on the same GL: the
// same triangles with a shader that transforms the vertices and writes a constant, into the same
// framebuffer, with the same depth test. frame / bare says what the lighting costs beyond
// getting the triangles onto the screen.
#include "app/cli/bench/bench_local.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "app/cli/bench/bench_scenes.h"
#include "app/cli/bench/bench_table.h"
#include "app/cli/render_command.h"
#include "app/common/i18n.h"
#include "core/error.h"
#include "gl/framebuffer.h"
#include "gl/functions.h"
#include "gl/mesh_buffers.h"
#include "gl/offscreen_context.h"
#include "gl/shader.h"
#include "local/local_renderer.h"

namespace luz::app {

namespace {

using Clock = std::chrono::steady_clock;

std::optional<Shading> shading_named(const std::string& name) {
  for (Shading s : {Shading::flat, Shading::gouraud, Shading::phong})
    if (name == to_string(s)) return s;
  return std::nullopt;
}

// A row's shading and effect as the table names them: the values --shadings and --effects take,
// in the current language (gouraud and phong are names, the same in both).
const char* shading_label(const std::string& name) { return name == "flat" ? tr("flat") : name.c_str(); }

const char* effect_label(const std::string& effect) {
  if (effect == "none") return tr("none");
  if (effect == "fog") return tr("fog");
  if (effect == "shadows") return tr("shadows");
  if (effect == "transparency") return tr("transparency");
  if (effect == "reflection") return tr("reflection");
  if (effect == "all") return tr("all");
  return effect.c_str();
}

// The options of one row: the plain model, one of slide 19's effects, or all of them.
std::optional<LocalOptions> options_for(Shading shading, const std::string& effect) {
  LocalOptions options;
  options.shading = shading;
  const bool all = effect == "all";
  if (effect == "none") return options;
  if (all || effect == "fog") options.fog.mode = FogMode::linear;
  if (all || effect == "shadows") options.shadows.on = true;
  if (all || effect == "transparency") options.transparency.on = true;
  if (all || effect == "reflection") options.reflection.on = true;
  if (!all && effect != "fog" && effect != "shadows" && effect != "transparency" && effect != "reflection")
    return std::nullopt;
  return options;
}

// The camera of frame `frame`: the scene's first, turned about the vertical axis through the
// scene's centre by one degree per frame.
Camera orbited(const Camera& camera, const glm::vec3& centre, int frame) {
  Camera c = camera;
  const glm::mat4 turn = glm::translate(glm::mat4(1.0f), centre) *
                         glm::rotate(glm::mat4(1.0f), glm::radians(float(frame)), glm::vec3(0, 1, 0)) *
                         glm::translate(glm::mat4(1.0f), -centre);
  c.to_world = turn * camera.to_world;
  return c;
}

// Times `frames` calls of draw(frame) after two untimed ones, each finished before the next.
template <typename Draw>
Timing time_frames(int frames, const Draw& draw) {
  for (int f = 0; f < 2; ++f) draw(f);
  glFinish();
  std::vector<double> ms;
  for (int f = 0; f < frames; ++f) {
    const auto start = Clock::now();
    draw(f + 2);
    glFinish();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  return best_and_median(std::move(ms));  // ms per frame
}

// The bare limit: the scene's triangles, trivially shaded, into `target`.
Timing time_bare(const Scene& scene, const Camera& camera, const glm::vec3& centre,
                 const gl::Framebuffer& target, int frames) {
  std::vector<gl::MeshBuffers> meshes;
  for (const Mesh& mesh : scene.meshes) meshes.emplace_back(mesh);
  gl::Program bare({"bare.vert", "bare.frag"});
  const float aspect = float(target.width()) / float(target.height());
  const Bounds bounds = scene.bounds();
  return time_frames(frames, [&](int frame) {
    const Camera c = orbited(camera, centre, frame);
    target.bind();
    const float background[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    const float far_depth = 1.0f;
    glDepthMask(GL_TRUE);
    glClearBufferfv(GL_COLOR, 0, background);
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    bare.use();
    bare.set("u_view_projection", c.projection(aspect, bounds) * c.view());
    for (const gl::MeshBuffers& mesh : meshes) mesh.draw();
    glUseProgram(0);
  });
}

}  // namespace

void add_local_bench_flags(CLI::App& bench, LocalBenchSettings& settings) {
  bench.add_option_function<std::string>(
      "--size",
      [&settings](const std::string& text) {
        if (!parse_size(text, settings.width, settings.height))
          throw CLI::ValidationError("--size", tr("expected WxH, e.g. 1280x720"));
      },
      tr("Image size WxH (default 1280x720)"));
  bench.add_option("--frames", settings.frames, tr("Timed frames per row (best and median)"))
      ->check(CLI::Range(1, 1000))->capture_default_str();
  bench.add_option("--scenes", settings.scenes, tr("Shipped scene names or glTF paths"))
      ->delimiter(',')->capture_default_str();
  bench.add_option("--shadings", settings.shadings, tr("flat, gouraud, phong"))
      ->delimiter(',')->capture_default_str();
  bench.add_option("--effects", settings.effects,
                   tr("none, fog, shadows, transparency, reflection, all (slide 19)"))
      ->delimiter(',')->capture_default_str();
}

int run_bench_local(const LocalBenchSettings& settings) {
  try {
    for (const std::string& name : settings.shadings)
      if (!shading_named(name)) throw Error(ErrorKind::usage, trf("--shadings: unknown shading \"{}\"", name));
    for (const std::string& effect : settings.effects)
      if (!options_for(Shading::phong, effect))
        throw Error(ErrorKind::usage, trf("--effects: unknown effect \"{}\"", effect));

    const std::vector<BenchScene> scenes = load_bench_scenes(settings.scenes);
    gl::OffscreenContext context;
    fmt::print("{}\n", trf("luz bench local: {}x{}, {} frames a row (best / median ms), orbiting 1 degree "
                            "a frame; {}", settings.width, settings.height, settings.frames,
                            gl_version_string()));
    // The lit frames, then the bare triangles, then frame / bare (medians).
    BenchTable table({{.header = tr("scene"), .width = 16, .left = true},
                      {.header = tr("shading"), .width = 8, .left = true},
                      {.header = tr("effect"), .width = 13, .left = true},
                      {.header = tr("best ms"), .width = 9},
                      {.header = tr("median"), .width = 9},
                      {.header = tr("fps"), .width = 7, .bar_after = true},
                      {.header = tr("bare ms"), .width = 8},
                      {.header = tr("median"), .width = 8, .bar_after = true},
                      {.header = tr("ratio"), .width = 6}});
    for (const std::string& shading : settings.shadings) table.fit(1, shading_label(shading));
    for (const std::string& effect : settings.effects) table.fit(2, effect_label(effect));
    fmt::print("{}", table.header());
    gl::Framebuffer target(settings.width, settings.height);
    for (const auto& [name, loaded] : scenes) {
      const Scene& scene = loaded.scene;
      const Camera& camera = scene.cameras.front();
      const glm::vec3 centre = scene.bounds().empty() ? glm::vec3(0.0f) : scene.bounds().centre();
      const Timing bare = time_bare(scene, camera, centre, target, settings.frames);
      LocalRenderer renderer(scene);
      for (const std::string& shading : settings.shadings)
        for (const std::string& effect : settings.effects) {
          const LocalOptions options = *options_for(*shading_named(shading), effect);
          const Timing frame = time_frames(settings.frames, [&](int f) {
            target.bind();
            renderer.draw(orbited(camera, centre, f), settings.width, settings.height, options);
          });
          const auto figure = [](double value) { return fmt::format("{:.1f}", value); };
          fmt::print("{}", table.row({name, shading_label(shading), effect_label(effect), figure(frame.best),
                                      figure(frame.median), figure(1000.0 / frame.median), figure(bare.best),
                                      figure(bare.median), figure(frame.median / bare.median)}));
          std::fflush(stdout);
        }
    }
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
