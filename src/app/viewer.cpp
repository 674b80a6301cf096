#include "app/viewer.h"

#define GLFW_INCLUDE_NONE  // GL comes through gl/functions.h, never GL/gl.h
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include "core/error.h"
#include "gl/window_context.h"
#include "io/gltf_loader.h"
#include "local/local_renderer.h"

namespace luz::app {
namespace {

// Keys of the classroom: 1 flat, 2 Gouraud, 3 Phong; A, D, S toggle the ambient, diffuse and
// specular terms; B Phong/Blinn; Esc quits.
void apply_key(int key, LocalOptions& options, bool& quit) {
  switch (key) {
    case GLFW_KEY_1: options.shading = Shading::flat; break;
    case GLFW_KEY_2: options.shading = Shading::gouraud; break;
    case GLFW_KEY_3: options.shading = Shading::phong; break;
    case GLFW_KEY_A: options.ambient = !options.ambient; break;
    case GLFW_KEY_D: options.diffuse = !options.diffuse; break;
    case GLFW_KEY_S: options.specular = !options.specular; break;
    case GLFW_KEY_B: options.blinn = !options.blinn; break;
    case GLFW_KEY_ESCAPE: quit = true; break;
    default: break;
  }
}

struct KeyQueue {
  int pending = -1;
};

}  // namespace

int run_viewer(const std::string& scene_path) {
  try {
    io::LoadedScene loaded = io::load_gltf(scene_path);
    for (const std::string& warning : loaded.warnings) fmt::print(stderr, "warning: {}\n", warning);
    const Scene& scene = loaded.scene;
    const Camera& camera = scene.cameras.front();

    gl::WindowContext window(960, int(960 / (camera.aspect > 0 ? camera.aspect : 4.0f / 3.0f)),
                             "Luz - " + scene_path);
    KeyQueue keys;
    glfwSetWindowUserPointer(window.handle(), &keys);
    glfwSetKeyCallback(window.handle(), [](GLFWwindow* w, int key, int, int action, int) {
      if (action == GLFW_PRESS) static_cast<KeyQueue*>(glfwGetWindowUserPointer(w))->pending = key;
    });

    LocalRenderer renderer(scene);
    LocalOptions options;
    bool quit = false;
    fmt::print("keys: 1 flat, 2 Gouraud, 3 Phong; A/D/S ambient/diffuse/specular; B Blinn; Esc quit\n");
    while (!window.should_close() && !quit) {
      window.poll();
      if (keys.pending >= 0) apply_key(keys.pending, options, quit);
      keys.pending = -1;
      const glm::ivec2 size = window.framebuffer_size();
      if (size.x > 0 && size.y > 0) renderer.draw(camera, size.x, size.y, options);
      window.swap();
    }
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return 1;
  }
}

}  // namespace luz::app
