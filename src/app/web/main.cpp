// The web page's shell (DESIGN.md "Two targets"): the canvas's WebGL 2 context, the Cornell box
// loaded from the page's packed files, and the browser's frame loop, which draws it with the
// local models' renderer, the same code as the window's and `luz render`'s. Each frame the
// picture is read back and shown exactly as `luz render` encodes a PNG (the scene's exposure,
// the sRGB curve), through a texture blitted onto the canvas.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <emscripten.h>
#include <emscripten/html5.h>

#include "core/error.h"
#include "core/image.h"
#include "core/resources.h"
#include "gl/functions.h"
#include "io/gltf_loader.h"
#include "local/local_renderer.h"

namespace luz::web {
namespace {

GlProc resolve(const char* name) { return reinterpret_cast<GlProc>(emscripten_webgl_get_proc_address(name)); }

// The page's text under the canvas: what went wrong, or how long a frame took.
EM_JS(void, set_status_text, (const char* text), {
  const status = document.getElementById('status');
  if (status) status.textContent = UTF8ToString(text);
});

void show_status(const std::string& text) { set_status_text(text.c_str()); }

class Page {
public:
  explicit Page(const std::filesystem::path& scene_file)
      : loaded_(io::load_gltf(scene_file)), renderer_(loaded_.scene) {
    glGenTextures(1, &shown_);
    glGenFramebuffers(1, &read_fbo_);
  }

  // One frame: the picture at the canvas's size, shown.
  void frame() {
    int width = 0, height = 0;
    emscripten_get_canvas_element_size("#canvas", &width, &height);
    if (width <= 0 || height <= 0) return;
    const auto start = std::chrono::steady_clock::now();
    const Image image = renderer_.render(loaded_.scene.cameras.front(), width, height, options_);
    show(image);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    show_status(std::string(to_string(options_.shading)) + ", " + std::to_string(width) + "x" +
                std::to_string(height) + ": " + std::to_string(int(ms + 0.5)) + " ms");
  }

private:
  // The picture as `luz render` writes it: radiance x 2^exposure (the scene's), the sRGB curve,
  // 8 bits.
  void show(const Image& image) {
    bytes_.resize(image.pixels.size() * 3);
    srgb_bytes(image.pixels, std::exp2(loaded_.scene.exposure), bytes_);
    glBindTexture(GL_TEXTURE_2D, shown_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image.width, image.height, 0, GL_RGB, GL_UNSIGNED_BYTE, bytes_.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, read_fbo_);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, shown_, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    // The image's row 0 is the top, GL's the bottom: blitted upside down.
    glBlitFramebuffer(0, 0, image.width, image.height, 0, image.height, image.width, 0, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  }

  io::LoadedScene loaded_;
  LocalRenderer renderer_;
  LocalOptions options_;
  std::vector<uint8_t> bytes_;
  GLuint shown_ = 0, read_fbo_ = 0;
};

std::unique_ptr<Page> page;

void frame() {
  try {
    page->frame();
  } catch (const std::exception& error) {
    show_status(error.what());
    emscripten_cancel_main_loop();
  }
}

}  // namespace
}  // namespace luz::web

int main() {
  using namespace luz;
  EmscriptenWebGLContextAttributes attributes;
  emscripten_webgl_init_context_attributes(&attributes);
  attributes.majorVersion = 2;
  attributes.minorVersion = 0;
  attributes.alpha = false;
  attributes.antialias = false;
  attributes.preserveDrawingBuffer = true;  // the canvas can be read back between frames
  const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = emscripten_webgl_create_context("#canvas", &attributes);
  if (context <= 0) {
    web::show_status("This browser gives no WebGL 2 context.");
    return 1;
  }
  emscripten_webgl_make_context_current(context);
  // Float colour buffers: the local models draw radiance in RGBA32F, as on the desktop.
  if (!emscripten_webgl_enable_extension(context, "EXT_color_buffer_float")) {
    web::show_status("This browser's WebGL 2 cannot draw into float buffers (EXT_color_buffer_float).");
    return 1;
  }
  try {
    load_gl_functions(web::resolve);
    web::page = std::make_unique<web::Page>(default_scene());
  } catch (const std::exception& error) {
    web::show_status(error.what());
    return 1;
  }
  // The browser calls frame() before each repaint; main returns and the page stays live.
  emscripten_set_main_loop(web::frame, 0, false);
  return 0;
}
