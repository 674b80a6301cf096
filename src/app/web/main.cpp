// The web page's program (DESIGN.md "Two targets"): the viewer, the same code as the window's,
// on the page's canvas. What differs is here and behind the viewer's seams (frame_loop.h,
// gl/window_context_web.cpp): the URL's parameters in place of the command line, the scene
// fetched when the URL names one, and window.luz, the page's door for scripts and tests.
//
// The URL's parameters (docs/web.md): scene=NAME|URL, model=NAME, effects=shadows,..., lang=es|en,
// size=WxH (the picture's size; without it the canvas follows the browser's window), panel=0
// (the picture alone), lesson=N (lessons/sintesis.json at step N). window.luz (the shell,
// luz.html): ready settles once the first picture of the URL's scene and model is shown;
// run(line) runs a line of the script language; picture() is the picture as `luz render` writes it.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <emscripten.h>
#include <emscripten/html5.h>
#include <emscripten/wget.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/classroom/lesson.h"
#include "app/common/i18n.h"
#include "app/common/model_registry.h"
#include "app/viewer/viewer.h"
#include "core/error.h"
#include "core/parallel_for.h"
#include "core/resources.h"
#include "io/gltf_uris.h"

namespace luz::web {
namespace {

using app::tr;
using app::trf;

// The page's text under the canvas: what went wrong, or nothing once the viewer shows.
EM_JS(void, set_status_text, (const char* text), {
  const status = document.getElementById('status');
  if (status) status.textContent = UTF8ToString(text);
});

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

// The page as it stays once Luz runs: the loading line emptied, the controls under the canvas
// shown (the room they take is the canvas's no longer).
EM_JS(void, show_controls, (), {
  document.getElementById('status').textContent = "";
  document.getElementById('controls').classList.add('shown');
});
// window.luz.ready: resolved once the first picture is on the canvas, rejected with the error
// the page shows when there will be none (the shell defines both callbacks).
EM_JS(void, report_ready, (), {
  if (window.luzReady) window.luzReady.resolve();
});
EM_JS(void, report_failure, (const char* text), {
  const canvas = document.getElementById("canvas");
  if (canvas) canvas.style.display = "none";  // the error in words, not an empty picture
  if (window.luzReady) window.luzReady.reject(new Error(UTF8ToString(text)));
});

// A request of window.luz (run, picture) settled: resolved with `text`, or rejected with it.
EM_JS(void, settle_request, (int id, int ok, const char* text), { window.luzSettle(id, ok, UTF8ToString(text)); });

// The words of the page's controls (luz.html), in the page's language.
EM_JS(void, set_control_words, (const char* open, const char* picture, const char* with_panel), {
  document.getElementById("open-label").textContent = UTF8ToString(open);
  document.getElementById("save-picture").textContent = UTF8ToString(picture);
  document.getElementById("save-page").textContent = UTF8ToString(with_panel);
});

// A screenshot the viewer saved in the page's files (P, Shift+P, the page's buttons), handed to
// the browser as a download under its name.
EM_JS(void, offer_download, (const char* path), {
  const file = UTF8ToString(path);
  const link = document.createElement("a");
  link.href = URL.createObjectURL(new Blob([FS.readFile(file)], { type: "image/png" }));
  link.download = file.slice(file.lastIndexOf("/") + 1);
  document.body.appendChild(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(link.href), 60000);
});

// The page's note under the canvas: shown once, with what it says in the page's language.
EM_JS(void, show_note, (const char* text), {
  const note = document.getElementById("note");
  if (!note) return;
  note.textContent = UTF8ToString(text);
  note.classList.add("shown");
});

// Built without threads (luz-1thread.js, which luz.html starts where the page cannot be
// cross-origin isolated), the page says so, and how to get every core.
void note_one_thread() {
#if !defined(__EMSCRIPTEN_PTHREADS__)
  show_note(tr("Luz runs on one thread here: this page is not cross-origin isolated, so the ray tracers, "
               "the path tracer and radiosity work on one core, between the page's frames. For every core, "
               "serve the page with the headers Cross-Origin-Opener-Policy: same-origin and "
               "Cross-Origin-Embedder-Policy: require-corp, or from https:// so that its service worker "
               "adds them (docs/web.md, \"Threads\")."));
#endif
}

void fail(const std::string& text) {
  set_status_text(text.c_str());
  report_failure(text.c_str());
}

// What the URL asks for; each value is checked here, so a bad one is a sentence on the page.
struct Request {
  std::string scene;  // a shipped scene's file, or a URL to fetch
  bool fetched = false;
  std::string model = "phong";
  std::vector<std::string> settings;  // `set` lines: slide 19's switches the URL turns on
  int width = 640, height = 480;  // the picture's
  bool follows_window = true;     // no size=: the canvas takes the browser window's room, resized with it
  bool panel = true;
  int lesson_step = 0;  // lesson=N: lessons/sintesis.json opened at step N (from 1); 0: none
  std::optional<app::Lesson> lesson;
};

std::filesystem::path shipped_scene(const std::string& name) {
  const bool plain = !name.empty() && name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") == std::string::npos;
  const std::filesystem::path file = scene_dir() / (name + ".gltf");
  if (plain && std::filesystem::exists(file)) return file;
  std::string names;
  for (const auto& entry : std::filesystem::directory_iterator(scene_dir()))
    if (entry.path().extension() == ".gltf") names += (names.empty() ? "" : ", ") + entry.path().stem().string();
  throw Error(ErrorKind::bad_value, trf("No shipped scene is called \"{}\" (the shipped scenes: {}).", name, names));
}

// A URL rather than a shipped scene's name: it names a glTF file.
bool names_a_file(const std::string& scene) {
  return scene.find('/') != std::string::npos || scene.ends_with(".gltf") || scene.ends_with(".glb");
}

void check_model(const std::string& name) {
  if (!app::find_model(name))
    throw Error(ErrorKind::bad_value, trf("No model is called \"{}\" ({}).", name, app::model_names()));
}

// effects=shadows,transparency,...: slide 19's switches, as `luz render`'s flags of those names,
// each the viewer's `set` line.
std::vector<std::string> effect_settings(const std::string& text) {
  std::vector<std::string> settings;
  std::string_view rest = text;
  while (!rest.empty()) {
    const std::string_view name = rest.substr(0, rest.find(','));
    rest.remove_prefix(std::min(rest.size(), name.size() + 1));
    if (name == "shadows") settings.push_back("set shadows on");
    else if (name == "transparency") settings.push_back("set transparency on");
    else if (name == "reflection") settings.push_back("set reflection-map on");
    else if (name == "fog") settings.push_back("set fog linear");
    else
      throw Error(ErrorKind::bad_value, trf("No effect is called \"{}\" (shadows, transparency, "
                                            "reflection, fog).", std::string(name)));
  }
  return settings;
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
    throw Error(ErrorKind::bad_value, trf("size={} is not WIDTHxHEIGHT with each side 1 to 4096 pixels.", text));
  width = w;
  height = h;
}

// lesson=N: a step of the shipped lesson, from 1 to its last.
int read_lesson_step(const std::string& text, int steps) {
  int step = 0;
  const char* end = text.data() + text.size();
  const auto [stop, problem] = std::from_chars(text.data(), end, step);
  if (problem != std::errc() || stop != end || step < 1 || step > steps)
    throw Error(ErrorKind::bad_value, trf("lesson={} is not a step of the lesson (1 to {}).", text, steps));
  return step;
}

Request read_request() {
  Request request;
  const std::string scene = url_parameter("scene"), model = url_parameter("model"), size = url_parameter("size"),
                    panel = url_parameter("panel"), effects = url_parameter("effects"), lesson = url_parameter("lesson");
  if (scene.empty()) request.scene = default_scene().string();
  else if (names_a_file(scene)) request.scene = scene, request.fetched = true;
  else request.scene = shipped_scene(scene).string();
  if (!model.empty()) check_model(model);
  if (!model.empty()) request.model = model;
  request.settings = effect_settings(effects);
  if (!size.empty()) read_size(size, request.width, request.height);
  request.follows_window = size.empty();
  if (panel == "0") request.panel = false;
  else if (!panel.empty() && panel != "1")
    throw Error(ErrorKind::bad_value, trf("panel={} is not 0 (the picture alone) or 1.", panel));
  if (!lesson.empty()) {
    // The lesson's steps name their scenes and models: the URL's scene and model are not asked.
    request.lesson = app::parse_lesson(app::default_lesson());
    request.lesson_step = read_lesson_step(lesson, int(request.lesson->steps.size()));
    request.scene = request.lesson->steps.front().scene;
    request.fetched = false;
  }
  return request;
}

// The language: lang=es|en, else the browser's first choice.
void choose_language() {
  const std::string asked = url_parameter("lang");
  if (!asked.empty()) {
    if (const auto language = i18n::parse_language(asked)) i18n::set_language(*language);
    else throw Error(ErrorKind::bad_value, trf("lang={} is not a language of Luz (es, en).", asked));
    return;
  }
  i18n::set_language(i18n::language_from_locale_name(text_from(browser_language_text)));
}

// ---- the viewer in the page ------------------------------------------------------------------
Request request;
app::LineQueue* viewer = nullptr;  // the running viewer's door, from its first frame on
bool ready = false;
const char* const windows_file = "/tmp/luz-windows.json";
const char* const picture_file = "/tmp/luz-picture.png";

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned n = unsigned(bytes[i]) << 16 | (i + 1 < bytes.size() ? unsigned(bytes[i + 1]) << 8 : 0u) |
                       (i + 2 < bytes.size() ? unsigned(bytes[i + 2]) : 0u);
    text += digits[n >> 18 & 63];
    text += digits[n >> 12 & 63];
    text += i + 1 < bytes.size() ? digits[n >> 6 & 63] : '=';
    text += i + 2 < bytes.size() ? digits[n & 63] : '=';
  }
  return text;
}

std::vector<unsigned char> file_bytes(const char* path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The picture's size is the URL's: the window grows or shrinks by what the panel and the status
// line take, measured on the frame drawn (their sizes follow the font). A panel narrowed by a
// small window takes a second try.
void fit_picture(int tries_left) {
  viewer->run_later(std::string("dump-windows ") + windows_file, [tries_left](const std::string& error) {
    if (!error.empty()) return fail(error);
    const nlohmann::json windows = nlohmann::json::parse(std::ifstream(windows_file));
    const auto& view = windows.at("view");
    const int shown_w = int(std::lround(view[2].get<double>() - view[0].get<double>()));
    const int shown_h = int(std::lround(view[3].get<double>() - view[1].get<double>()));
    if ((shown_w == request.width && shown_h == request.height) || tries_left == 0) {
      show_controls();
      ready = true;
      report_ready();
      return;
    }
    int window_w = 0, window_h = 0;
    emscripten_get_canvas_element_size("#canvas", &window_w, &window_h);
    const std::string resize = fmt::format("resize {} {}", window_w + request.width - shown_w,
                                           window_h + request.height - shown_h);
    viewer->run_later(resize, [tries_left](const std::string& resize_error) {
      if (!resize_error.empty()) return fail(resize_error);
      fit_picture(tries_left - 1);
    });
  });
}

// The room the browser's window gives the canvas: its whole width, and its height less what the
// rest of the page takes (the canvas's margins, the status line, the controls and messages under
// it), so that the page does not scroll.
EM_JS(int, room_width, (), { return Math.max(1, window.innerWidth); });
EM_JS(int, room_height, (), {
  const canvas = document.getElementById('canvas');
  let bottom = 0;
  for (const element of document.body.children) {
    const style = getComputedStyle(element);
    if (style.display === 'none') continue;
    bottom = Math.max(bottom, element.getBoundingClientRect().bottom + window.scrollY + parseFloat(style.marginBottom));
  }
  const others = bottom - canvas.getBoundingClientRect().height;
  return Math.max(1, Math.floor(window.innerHeight - others));
});

// Without size=, the canvas follows the browser's window: each change of its room resizes the
// viewer's window, one `resize` line at a time (dragging a window's edge sends many events; the
// last room is the one asked for once the line before is done).
int asked_width = 0, asked_height = 0;
bool resizing = false;

void follow_window() {
  if (!viewer || !ready || resizing) return;
  const int width = room_width(), height = room_height();
  int canvas_w = 0, canvas_h = 0;
  emscripten_get_canvas_element_size("#canvas", &canvas_w, &canvas_h);
  if ((width == canvas_w && height == canvas_h) || (width == asked_width && height == asked_height)) return;
  asked_width = width;
  asked_height = height;
  resizing = true;
  viewer->run_later(fmt::format("resize {} {}", width, height), [](const std::string&) {
    resizing = false;
    follow_window();
  });
}

EM_BOOL window_resized(int, const EmscriptenUiEvent*, void*) {
  follow_window();
  return EM_FALSE;
}

// Without size=, before ready: the canvas brought to the room the page leaves it with its
// controls shown, one `resize` line at a time until it has it (a line under the canvas may wrap
// anew at another width: a few tries), so that the first picture, and a trace a lesson's step
// starts, are of the size the canvas keeps; then ready, and the canvas follows the window.
void fill_room(int tries_left) {
  const int width = room_width(), height = room_height();
  int canvas_w = 0, canvas_h = 0;
  emscripten_get_canvas_element_size("#canvas", &canvas_w, &canvas_h);
  if ((width == canvas_w && height == canvas_h) || tries_left == 0) {
    ready = true;
    report_ready();
    emscripten_set_resize_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_FALSE, window_resized);
    follow_window();  // the window may have changed meanwhile
    return;
  }
  viewer->run_later(fmt::format("resize {} {}", width, height), [tries_left](const std::string& error) {
    if (!error.empty()) return fail(error);
    fill_room(tries_left - 1);
  });
}

// Once the viewer runs: the URL's switches on and the panel hidden when it says so, then, on the
// frame drawn after them, the picture brought to its size (or the canvas to its room), then
// ready.
void viewer_started(app::LineQueue& queue) {
  viewer = &queue;
  std::vector<std::string> lines = request.settings;
  if (!request.panel) lines.push_back("set panel off");
  if (request.lesson_step > 1) lines.push_back(fmt::format("lesson goto {}", request.lesson_step));
  lines.push_back("wait 1");
  for (size_t i = 0; i < lines.size(); ++i)
    viewer->run_later(lines[i], [last = i + 1 == lines.size()](const std::string& error) {
      if (!error.empty()) return fail(error);
      if (!last) return;
      if (!request.follows_window) return fit_picture(3);
      show_controls();
      fill_room(3);
    });
}

void start() {
  app::ViewerSettings settings;
  settings.scene = request.scene;
  if (request.lesson) settings.lesson = request.lesson;  // it opens on its first step's model
  else settings.models = {request.model};
  // A first guess at the window around the picture: the panel's default width and a status line.
  settings.width = request.width + (request.panel ? 440 : 0);
  settings.height = request.height + 30;
  if (request.follows_window) settings.width = room_width(), settings.height = room_height();
  settings.started = viewer_started;
  settings.screenshot_saved = [](const std::filesystem::path& file) { offer_download(file.c_str()); };
  // Five frames a second while a trace's threads or the radiosity loop work: each frame the
  // browser draws on the CPU (SwiftShader) is time the tracer's threads lose, and the solver
  // shoots on this thread in the passes between (the light still seen spreading); the end is
  // drawn at the next frame, an event or a `luz.run` line at once.
  settings.paced_frames = std::chrono::milliseconds(200);
  try {
    app::start_viewer(settings);
  } catch (const std::exception& error) {
    fail(error.what());
  }
}

// A fetched scene's folder in the page's files, and the URL it came from up to its name.
const std::filesystem::path fetched_dir = "/tmp/scenes";
std::string fetched_base;
std::vector<std::string> parts_to_fetch;  // the files a .gltf names beside it, still to fetch
std::string part_fetching;

void not_fetched(const char*) { fail(trf("The scene at {} could not be fetched.", url_parameter("scene"))); }
void part_not_fetched(const char*) { fail(trf("The scene at {} could not be fetched.", fetched_base + part_fetching)); }

void fetch_parts() {
  if (parts_to_fetch.empty()) return start();
  part_fetching = parts_to_fetch.back();
  parts_to_fetch.pop_back();
  const std::filesystem::path file = fetched_dir / part_fetching;
  std::filesystem::create_directories(file.parent_path());
  emscripten_async_wget((fetched_base + part_fetching).c_str(), file.c_str(), [](const char*) { fetch_parts(); },
                        part_not_fetched);
}

// The buffers and images a .gltf names by a relative path beside it (not a data: URI, not in
// another folder), as its URIs write them; a file that does not parse names none (the loader
// says what is wrong with it).
std::vector<std::string> files_named_beside(const std::filesystem::path& file) {
  std::vector<std::string> uris;
  const nlohmann::json gltf = nlohmann::json::parse(std::ifstream(file), nullptr, false);
  for (const char* list : {"buffers", "images"})
    if (gltf.is_object() && gltf.contains(list) && gltf[list].is_array())
      for (const auto& entry : gltf[list])
        if (entry.is_object() && entry.contains("uri") && entry["uri"].is_string()) {
          const std::string uri = entry["uri"];
          const bool beside = !uri.starts_with("data:") && !uri.starts_with("/") &&
                              uri.find("://") == std::string::npos && uri.find("..") == std::string::npos;
          if (beside) uris.push_back(uri);
        }
  return uris;
}

// A fetched .gltf's buffers and images are fetched beside it.
void fetched(const char* file) {
  request.scene = file;
  if (std::filesystem::path(file).extension() == ".gltf") parts_to_fetch = files_named_beside(file);
  fetch_parts();
}

// ---- the student's own files -------------------------------------------------------------------
// Each choice of files (the file input, a drop on the page) is written by the shell into a folder
// of its own (/files/N), under the names the browser gives; the one scene among them is loaded
// with the viewer's `load`, and what the loader said is shown on the page. Only the shown scene's
// folder is kept: a broken file's goes, and so does the scene's it replaces.
const char* const state_file = "/tmp/luz-state.json";
std::filesystem::path shown_folder;  // the folder of the student's scene shown, if one is

// The page's text about the files last given; `failed` shows it as an error.
EM_JS(void, show_file_messages, (const char* text, int failed), {
  const messages = document.getElementById("messages");
  if (!messages) return;
  messages.textContent = UTF8ToString(text);
  messages.className = failed ? "error" : "";
});

bool is_scene_file(const std::filesystem::path& file) {
  return file.extension() == ".gltf" || file.extension() == ".glb";
}

// The loader's lines name the file by its path in the page's files: shown by its name alone.
std::string without_folder(std::string text, const std::filesystem::path& folder) {
  const std::string prefix = folder.string() + "/";
  for (auto at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at)) text.erase(at, prefix.size());
  return text;
}

// The files a .gltf names beside it that were not given with it, by their names.
std::vector<std::string> files_not_given(const std::filesystem::path& gltf) {
  std::vector<std::string> missing;
  if (gltf.extension() != ".gltf") return missing;
  for (const std::string& uri : files_named_beside(gltf))
    if (!std::filesystem::exists(gltf.parent_path() / io::gltf::uri_path(uri))) missing.push_back(io::gltf::uri_path(uri));
  return missing;
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : ", ") + word;
  return text;
}

// A .gltf may name its files in folders beside it ("textures/wood.png", as Blender's exporter can
// write them), and the file picker gives files without their folders: each file given by the
// name a URI ends with is copied to where the .gltf looks for it.
void place_named_files(const std::filesystem::path& gltf) {
  if (gltf.extension() != ".gltf") return;
  for (const std::string& uri : files_named_beside(gltf)) {
    const std::string path = io::gltf::uri_path(uri);
    if (path.find("..") != std::string::npos) continue;  // outside the folder: the loader refuses it
    const std::filesystem::path wanted = gltf.parent_path() / path;
    const std::filesystem::path given = gltf.parent_path() / wanted.filename();
    std::error_code ignored;  // a file that cannot be placed is told missing by the loader
    if (wanted != given && !std::filesystem::exists(wanted) && std::filesystem::is_regular_file(given)) {
      std::filesystem::create_directories(wanted.parent_path(), ignored);
      std::filesystem::copy_file(given, wanted, ignored);
    }
  }
}

// The one scene among the files given, or why there is none to load.
std::filesystem::path scene_among(const std::filesystem::path& folder, std::string& problem) {
  std::vector<std::string> names, scenes;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
    if (is_scene_file(entry.path())) scenes.push_back(names.back());
  }
  std::sort(names.begin(), names.end());
  std::sort(scenes.begin(), scenes.end());
  if (scenes.empty()) problem = trf("None of the files given is a glTF scene (.glb, or .gltf with its files): {}.", joined(names));
  else if (scenes.size() > 1) problem = trf("Give one scene at a time: {} were given together.", joined(scenes));
  else if (scenes.front().find('"') != std::string::npos) problem = trf("{}: a scene's name cannot hold a double quote.", scenes.front());
  return problem.empty() ? folder / scenes.front() : std::filesystem::path();
}

// What the viewer said after loading `scene`: the page's text, and whether the scene is shown.
void report_load(const std::filesystem::path& scene, int id) {
  const std::filesystem::path folder = scene.parent_path();
  const nlohmann::json state = nlohmann::json::parse(std::ifstream(state_file), nullptr, false);
  std::remove(state_file);
  const std::string error = state.is_object() ? state.value("load_error", std::string()) : tr("the viewer's state could not be read");
  std::string text;
  for (const std::string& name : files_not_given(scene))
    text += trf("{} names {}, which was not given with it: choose the files together.", scene.filename().string(), name) + "\n";
  if (!error.empty()) {
    text = without_folder(error, folder) + "\n" + text + tr("the scene did not load; showing the previous one");
    std::filesystem::remove_all(folder);
  } else {
    text = trf("loaded {}", scene.filename().string()) + "\n" + text;
    if (state.contains("warnings"))
      for (const auto& warning : state["warnings"]) text += trf("warning: {}", without_folder(warning, folder)) + "\n";
    if (!shown_folder.empty() && shown_folder != folder) std::filesystem::remove_all(shown_folder);
    shown_folder = folder;
  }
  while (!text.empty() && text.back() == '\n') text.pop_back();
  show_file_messages(text.c_str(), !error.empty());
  settle_request(id, error.empty(), text.c_str());
}

}  // namespace
}  // namespace luz::web

// window.luz.run(line) and picture(): the shell calls these with the id it settles.
extern "C" EMSCRIPTEN_KEEPALIVE void luz_run(const char* line, int id) {
  using namespace luz::web;
  if (!viewer || !ready) return settle_request(id, 0, "Luz is not ready: await luz.ready first.");
  viewer->run_later(line, [id](const std::string& error) { settle_request(id, error.empty(), error.c_str()); });
}

// luz.open(files): the shell has written the files into `folder`; the scene among them is loaded.
extern "C" EMSCRIPTEN_KEEPALIVE void luz_open_files(const char* folder, int id) {
  using namespace luz::web;
  if (!viewer || !ready) return settle_request(id, 0, "Luz is not ready: await luz.ready first.");
  std::string problem;
  const std::filesystem::path scene = scene_among(folder, problem);
  if (!problem.empty()) {
    std::filesystem::remove_all(folder);
    show_file_messages(problem.c_str(), 1);
    return settle_request(id, 0, problem.c_str());
  }
  place_named_files(scene);
  viewer->run_later(fmt::format("load \"{}\"", scene.string()), [](const std::string&) {});
  viewer->run_later(std::string("dump-state ") + state_file, [scene, id](const std::string& error) {
    if (!error.empty()) return settle_request(id, 0, error.c_str());
    report_load(scene, id);
  });
}

extern "C" EMSCRIPTEN_KEEPALIVE void luz_picture(int id) {
  using namespace luz::web;
  if (!viewer || !ready) return settle_request(id, 0, "Luz is not ready: await luz.ready first.");
  viewer->run_later(fmt::format("screenshot {} --quiet", picture_file), [id](const std::string& error) {
    if (!error.empty()) return settle_request(id, 0, error.c_str());
    const std::string url = "data:image/png;base64," + base64(file_bytes(picture_file));
    std::remove(picture_file);
    settle_request(id, 1, url.c_str());
  });
}

int main() {
  using namespace luz;
  // The parallel loops' threads, started while the page loads: started later, from the worker
  // that runs a trace, they would wait for the main thread's next frame.
  parallel::start_threads();
  try {
    web::choose_language();
    web::set_control_words(app::tr("Open a scene (.glb, or .gltf with its files):"), app::tr("Save the picture (P)"),
                           app::tr("Save with the panel (Shift+P)"));
    web::note_one_thread();
    web::request = web::read_request();
  } catch (const std::exception& error) {
    web::fail(error.what());
    return 1;
  }
  if (!web::request.fetched) {
    web::start();
    return 0;
  }
  // The scene's file under its own name, so that the viewer's title and messages name it.
  std::filesystem::create_directories(web::fetched_dir);
  const std::string& url = web::request.scene;
  const std::string name = url.substr(url.find_last_of('/') + 1);
  web::fetched_base = url.substr(0, url.size() - name.size());
  emscripten_async_wget(url.c_str(), (web::fetched_dir / name).c_str(), web::fetched, web::not_fetched);
  return 0;
}
