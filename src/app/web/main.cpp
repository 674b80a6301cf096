// The web page's shell (DESIGN.md "Two targets"): the canvas's WebGL 2 context, the scene the
// URL names loaded from the page's packed files, and the browser's frame loop, which draws it
// with the local models' renderer, the same code as the window's and `luz render`'s. Each frame
// the picture is read back and shown exactly as `luz render` encodes a PNG (the scene's exposure,
// the sRGB curve), through a texture blitted onto the canvas.
//
// The URL's parameters (docs/web.md): scene=NAME (a shipped scene), model=gouraud|phong,
// lang=es|en, size=WxH. The page's `window.luz.ready` settles after the first picture is shown.
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <emscripten.h>
#include <emscripten/html5.h>

#include "core/error.h"
#include "core/i18n.h"
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

// The value of the page URL's parameter `name` (empty when it is absent), written into `buffer`
// as far as it fits; returns its length in bytes.
EM_JS(int, url_parameter_text, (const char* name, char* buffer, int size), {
  const value = new URLSearchParams(window.location.search).get(UTF8ToString(name)) || "";
  stringToUTF8(value, buffer, size);
  return lengthBytesUTF8(value);
});

// The browser's first language ("es-ES", "en-US", ...), as above.
EM_JS(int, browser_language_text, (char* buffer, int size), {
  const value = navigator.language || "en";
  stringToUTF8(value, buffer, size);
  return lengthBytesUTF8(value);
});

// A JavaScript string through one of the functions above, at any length.
template <typename Read>
std::string text_from(Read read) {
  std::string text(256, '\0');
  int length = read(text.data(), int(text.size()));
  if (length >= int(text.size())) {
    text.resize(std::size_t(length) + 1);
    length = read(text.data(), int(text.size()));
  }
  text.resize(std::size_t(length));
  return text;
}

std::string url_parameter(const char* name) {
  return text_from([name](char* buffer, int size) { return url_parameter_text(name, buffer, size); });
}

// window.luz.ready: resolved once the first picture is on the canvas, rejected with the error
// the page shows when there will be none (the shell defines both callbacks).
EM_JS(void, report_ready, (), { if (window.luzReady) window.luzReady.resolve(); });
EM_JS(void, report_failure, (const char* text), {
  const canvas = document.getElementById("canvas");
  if (canvas) canvas.style.display = "none";  // the error in words, not an empty picture
  if (window.luzReady) window.luzReady.reject(new Error(UTF8ToString(text)));
});

void fail(const std::string& text) {
  show_status(text);
  report_failure(text.c_str());
}

// What the URL asks for; each value is checked here, so a bad one is a sentence on the page.
struct Request {
  std::filesystem::path scene;
  LocalOptions options;  // the shading model and slide 19's switches
  int width = 640, height = 480;
};

// A shipped scene by its name (cornell_box, whitted, ...): a name, never a path.
std::filesystem::path shipped_scene(const std::string& name) {
  const bool plain = !name.empty() && name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") == std::string::npos;
  const std::filesystem::path file = scene_dir() / (name + ".gltf");
  if (plain && std::filesystem::exists(file)) return file;
  std::string names;
  for (const auto& entry : std::filesystem::directory_iterator(scene_dir()))
    if (entry.path().extension() == ".gltf") names += (names.empty() ? "" : ", ") + entry.path().stem().string();
  throw Error(ErrorKind::bad_value, i18n::trf("No shipped scene is called \"{}\" (the shipped scenes: {}).", name, names));
}

Shading shading_named(const std::string& name) {
  if (name == "phong") return Shading::phong;
  if (name == "gouraud") return Shading::gouraud;
  if (name == "flat") return Shading::flat;
  throw Error(ErrorKind::bad_value, i18n::trf("No local model is called \"{}\" (flat, gouraud, phong).", name));
}

// effects=shadows,transparency,...: slide 19's switches, as `luz render`'s flags of those names.
void read_effects(const std::string& text, LocalOptions& options) {
  std::string_view rest = text;
  while (!rest.empty()) {
    const std::string_view name = rest.substr(0, rest.find(','));
    rest.remove_prefix(std::min(rest.size(), name.size() + 1));
    if (name == "shadows") options.shadows.on = true;
    else if (name == "transparency") options.transparency.on = true;
    else if (name == "reflection") options.reflection.on = true;
    else if (name == "fog") options.fog.mode = FogMode::linear;
    else
      throw Error(ErrorKind::bad_value, i18n::trf("No effect is called \"{}\" (shadows, transparency, "
                                                  "reflection, fog).", std::string(name)));
  }
}

// "WxH", each side 1 to 4096 pixels.
void read_size(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  int w = 0, h = 0;
  const char* end = text.data() + text.size();
  const bool read = x != std::string::npos &&
                    std::from_chars(text.data(), text.data() + x, w).ptr == text.data() + x &&
                    std::from_chars(text.data() + x + 1, end, h).ptr == end;
  if (!read || w < 1 || h < 1 || w > 4096 || h > 4096)
    throw Error(ErrorKind::bad_value, i18n::trf("size={} is not WIDTHxHEIGHT with each side 1 to 4096 pixels.", text));
  width = w;
  height = h;
}

Request read_request() {
  Request request;
  const std::string scene = url_parameter("scene"), model = url_parameter("model"), size = url_parameter("size"),
                    effects = url_parameter("effects");
  request.scene = scene.empty() ? default_scene() : shipped_scene(scene);
  if (!model.empty()) request.options.shading = shading_named(model);
  read_effects(effects, request.options);
  if (!size.empty()) read_size(size, request.width, request.height);
  return request;
}

// The language: lang=es|en, else the browser's first choice.
void choose_language() {
  const std::string asked = url_parameter("lang");
  if (!asked.empty()) {
    if (const auto language = i18n::parse_language(asked)) i18n::set_language(*language);
    else throw Error(ErrorKind::bad_value, i18n::trf("lang={} is not a language of Luz (es, en).", asked));
    return;
  }
  i18n::set_language(i18n::language_from_locale_name(text_from(browser_language_text)));
}

class Page {
public:
  explicit Page(const Request& request) : loaded_(io::load_gltf(request.scene)), renderer_(loaded_.scene) {
    options_ = request.options;
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
    if (!shown_once_) {
      shown_once_ = true;
      report_ready();
    }
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
  bool shown_once_ = false;
};

std::unique_ptr<Page> page;

void frame() {
  try {
    page->frame();
  } catch (const std::exception& error) {
    fail(error.what());
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
    web::fail(i18n::tr("This browser gives no WebGL 2 context."));
    return 1;
  }
  emscripten_webgl_make_context_current(context);
  // Float colour buffers: the local models draw radiance in RGBA32F, as on the desktop.
  if (!emscripten_webgl_enable_extension(context, "EXT_color_buffer_float")) {
    web::fail(i18n::tr("This browser's WebGL 2 cannot draw into float buffers (EXT_color_buffer_float)."));
    return 1;
  }
  // Transparency blends into them (lighting.glsl's two draws), which WebGL 2 allows with this one.
  emscripten_webgl_enable_extension(context, "EXT_float_blend");
  try {
    web::choose_language();
    const web::Request request = web::read_request();
    emscripten_set_canvas_element_size("#canvas", request.width, request.height);
    load_gl_functions(web::resolve);
    web::page = std::make_unique<web::Page>(request);
  } catch (const std::exception& error) {
    web::fail(error.what());
    return 1;
  }
  // The browser calls frame() before each repaint; main returns and the page stays live.
  emscripten_set_main_loop(web::frame, 0, false);
  return 0;
}
