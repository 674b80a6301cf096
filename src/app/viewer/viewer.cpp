// The viewer's loop: a window with the panel on the left, the picture on the right and the
// status line under it. Every change comes in as a script line (a key runs its own, shortcuts.h),
// a panel edit of the ViewerState or a mouse gesture, and is drawn on the next frame; what the
// picture shows is the shown model's view (model_view.h, model_registry.h).
//
// Sections: [setup] [loading] [views] [input] [keys] [script] [the frame] [the loop]
//           [run_viewer]
#include "app/viewer/viewer_window.h"

#include "gl/functions.h"  // before GLFW: GLFW_INCLUDE_NONE keeps GLFW from including GL

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>  // the windows' rectangles, for the tests' dump-windows

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "app/script/script_watch.h"
#include "app/viewer/difference_window.h"
#include "app/common/i18n.h"
#include "app/viewer/overlays.h"
#include "app/viewer/panel.h"
#include "app/viewer/panes.h"
#include "app/cli/render_grid.h"
#include "app/viewer/ui_glyphs.h"
#include "app/viewer/screenshot.h"
#include "app/viewer/viewer_settings.h"
#include "core/error.h"
#include "core/exposure.h"

namespace luz::app {
namespace {

constexpr int default_width = 1280;
constexpr int default_height = 760;
constexpr float panel_width = 440.0f;   // window units at a UI scale of 1
constexpr float lesson_panel_share = 0.4f;  // of the window's width, the most a lesson's panel opens with
constexpr float dock_share = 0.3f;      // of the picture's room, a lesson's dock at the least
constexpr float dock_ems = 20.0f;       // and at least this many font heights: the caption's lines
constexpr float below_caption_share = 0.6f;  // of a dock below the picture, the caption's; its windows the rest
constexpr float font_size = 16.0f;      // pixels at a content scale of 1
constexpr float drag_threshold = 3.0f;  // window units a press may move and still be a click
constexpr glm::vec4 background{0.06f, 0.06f, 0.07f, 1.0f};  // the window where nothing is drawn
const char* const font_file = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// Whether a and b are the same text once their digits are left out.
bool same_but_digits(std::string_view a, std::string_view b) {
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  size_t i = 0, j = 0;
  for (;; ++i, ++j) {
    while (i < a.size() && digit(a[i])) ++i;
    while (j < b.size() && digit(b[j])) ++j;
    if (i == a.size() || j == b.size()) return i == a.size() && j == b.size();
    if (a[i] != b[j]) return false;
  }
}

// A viewport's pixels in the window's framebuffer.
FramebufferRect framebuffer_rect(const Viewport& v) { return {v.gl_origin.x, v.gl_origin.y, v.pixels.x, v.pixels.y}; }

Viewer& viewer_of(GLFWwindow* window) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// The caption's part of the dock and its windows' column: the same column beside the picture;
// below it, the caption on the left and the windows on the right, their column `wanted` wide
// when a table asks for it (measure_dock), up to half the row.
std::pair<Viewport, Viewport> split_dock(const Viewport& dock, float wanted) {
  if (dock.origin.y == 0.0f) return {dock, dock};
  Viewport caption = dock, column = dock;
  column.size.x = std::round(std::max((1.0f - below_caption_share) * dock.size.x, std::min(wanted, 0.5f * dock.size.x)));
  caption.size.x = dock.size.x - column.size.x;
  column.origin.x += caption.size.x;
  return {caption, column};
}

}  // namespace

// ---- [setup] -----------------------------------------------------------------------------------
Viewer::Viewer(io::LoadedScene loaded, const std::filesystem::path& path, const ViewerSettings& settings)
    : window_(settings.width > 0 ? settings.width : default_width,
              settings.height > 0 ? settings.height : default_height,
              "Luz - " + path.filename().string()),
      screenshot_saved_(settings.screenshot_saved),
      paced_frames_(settings.paced_frames) {
  glGenVertexArrays(1, &empty_vertex_array_);
  if (settings.script) {
    script_.emplace(*settings.script);
    script_watch::install();
  }
  if (settings.lesson) classroom_ = Classroom(*settings.lesson);
  model_ = find_model(state_.model);
  panes_ = {model_};

  GLFWwindow* w = window_.handle();
  glfwSetWindowUserPointer(w, this);
  // Ours first: ImGui's GLFW backend (1.86) keeps these and calls them after its own. Every
  // event asks for a few frames; without events the loop sleeps (see needs_frames).
  glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int mods) {
    viewer_of(win).frames_to_draw_ = 3;
    if (action != GLFW_RELEASE) viewer_of(win).on_key(key, mods);
  });
  glfwSetCharCallback(w, [](GLFWwindow* win, unsigned codepoint) {
    viewer_of(win).frames_to_draw_ = 3;
    viewer_of(win).on_char(codepoint);
  });
  glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int) {
    viewer_of(win).frames_to_draw_ = 3;
    viewer_of(win).on_mouse_button(button, action);
  });
  glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) {
    viewer_of(win).frames_to_draw_ = 3;
    viewer_of(win).on_cursor(glm::vec2(float(x), float(y)));
  });
  glfwSetScrollCallback(w, [](GLFWwindow* win, double, double dy) {
    viewer_of(win).frames_to_draw_ = 3;
    viewer_of(win).on_scroll(float(dy));
  });
  glfwSetDropCallback(w, [](GLFWwindow* win, int count, const char** paths) {
    viewer_of(win).frames_to_draw_ = 3;
    if (count > 0) viewer_of(win).load(paths[count - 1]);
  });
  glfwSetWindowFocusCallback(w, [](GLFWwindow* win, int) { viewer_of(win).frames_to_draw_ = 3; });
  glfwSetCursorEnterCallback(w, [](GLFWwindow* win, int) { viewer_of(win).frames_to_draw_ = 3; });
  glfwSetWindowRefreshCallback(w, [](GLFWwindow* win) {  // uncovered: its pixels are gone from the screen
    viewer_of(win).frames_to_draw_ = 3;
    viewer_of(win).show_whole_window_ = true;
  });
  glfwSetFramebufferSizeCallback(w, [](GLFWwindow* win, int, int) { viewer_of(win).frames_to_draw_ = 3; });

  // Dear ImGui, scaled for the screen: fonts are rasterised at the pixel size they will have.
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the same layout every run, for the class and for the tests
  const float content_x = window_.content_scale().x;
  int window_w = 1, window_h = 1;
  glfwGetWindowSize(w, &window_w, &window_h);
  pixels_per_unit_ = float(std::max(window_.framebuffer_size().x, 1)) / float(std::max(window_w, 1));
  content_scale_ = std::max(content_x, 1.0f);
  user_scale_ = std::clamp(settings.ui_scale, kMinUiScale, kMaxUiScale);
  ImGui_ImplGlfw_InitForOpenGL(w, true);
  ImGui_ImplOpenGL3_Init(gl::WindowContext::glsl_version());
  rebuild_fonts();
  // A lesson on a projector, its interface enlarged: a panel wider than 40 % of the window
  // would leave the picture and the caption a strip. It starts hidden, and the caption says
  // which key shows it.
  if (classroom_.has_lesson() && panel_width * ui_scale_ > lesson_panel_share * float(window_w)) {
    state_.show_panel = false;
    panel_hint_ = true;
  }

  // ImGui 1.86 samples the keys once a frame and, within a frame, takes the typed characters
  // before the keys and one editing key only: while a frame took 100-600 ms, a key pressed and
  // released within it was never seen down, and "57", Backspace, Enter, "+" typed into a panel
  // field became "57+" with Backspace or Enter lost. So keys and characters wait in one queue,
  // in the order they came, and each frame takes them up to and including one key press.
  glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int scancode, int action, int mods) {
    viewer_of(win).input_.push_back({true, key, scancode, action, mods, 0});
  });
  glfwSetCharCallback(w, [](GLFWwindow* win, unsigned codepoint) {
    viewer_of(win).input_.push_back({false, 0, 0, 0, 0, codepoint});
  });

  adopt(std::move(loaded), path, false);
  if (!settings.models.empty()) set_panes(settings.models);  // `--model a,b,...`, already checked
}

Viewer::~Viewer() {
  views_.clear();  // a running trace reads the scene and radiosity's mesh: joined first
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  if (empty_vertex_array_) glDeleteVertexArrays(1, &empty_vertex_array_);
}

// The interface's size: the screen's content scale (HiDPI) times the class's choice
// (--ui-scale, the Scene section, Ctrl+= / Ctrl+-). Fonts are rasterised again at the size they
// will have, and the style's sizes scaled from ImGui's defaults.
void Viewer::rebuild_fonts() {
  ImGuiIO& io = ImGui::GetIO();
  ui_scale_ = std::max(content_scale_ / pixels_per_unit_, 1.0f) * user_scale_;
  io.Fonts->Clear();
  // The formula needs Greek letters, sub- and superscripts: DejaVu Sans has them (Debian's
  // fonts-dejavu-core); without it ImGui's own font shows '?' for those.
  static_assert(sizeof(ImWchar) == sizeof(kUiGlyphRanges[0]));
  const ImWchar* ranges = kUiGlyphRanges;
  const float pixels = content_scale_ * user_scale_;
  if (std::filesystem::exists(font_file)) {
    io.Fonts->AddFontFromFileTTF(font_file, font_size * pixels, nullptr, ranges);
  } else {
    ImFontConfig config;
    config.SizePixels = 13.0f * pixels;
    io.Fonts->AddFontDefault(&config);
  }
  io.FontGlobalScale = 1.0f / pixels_per_unit_;
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.ScaleAllSizes(ui_scale_);
  ImGui::GetStyle() = style;
  fonts_stale_ = false;
}

const char* Viewer::panel_hint() const { return panel_hint_ && !state_.show_panel ? tr("Tab: panel") : nullptr; }

void Viewer::set_ui_scale(float scale) {
  user_scale_ = std::clamp(scale, kMinUiScale, kMaxUiScale);
  fonts_stale_ = true;  // between frames: ImGui's font atlas is locked inside one
  dock_wanted_ = 0.0f;  // measured again in the new font
  state_.note = trf("interface size x{:.2f}", user_scale_);
}

Layout Viewer::layout() const {
  Layout l;
  int w = 0, h = 0;
  glfwGetWindowSize(window_.handle(), &w, &h);
  l.window = glm::vec2(float(std::max(w, 1)), float(std::max(h, 1)));
  l.framebuffer = window_.framebuffer_size();
  const glm::vec2 scale = glm::vec2(l.framebuffer) / l.window;
  // The panel and the status line end on whole pixels: no pixel is half panel, half picture.
  const auto whole_pixels = [](float units, float pixels_per_unit) {
    return pixels_per_unit > 0.0f ? std::round(units * pixels_per_unit) / pixels_per_unit : units;  // 0: minimised
  };
  l.panel = state_.show_panel ? whole_pixels(std::min(panel_width * ui_scale_, 0.6f * l.window.x), scale.x) : 0.0f;
  l.status = whole_pixels(ImGui::GetFontSize() + 2.0f * ImGui::GetStyle().WindowPadding.y, scale.y);
  Viewport& v = l.view;
  v.origin = glm::vec2(l.panel, 0.0f);
  v.size = glm::vec2(l.window.x - l.panel, std::max(l.window.y - l.status, 0.0f));
  v.scale = scale;
  const int left = int(std::lround(l.panel * scale.x));
  v.pixels = glm::ivec2(std::max(l.framebuffer.x - left, 0), std::max(int(std::lround(v.size.y * scale.y)), 0));
  v.gl_origin = glm::ivec2(left, l.framebuffer.y - v.pixels.y);
  if (classroom_.has_lesson() && v.size.x > 0.0f && v.size.y > 0.0f) {
    // A third of the picture's room, or more when the caption's font or a docked window asks for
    // it (a table keeps its columns as wide as their text), but never more than half of it.
    const float least = std::max(dock_share * v.size.x, dock_ems * ImGui::GetFontSize());
    const float narrowest = whole_pixels(std::min(least, 0.5f * v.size.x), scale.x);
    // Below the picture, a row as high as the caption's text asks (at most half the room).
    const Layout below = with_dock_below(l, whole_pixels(std::min(caption_wanted_, 0.5f * v.size.y), scale.y));
    if (dock_goes_below(with_dock_beside(l, narrowest), below)) return below;
    return with_dock_beside(l, whole_pixels(std::min(std::max(least, dock_wanted_), 0.5f * v.size.x), scale.x));
  }
  l.panes = pane_viewports(v, panes_.size());
  return l;
}

// The lesson's dock as a column right of the picture, `width` wide.
Layout Viewer::with_dock_beside(Layout l, float width) const {
  Viewport& v = l.view;
  Viewport& d = l.dock;
  d.scale = v.scale;
  d.pixels = glm::ivec2(int(std::lround(width * v.scale.x)), v.pixels.y);
  v.pixels.x = std::max(v.pixels.x - d.pixels.x, 0);
  v.size.x = std::max(v.size.x - width, 0.0f);
  d.origin = glm::vec2(v.origin.x + v.size.x, 0.0f);
  d.size = glm::vec2(width, v.size.y);
  d.gl_origin = glm::ivec2(v.gl_origin.x + v.pixels.x, v.gl_origin.y);
  l.panes = pane_viewports(v, panes_.size());
  return l;
}

// The lesson's dock as a row under the picture, above the status line, `height` high.
Layout Viewer::with_dock_below(Layout l, float height) const {
  Viewport& v = l.view;
  Viewport& d = l.dock;
  d.scale = v.scale;
  d.pixels = glm::ivec2(v.pixels.x, std::min(int(std::lround(height * v.scale.y)), v.pixels.y));
  v.pixels.y -= d.pixels.y;
  v.size.y = float(v.pixels.y) / v.scale.y;
  v.gl_origin.y += d.pixels.y;
  d.origin = glm::vec2(v.origin.x, v.origin.y + v.size.y);
  d.size = glm::vec2(v.size.x, float(d.pixels.y) / v.scale.y);
  d.gl_origin = glm::ivec2(v.gl_origin.x, v.gl_origin.y - d.pixels.y);
  l.panes = pane_viewports(v, panes_.size());
  return l;
}

// Below the picture when the camera's whole frame comes out larger there: a view keeps the
// camera's vertical field of view, so a wide scene (the plate of spheres) in a tall, narrow view
// loses its sides. The frame's height in a pane is what the comparison reads; the dock beside is
// taken at its least width, so that a docked window's width cannot move the dock. A caption
// folded to one line goes below whatever the scene when no window is docked; with one (the item
// buffer), the dock stays beside, where the room the folded caption frees is the window's (a row
// below would give it one line). Slide 36's window keeps the dock beside.
bool Viewer::dock_goes_below(const Layout& beside, const Layout& below) const {
  if (caption_wanted_ <= 0.0f || solvers_.state().open) return false;  // not measured yet, or slide 36's
  if (classroom_.caption_collapsed()) return docked_windows_ == 0;
  const float aspect = state_.scene ? state_.scene->cameras[size_t(state_.scene_camera)].aspect : 0.0f;
  if (!(aspect > 0.0f)) return false;
  const auto frame_height = [aspect](const Layout& l) {
    const Viewport& pane = l.panes.front();
    return std::min(pane.size.y, pane.size.x / aspect);
  };
  return frame_height(below) > frame_height(beside);
}

// ---- [loading] ---------------------------------------------------------------------------------
// A new scene replaces the old only once it has loaded: a broken file shows its error and the
// class keeps looking at the previous scene.
void Viewer::adopt(io::LoadedScene loaded, const std::filesystem::path& path, bool keep_view) {
  warnings_.clear();
  for (const std::string& warning : loaded.warnings) {
    fmt::print(stderr, "{}\n", trf("warning: {}", warning));
    warnings_.push_back(warning);
  }
  for (auto& [name, view] : views_) view->scene_changed();  // before the scene they read goes
  picker_.reset();
  renderer_.reset();  // both refer to the old scene
  inspection_ = Inspection{};
  state_.scene = std::make_unique<Scene>(std::move(loaded.scene));
  state_.scene_path = path;
  const Scene& scene = *state_.scene;
  solvers_.scene_changed(scene);  // the comparison on the old scene goes
  state_.light_edits.clear();
  for (const Light& light : scene.lights) {
    const float intensity = std::max({light.intensity.r, light.intensity.g, light.intensity.b});
    state_.light_edits.push_back({intensity > 0 ? light.intensity / intensity : Rgb(1.0f), intensity});
  }
  if (!keep_view || size_t(state_.scene_camera) >= scene.cameras.size()) {
    state_.scene_camera = 0;
    state_.free_camera = false;
  }
  if (!keep_view) state_.exposure = scene.exposure;
  exposure_check_ = true;
  if (size_t(state_.selected_material) >= scene.materials.size()) state_.selected_material = -1;
  if (!state_.free_camera) to_scene_camera();
  rebuild_renderer();
  picker_ = std::make_unique<Picker>(scene);
  state_.error.clear();
  show_warnings_ = !warnings_.empty();
  glfwSetWindowTitle(window_.handle(), ("Luz - " + path.filename().string()).c_str());
}

void Viewer::load(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension != ".gltf" && extension != ".glb") {
    state_.error = trf("{}: not a glTF scene (.gltf or .glb)", path.string());
    return;
  }
  try {
    adopt(io::load_gltf(path), path, path == state_.scene_path);
    state_.note = trf("loaded {}", path.filename().string());
  } catch (const Error& error) {
    state_.error = error.what();
    state_.note = tr("the scene did not load; showing the previous one");
    fmt::print(stderr, "luz: {}\n", error.what());
  }
}

void Viewer::rebuild_renderer() {
  renderer_.reset();
  renderer_ = std::make_unique<LocalRenderer>(*state_.scene);
  for (const std::string& warning : renderer_->warnings()) {
    fmt::print(stderr, "{}\n", trf("warning: {}", warning));
    warn(warning);
  }
}

// Each warning once, in the window until closed (and in the terminal, where it was printed).
void Viewer::warn(const std::string& warning) {
  if (std::find(warnings_.begin(), warnings_.end(), warning) != warnings_.end()) return;
  warnings_.push_back(warning);
  show_warnings_ = true;
}

Camera Viewer::current_camera() const {
  return state_.free_camera ? orbit_.camera() : state_.scene->cameras[size_t(state_.scene_camera)];
}

void Viewer::to_scene_camera() {
  state_.free_camera = false;
  orbit_.start_from(state_.scene->cameras[size_t(state_.scene_camera)], state_.scene->bounds().centre());
}

// ---- [views] -----------------------------------------------------------------------------------
ModelView& Viewer::view(std::string_view name) {
  auto found = views_.find(name);
  if (found != views_.end()) return *found->second;
  const ModelEntry* entry = find_model(name);
  if (!entry) throw Error(ErrorKind::usage, fmt::format("no model \"{}\"", name));  // a programmer's slip
  std::unique_ptr<ModelView> made = entry->make_view(*this);
  ModelView& result = *made;
  views_.emplace(std::string(name), std::move(made));
  return result;
}

void Viewer::set_model(const ModelEntry& model) {
  const auto pane = std::find(panes_.begin(), panes_.end(), &model);
  const ModelEntry* leaving = nullptr;
  if (pane != panes_.end()) {
    active_pane_ = size_t(pane - panes_.begin());
  } else {
    leaving = model_;
    panes_[active_pane_] = &model;
  }
  model_ = &model;
  // It leaves the window (a trace running there stops), told once the panes show the new model.
  if (leaving) view(leaving->name).hidden();
  state_.model = model.name;
  if (panes_.size() > 1)
    for (size_t i = 0; i < panes_.size(); ++i) state_.panes[i] = panes_[i]->name;
  state_.note = tr(model.label);
}

void Viewer::set_panes(const std::vector<std::string>& models) {
  std::vector<const ModelEntry*> wanted;
  for (const std::string& name : models) wanted.push_back(find_model(name));
  const std::vector<const ModelEntry*> before = panes_;
  const auto keep = std::find(wanted.begin(), wanted.end(), model_);  // the active model stays active
  active_pane_ = keep != wanted.end() ? size_t(keep - wanted.begin()) : 0;
  panes_ = wanted;
  model_ = panes_[active_pane_];
  // Those that leave the window are told once the panes show the new ones.
  for (const ModelEntry* shown_before : before)
    if (std::find(wanted.begin(), wanted.end(), shown_before) == wanted.end()) view(shown_before->name).hidden();
  state_.model = model_->name;
  state_.panes = panes_.size() > 1 ? models : std::vector<std::string>{};
  std::string names;
  for (const std::string& name : models) names += (names.empty() ? "" : ", ") + model_label(name);
  state_.note = panes_.size() > 1 ? trf("side by side: {}", names) : model_->label;
}

std::vector<ModelView*> Viewer::pane_views() {
  std::vector<ModelView*> shown_views;
  for (const ModelEntry* m : panes_) shown_views.push_back(&view(m->name));
  return shown_views;
}

// ---- [input] -----------------------------------------------------------------------------------
// A panel field being edited takes the keys: asked of ImGui's active item now, since
// io.WantTextInput tells of the frame before last and a key queued behind Enter would be lost.
bool Viewer::typing_in_panel() const {
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  return g.ActiveId != 0 && g.ActiveId == g.InputTextState.ID;
}

void Viewer::on_key(int key, int mods) {
  if (typing_in_panel()) return;  // typing a number into the panel
  press_key(key, mods);
}

void Viewer::press_key(int key, int mods) {
  if (asking_to_quit_) {  // the question takes the keys until it is answered
    if (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER || key == GLFW_KEY_Q) quit_ = true;
    if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_N) asking_to_quit_ = false;
    return;
  }
  if (const Shortcut* shortcut = shortcut_for(key, mods)) run_key(*shortcut);
}

void Viewer::on_char(unsigned codepoint) {
  if (typing_in_panel()) return;  // the character goes into the panel's field
  typed(codepoint);
}

void Viewer::typed(unsigned codepoint) {
  if (asking_to_quit_) return;  // its keys are pressed, not typed
  if (ImGui::GetIO().WantTextInput) {
    ImGui::GetIO().AddInputCharacter(codepoint);
    return;
  }
  if (const Shortcut* shortcut = shortcut_for_character(codepoint)) run_key(*shortcut);
}

void Viewer::on_mouse_button(int button, int action) {
  if (action == GLFW_PRESS) {
    if (ImGui::GetIO().WantCaptureMouse || !layout().view.contains(last_cursor_)) return;
    drag_ = button == GLFW_MOUSE_BUTTON_LEFT ? DragButton::left : DragButton::right;
    press_at_ = last_cursor_;
    dragged_ = false;
  } else if (drag_ != DragButton::none) {
    if (drag_ == DragButton::left && !dragged_) click_at(press_at_);
    drag_ = DragButton::none;
  }
}

void Viewer::on_cursor(glm::vec2 p) {
  const glm::vec2 delta = p - last_cursor_;
  last_cursor_ = p;
  if (drag_ == DragButton::none) return;
  if (!dragged_ && glm::length(p - press_at_) < drag_threshold) return;
  dragged_ = true;
  move_camera(drag_, delta);
}

void Viewer::on_scroll(float steps) {
  if (ImGui::GetIO().WantCaptureMouse || !layout().view.contains(last_cursor_)) return;
  zoom(steps);
}

void Viewer::zoom(float steps) {
  if (!state_.free_camera) to_scene_camera();
  state_.free_camera = true;
  orbit_.zoom(steps);
}

void Viewer::move_camera(DragButton button, glm::vec2 delta) {
  if (!state_.free_camera) to_scene_camera();  // start from what is on screen
  state_.free_camera = true;
  if (button == DragButton::left) orbit_.orbit(delta.x, delta.y);
  else orbit_.pan(delta.x, delta.y, layout().panes.front().size.y);  // the drag moves what is under it
}

bool Viewer::flying() const {
  if (ImGui::GetIO().WantTextInput) return false;
  GLFWwindow* w = window_.handle();
  for (int key : {GLFW_KEY_UP, GLFW_KEY_DOWN, GLFW_KEY_LEFT, GLFW_KEY_RIGHT, GLFW_KEY_PAGE_UP, GLFW_KEY_PAGE_DOWN})
    if (glfwGetKey(w, key) == GLFW_PRESS) return true;
  return false;
}

// Arrows and PageUp / PageDown fly at half the scene's size per second (Shift: four times that).
void Viewer::fly(float seconds) {
  if (!flying()) return;
  GLFWwindow* w = window_.handle();
  auto held = [w](int key) { return glfwGetKey(w, key) == GLFW_PRESS ? 1.0f : 0.0f; };
  const glm::vec3 axes(held(GLFW_KEY_UP) - held(GLFW_KEY_DOWN), held(GLFW_KEY_RIGHT) - held(GLFW_KEY_LEFT),
                       held(GLFW_KEY_PAGE_UP) - held(GLFW_KEY_PAGE_DOWN));
  if (axes == glm::vec3(0.0f)) return;
  const float fast = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ? 4.0f : 1.0f;
  const float speed = 0.5f * glm::length(state_.scene->bounds().extent()) * fast;
  if (!state_.free_camera) to_scene_camera();
  state_.free_camera = true;
  orbit_.fly(axes * speed * seconds);
}

void Viewer::click_at(glm::vec2 p) {
  const Layout l = layout();
  if (!l.view.contains(p)) {  // the panel: ImGui sees a press this frame and the release on the next
    scripted_click_at_ = p;
    scripted_click_frames_ = 2;
    return;
  }
  const int pane = pane_at(l.panes, p);
  if (l.view.empty() || pane < 0) return;  // a background strip beside the panes
  const Viewport& v = l.panes[size_t(pane)];
  if (v.empty()) return;
  if (panes_[size_t(pane)] != model_) set_model(*panes_[size_t(pane)]);  // the clicked pane is the active one
  shown().click(current_camera(), v, v.pixel_of(p));
}

bool Viewer::choose_camera(const std::string& name_or_index, std::string& error) {
  const int index = state_.scene->find_camera(name_or_index);
  if (index < 0) {
    error = fmt::format("the scene has no camera \"{}\"", name_or_index);
    return false;
  }
  state_.scene_camera = index;
  to_scene_camera();
  return true;
}

void Viewer::resize(int width, int height) { glfwSetWindowSize(window_.handle(), width, height); }

// ---- [keys] ------------------------------------------------------------------------------------
// A key runs its line (shortcuts.h) as a script would, and so does a button of the panel
// (panel.h); a line that cannot be done (a lesson's step with no lesson open) says why in the
// status line.
void Viewer::run_line(const std::string& line) {
  const Script script = parse_script_text(line, "key");  // every bound line is checked by the tests
  std::string error;
  for (const ScriptCommand& command : script.commands)
    if (!run(command, error)) {
      state_.note = error;
      return;
    }
}

void Viewer::next_camera() {
  state_.scene_camera = (state_.scene_camera + 1) % int(state_.scene->cameras.size());
  to_scene_camera();
  state_.note = trf("camera {}", state_.scene->cameras[size_t(state_.scene_camera)].name);
}

// On a projector a stray Esc must not end the class: with a lesson open or work running, it asks
// first.
void Viewer::ask_to_quit() {
  if (classroom_.has_lesson() || working()) asking_to_quit_ = true;
  else quit_ = true;
}

// ---- [script] ----------------------------------------------------------------------------------
bool Viewer::run(const ScriptCommand& command, std::string& error) {
  const ScriptVerb* verb = find_verb(command.verb);  // checked when the script was read
  return verb ? verb->run(*this, command, error) : true;
}

// A click's press and release, a `trace` the script waits for, radiosity shots it asked for
// (`radiosity step N`, `wait-shots N`), slide 36's rows, or `idle`: what is still playing out,
// in words for a script stopped while waiting (script_watch.h), or nullptr.
const char* Viewer::busy_with() const {
  if (scripted_click_frames_ > 0) return "a click";
  // Only the views shown work (a hidden one has stopped): their requests are what may be pending.
  for (const ModelEntry* m : panes_)
    if (const auto found = views_.find(m->name); found != views_.end() && found->second->busy()) return m->name;
  if (difference_.waiting()) return "the difference's reference";
  if (solvers_.busy()) return "slide 36's solvers";
  if (idle_until_) return "idle";
  if (classroom_.moving()) return "the lesson's move";
  return nullptr;
}

void Viewer::idle(double seconds) {
  idle_until_ = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                        std::chrono::duration<double>(seconds));
  idle_cpu_start_ = cpu_seconds();
  idle_wall_ = seconds;
}

nlohmann::json Viewer::windows_json() const {
  nlohmann::json windows = nlohmann::json::array();
  for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
    if (!w->Active || w->Hidden || (w->Flags & ImGuiWindowFlags_ChildWindow)) continue;
    const std::string name = w->Name;
    if (name.starts_with("Debug##")) continue;  // ImGui's own
    // content_width > visible_width: something in the window is cut at its right edge; the
    // same for the heights, at its bottom (unless one scrolls to it).
    windows.push_back({{"name", name},
                       {"rect", {w->Pos.x, w->Pos.y, w->Pos.x + w->Size.x, w->Pos.y + w->Size.y}},
                       {"content_width", w->ContentSize.x},
                       {"visible_width", w->ContentRegionRect.GetWidth()},
                       {"content_height", w->ContentSize.y},
                       {"visible_height", w->ContentRegionRect.GetHeight()},
                       {"scrolls_sideways", w->ScrollbarX}});
  }
  const Viewport& v = last_layout_.view;
  const Viewport& d = last_layout_.dock;
  return {{"view", {v.origin.x, v.origin.y, v.origin.x + v.size.x, v.origin.y + v.size.y}},
          {"dock", {d.origin.x, d.origin.y, d.origin.x + d.size.x, d.origin.y + d.size.y}},
          {"font_size", ImGui::GetFontSize()},
          {"windows", windows},
          {"tables", tables_json()}};
}

// Every table of the last frame, column by column: the width its text took ("text", the widest
// cell or heading) beside the room the column had ("room"), and whether its right edge ("right")
// lies inside its window ("clip_right") or the window scrolls sideways to it. A cell narrower
// than its text is cut.
nlohmann::json Viewer::tables_json() const {
  nlohmann::json tables = nlohmann::json::array();
  ImGuiContext& g = *ImGui::GetCurrentContext();
  for (int i = 0; i < g.Tables.GetMapSize(); ++i) {
    const ImGuiTable* t = g.Tables.TryGetMapData(i);
    if (!t || t->LastFrameActive < g.FrameCount - 1 || !t->OuterWindow || !t->OuterWindow->Active) continue;
    nlohmann::json columns = nlohmann::json::array();
    for (int c = 0; c < t->ColumnsCount; ++c) {
      const ImGuiTableColumn& column = t->Columns[c];
      const float end = std::max({column.ContentMaxXUnfrozen, column.ContentMaxXFrozen, column.ContentMaxXHeadersIdeal});
      columns.push_back({{"text", end - column.WorkMinX}, {"room", column.WorkMaxX - column.WorkMinX},
                         {"right", column.MaxX}});
    }
    // A table that scrolls sideways is a child window of its own (InnerWindow): its clip and
    // its scroll bar are that child's.
    const ImGuiWindow* inner = t->InnerWindow ? t->InnerWindow : t->OuterWindow;
    tables.push_back({{"window", t->OuterWindow->RootWindow->Name}, {"clip_right", inner->InnerClipRect.Max.x},
                      {"scrolls_sideways", inner->ScrollbarX || t->OuterWindow->RootWindow->ScrollbarX},
                      {"columns", columns}});
  }
  return tables;
}

// ---- [the frame] -------------------------------------------------------------------------------
// Each pane's view draws its radiance into that pane's picture, then the display pass shows it:
// radiance -> exposure -> sRGB, pixel for pixel into the pane's rectangle. A local model that
// computed those displayed values as it drew (ModelView::drew_display) is copied instead: the
// display pass's float fetch is most of its cost on a software rasteriser. On a frame that needs
// no radiance (no heat map, no screenshot of the picture) a view may draw what the window shows
// straight into it (ModelView::draw_into_window: the local models, but for the inspector and
// transparency), which saves the copy and the float picture's writes. One camera for all.
void Viewer::draw_picture(const Layout& l, bool view_alone_shown) {
  if (l.view.empty()) return;
  const Camera camera = current_camera();
  pictures_.resize(panes_.size());
  drawn_cameras_.assign(panes_.size(), camera);
  const bool reference_in_a_pane =
      std::any_of(panes_.begin(), panes_.end(), [](const ModelEntry* m) { return m == &reference_model(); });
  double models_ms = 0.0, exposure_ms = 0.0;  // summed over the panes
  copied_panes_ = direct_panes_ = 0;
  const bool checking_exposure = exposure_check_ && view(model_->name).shows_the_light();
  const bool reading_exposure = state_.exposure_fit || checking_exposure;
  const bool radiance_wanted =
      reading_exposure || difference_.on() || !state_.display_copy || !state_.display_direct || !window_takes_blits_ ||
      std::any_of(screenshots_.begin(), screenshots_.end(), [](const PendingScreenshot& s) { return !s.with_panel; });
  auto phase_start = FrameClock::now();
  for (size_t i = 0; i < panes_.size(); ++i) {
    const Viewport& v = l.panes[i];
    if (v.empty()) continue;
    std::unique_ptr<gl::Framebuffer>& picture = pictures_[i];
    if (!picture || picture->width() != v.pixels.x || picture->height() != v.pixels.y)
      picture = std::make_unique<gl::Framebuffer>(v.pixels.x, v.pixels.y, window_takes_blits_);
    ModelView& pane_view = view(panes_[i]->name);
    pane_view.advance(camera, v);
    if (!radiance_wanted && pane_view.draw_into_window(camera, v, view_alone_shown && panes_.size() == 1)) {
      if (i == active_pane_) difference_.draw(*this, *panes_[i], camera, v, *picture, reference_in_a_pane);
      ++direct_panes_;
      models_ms += finish_phase(phase_start);
      continue;
    }
    picture->bind();
    pane_view.draw(camera, v, *picture);
    // The heat map instead, when it is on, in the active pane: the panes are of one size, so
    // the reference's one film serves whichever pane is compared.
    const bool heat_map = i == active_pane_ && difference_.on();
    if (i == active_pane_) difference_.draw(*this, *panes_[i], camera, v, *picture, reference_in_a_pane);
    models_ms += finish_phase(phase_start);

    if (pane_view.drew_display() && !heat_map) {  // the model wrote what the window shows: a copy
      glBindFramebuffer(GL_READ_FRAMEBUFFER, picture->id());
      glReadBuffer(GL_COLOR_ATTACHMENT1);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
      glBlitFramebuffer(0, 0, v.pixels.x, v.pixels.y, v.gl_origin.x, v.gl_origin.y, v.gl_origin.x + v.pixels.x,
                        v.gl_origin.y + v.pixels.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      glBindFramebuffer(GL_READ_FRAMEBUFFER, picture->id());
      glReadBuffer(GL_COLOR_ATTACHMENT0);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      ++copied_panes_;
      exposure_ms += finish_phase(phase_start);
      continue;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(v.gl_origin.x, v.gl_origin.y, v.pixels.x, v.pixels.y);
    glDisable(GL_DEPTH_TEST);
    display_.use();
    display_.set("u_radiance", 0);
    display_.set("u_scale", std::exp2(state_.exposure));
    display_.set("u_origin", glm::vec2(v.gl_origin));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, picture->colour_texture());
    glBindVertexArray(empty_vertex_array_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glUseProgram(0);
    exposure_ms += finish_phase(phase_start);
  }
  smooth(state_.frame_phases.models_ms, models_ms);
  smooth(state_.frame_phases.exposure_ms, exposure_ms);
  if (reading_exposure) read_exposure(checking_exposure);
}

// The active pane's radiance against the exposure: fitted to it when K (the panel, `set exposure
// auto`) asked, and when `check`, for a scene just loaded, a warning when the picture is far off
// (most often a file whose lights are in photometric units).
void Viewer::read_exposure(bool check) {
  const bool fit = std::exchange(state_.exposure_fit, false);
  if (check) exposure_check_ = false;
  if (active_pane_ >= pictures_.size() || !pictures_[active_pane_]) return;
  const Image picture = pictures_[active_pane_]->read();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (fit) {
    const PictureKey key = picture_key(picture);
    if (const std::optional<float> fitted = fitted_exposure(key)) {
      state_.exposure = *fitted;
      // The load's warning about this exposure is answered: it goes (the window too, if it was the last).
      if (const auto found = std::find(warnings_.begin(), warnings_.end(), exposure_warning_); found != warnings_.end()) {
        warnings_.erase(found);
        show_warnings_ = show_warnings_ && !warnings_.empty();
      }
      state_.note = almost_no_light(key)
                        ? almost_no_light_note(key)
                        : trf("exposure {:+.1f} EV: the picture's log-average luminance, {:.3g}, shown as middle grey",
                              *fitted, key.log_average);
    } else {
      state_.note = tr("exposure: nothing in the picture is lit to fit it to");
    }
    frames_to_draw_ = std::max(frames_to_draw_, 1);  // the picture again, at its new exposure
  } else if (check) {
    const Scene& scene = *state_.scene;
    if (const std::string problem = exposure_problem(picture, state_.exposure, photometric_hint(scene));
        !problem.empty()) {
      exposure_warning_ = trf("{}: {}; K fits the exposure to the picture", state_.scene_path.filename().string(),
                              problem);
      fmt::print(stderr, "{}\n", trf("warning: {}", exposure_warning_));
      warn(exposure_warning_);
    }
  }
}

// The windows over the picture: the status line, the shown model's windows in the picture's
// corners (WindowCorners), slide 36's window in its left half, F1's list and a load error in the
// middle (they are asked for, and closed), the scene's warnings at the bottom.
void Viewer::draw_windows(const Layout& l) {
  std::string model;
  for (size_t i = 0; i < panes_.size(); ++i) {  // side by side: every pane's, the active one's in brackets
    std::string pane = panes_.size() > 1 ? model_label(panes_[i]->name) : std::string(tr(panes_[i]->label));
    if (const std::string s = view(panes_[i]->name).status(); !s.empty()) pane += " " + s;
    if (panes_.size() > 1 && i == active_pane_) pane = "[" + pane + "]";
    model += (i == 0 ? "" : " | ") + pane;
  }
  draw_status_line(status_shown(status_line_text(state_, model)), l.window.y - l.status, l.window.x, l.status);
  if (panes_.size() > 1)
    for (size_t i = 0; i < panes_.size(); ++i) draw_pane_label(pane_label(panes_[i]->name, l.panes[i]), i == active_pane_);

  const float margin = 8.0f * ui_scale_;
  WindowCorners corners(l.view, margin);
  if (!l.dock.empty()) {
    const auto [caption, column] = split_dock(l.dock, dock_wanted_);
    corners.dock_in(column);
    if (state_.show_panel) panel_hint_ = false;  // found: the hint has done its work
    const float wanted = classroom_.draw_caption(caption.origin, caption.size, margin, ui_scale_, panel_hint());
    if (std::abs(wanted - caption_wanted_) > 0.5f) {
      caption_wanted_ = wanted;  // the next frame's dock below the picture
      frames_to_draw_ = std::max(frames_to_draw_, 2);
    }
  }
  if (solvers_.state().open) {
    const glm::vec4 half = corners.take_left_half();
    solvers_.draw(half.x, half.y, half.z, half.w, corners.docked());
  }
  if (panes_.size() > 1) {  // the active pane's windows, in its own corners
    WindowCorners pane_corners(l.panes[active_pane_], margin);
    const PaneLabel label = pane_label(panes_[active_pane_]->name, l.panes[active_pane_]);
    pane_corners.reserve_top(label.origin.y + label.size.y);  // the hints go below the pane's name
    if (!l.dock.empty()) pane_corners.dock_in(split_dock(l.dock, dock_wanted_).second);
    shown().windows(l.panes[active_pane_], pane_corners);
    difference_.windows(l.panes[active_pane_], pane_corners);
  } else {
    shown().windows(l.view, corners);
    difference_.windows(l.view, corners);
  }
  draw_warnings(warnings_, show_warnings_, l.view, margin);
  if (state_.show_help) draw_help(state_.show_help, l.view.centre(), 0.9f * l.view.size);
  if (!state_.error.empty()) draw_load_error(state_, l.view.centre().x, l.view.centre().y, l.view.size.x);
  draw_quit_question(l.view);
  if (!l.dock.empty()) measure_dock(split_dock(l.dock, dock_wanted_).second, margin);
}

// The dock (or its windows' column, below the picture) widens when a docked window's content is
// wider than the room it had (a table's columns keep the width of their text), up to half the
// picture's room; the next frame gives it that room. It keeps that width while windows other
// than the caption stay docked. How many are docked decides where a folded caption goes
// (dock_goes_below); they are docked in either place, so the choice cannot swing between frames.
void Viewer::measure_dock(const Viewport& column, float margin) {
  float wanted = dock_wanted_;
  int docked = 0;
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  const Viewport& d = column;
  for (const ImGuiWindow* w : g.Windows) {
    if (!w->Active || w->Hidden || (w->Flags & (ImGuiWindowFlags_ChildWindow | ImGuiWindowFlags_Tooltip))) continue;
    const bool in_dock = w->Pos.x >= d.origin.x + 0.5f * margin && w->Pos.x < d.origin.x + d.size.x &&
                         w->Pos.y >= d.origin.y + 0.5f * margin && w->Pos.y < d.origin.y + d.size.y;
    if (!in_dock || std::string_view(w->Name).starts_with("##lesson")) continue;
    ++docked;
    const float overflow = w->ContentSize.x - w->ContentRegionRect.GetWidth();
    if (overflow > 0.5f) wanted = std::max(wanted, d.size.x + overflow);
  }
  if (docked == 0) wanted = 0.0f;
  if (docked != docked_windows_) {
    docked_windows_ = docked;
    frames_to_draw_ = std::max(frames_to_draw_, 2);
  }
  if (std::abs(wanted - dock_wanted_) > 0.5f) {
    dock_wanted_ = wanted;
    frames_to_draw_ = std::max(frames_to_draw_, 2);
  }
}

// Esc's question, in the picture's middle: Enter (or Q, or its button) quits, Esc (or N, or its
// button) stays. The keys are press_key's; the popup is modal, so the mouse answers it or nothing.
void Viewer::draw_quit_question(const Viewport& view) {
  static constexpr const char* popup = "###quit";
  if (asking_to_quit_ && !ImGui::IsPopupOpen(popup)) ImGui::OpenPopup(popup);
  ImGui::SetNextWindowPos(ImVec2(view.centre().x, view.centre().y), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  const std::string title = std::string(tr("Quit Luz?")) + popup;
  if (!ImGui::BeginPopupModal(title.c_str(), nullptr,
                              ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings))
    return;
  if (!asking_to_quit_) {
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return;
  }
  if (const LessonPlayer* lesson = classroom_.player())
    ImGui::TextUnformatted(trf("The lesson is at step {} of {}.", lesson->index() + 1, lesson->size()).c_str());
  if (working()) ImGui::TextUnformatted(tr("A computation is still running."));
  if (ImGui::Button(tr("Quit  [Enter]"))) quit_ = true;
  ImGui::SameLine();
  if (ImGui::Button(tr("Stay  [Esc]"))) asking_to_quit_ = false;
  ImGui::EndPopup();
}

// The status line's text: `text` at once when it differs from the shown one in more than its
// digits (a key's message, another model or camera, a trace that ends), else at the next
// refresh, twice a second (the frame time, a trace's progress, radiosity's shots): readable, and
// a status line that stays the same from frame to frame stays in the panel cache instead of being
// drawn and shown again on every frame. `status-time off` holds the figures.
const std::string& Viewer::status_shown(const std::string& text) {
  const FrameClock::time_point now = FrameClock::now();
  const bool due = state_.status_ms_live && now - status_refreshed_ >= std::chrono::milliseconds(500);
  if (due) status_refreshed_ = now;
  if (due || !same_but_digits(text, status_shown_)) status_shown_ = text;
  return status_shown_;
}

std::vector<const gl::Framebuffer*> Viewer::pane_pictures() const {
  std::vector<const gl::Framebuffer*> pictures;
  for (const auto& picture : pictures_) pictures.push_back(picture.get());
  return pictures;
}

void Viewer::take_screenshots(const Layout& l) {
  for (const PendingScreenshot& shot : screenshots_) {
    try {
      if (shot.shown) save_shown_window(window_, shot.path);
      else if (shot.with_panel) save_window(l.framebuffer.x, l.framebuffer.y, shot.path);
      else if (panes_.size() > 1 && pictures_.size() == panes_.size() && l.panes.size() == panes_.size())
        save_panes(pane_pictures(), l.panes, state_.panes, l.view, shot.path, state_.exposure);
      else if (!pictures_.empty() && pictures_.front()) save_picture(*pictures_.front(), shot.path, state_.exposure);
      if (shot.quiet) continue;
      state_.note = trf("saved {}", shot.path.string());
      fmt::print("{}\n", state_.note);
      if (shot.origin.empty() && screenshot_saved_) screenshot_saved_(shot.path);
    } catch (const Error& error) {
      state_.note = error.what();
      if (!shot.origin.empty() && failure_.empty()) failure_ = error.what();
      fmt::print(stderr, "luz: {}\n", error.what());
    }
  }
  screenshots_.clear();
}

// Clears to the background the window's pixels that nothing paints whole this frame: the panel's
// rectangles (the status line's window may be translucent) unless the cache copies or keeps them
// there, and the view unless its panes tile it. On the software rasteriser a clear costs per
// pixel (a whole 1280x720 window's about 2 ms), so what is painted anyway is not cleared first.
// Nothing reads the window's depth but the local models, which clear their pane's.
void Viewer::clear_unpainted(const Layout& l, std::span<const FramebufferRect> panel, bool panel_painted,
                             glm::vec4 colour) {
  long tiled = 0;
  for (const Viewport& pane : l.panes) tiled += long(pane.pixels.x) * pane.pixels.y;
  const bool view_tiled = !l.view.empty() && tiled == long(l.view.pixels.x) * l.view.pixels.y;
  glClearColor(colour.r, colour.g, colour.b, colour.a);
  glEnable(GL_SCISSOR_TEST);
  const auto clear = [](const FramebufferRect& r) {
    if (r.empty()) return;
    glScissor(r.x, r.y, r.width, r.height);
    glClear(GL_COLOR_BUFFER_BIT);
  };
  if (!panel_painted) std::for_each(panel.begin(), panel.end(), clear);
  if (!view_tiled) clear(framebuffer_rect(l.view));
  if (!l.dock.empty()) clear(framebuffer_rect(l.dock));  // under the caption and the docked windows
  glDisable(GL_SCISSOR_TEST);
}

void Viewer::frame() {
  if (fonts_stale_) rebuild_fonts();
  // The lines the panel's buttons ran during the last frame, as their keys run them.
  for (const std::string& line : std::exchange(state_.panel_lines, {})) run_line(line);
  if (state_.emitters_changed) {
    state_.emitters_changed = false;
    state_.scene->find_area_lights();
    rebuild_renderer();
    for (auto& [name, view] : views_) view->emitters_changed();
  }
  // Slide 36's solvers step here, on the GL thread, within their own budget per frame.
  solvers_.advance();

  // The first frames (shaders compiled, maps drawn) are not the steady frame being measured.
  timing_phases_ = frame_number_ >= 16 && frame_number_ % 8 == 0;
  ++frame_number_;
  const auto panel_building_start = FrameClock::now();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  if (scripted_click_frames_ > 0) {  // a script's click on the panel
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(scripted_click_at_.x, scripted_click_at_.y);
    io.MouseDown[0] = scripted_click_frames_-- == 2;
  }
  ImGui::NewFrame();
  const Layout l = layout();
  last_layout_ = l;
  if (state_.show_panel) draw_panel(state_, shown(), difference_, l.panel, l.window.y - l.status);
  draw_windows(l);
  ImGui::Render();
  const double panel_building =
      1000.0 * std::chrono::duration<double>(FrameClock::now() - panel_building_start).count();

  // The panel cache's rectangles: the panel left of the view, the status line under both. Where
  // the window keeps what it shows, a panel that has not changed stays on the screen: the frame
  // draws and shows only the view. The back buffer's panel may then be wiped (a view may clear
  // the whole window, see draw_into_window), so a frame that shows the whole window (an expose)
  // or saves it with the panel copies the panel in again.
  const FramebufferRect panel[] = {{0, l.view.gl_origin.y, l.view.gl_origin.x, l.view.pixels.y},
                                   {0, 0, l.framebuffer.x, l.view.gl_origin.y}};
  const bool window_read = std::any_of(screenshots_.begin(), screenshots_.end(),
                                       [](const PendingScreenshot& shot) { return shot.with_panel && !shot.shown; });
  const bool window_kept = window_.keeps_back_buffer() && state_.present_parts && !show_whole_window_ && !window_read;
  const bool panel_kept = window_takes_blits_ && panel_cache_.prepare(*ImGui::GetDrawData(), panel, window_kept);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, l.framebuffer.x, l.framebuffer.y);
  clear_unpainted(l, panel, window_takes_blits_ && panel_cache_.paints_panel(), background);
  ViewerState::FramePhases& phases = state_.frame_phases;
  draw_picture(l, panel_kept);  // the view alone shown where the panel is kept
  auto phase_start = FrameClock::now();
  glViewport(0, 0, l.framebuffer.x, l.framebuffer.y);
  if (window_takes_blits_) panel_cache_.draw(background);
  else ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  take_screenshots(l);
  smooth(phases.panel_building_ms, panel_building);
  smooth(phases.panel_ms, panel_building + finish_phase(phase_start));
  const FramebufferRect rest[] = {framebuffer_rect(l.view), framebuffer_rect(l.dock)};
  if (panel_kept) window_.present(std::span(rest, l.dock.empty() ? 1 : 2));
  else window_.present();
  show_whole_window_ = false;
  smooth(phases.present_ms, finish_phase(phase_start));
}

// On the frames that time their phases (one in eight: the waits would slow every frame), each
// phase ends with glFinish, so that its time is its own and not the next one's wait: the ms
// since `start`, which becomes now. On the others, nothing.
double Viewer::finish_phase(FrameClock::time_point& start) const {
  if (!timing_phases_) return 0.0;
  glFinish();
  const auto end = FrameClock::now();
  const double ms = 1000.0 * std::chrono::duration<double>(end - start).count();
  start = end;
  return ms;
}

// Smoothed over about ten timed frames, from the first.
void Viewer::smooth(double& ms, double sample) const {
  if (timing_phases_) ms = ms == 0.0 ? sample : 0.9 * ms + 0.1 * sample;
}

// ---- [the loop] --------------------------------------------------------------------------------
// Frames are drawn while something changes: after an event, while a model runs (a trace, the
// solver), slide 36's methods step, the camera flies or a script plays. Otherwise the loop
// sleeps in glfwWaitEvents: an idle window costs no CPU.
bool Viewer::needs_frames() const {
  if (frames_to_draw_ > 0 || fonts_stale_ || flying() || !screenshots_.empty() || !input_.empty()) return true;
  if (script_ && !script_->finished() && !idle_until_ && !script_->waiting_until()) return true;
  if (!queued_lines_.empty()) return true;
  if (classroom_.moving()) return true;
  if (ImGui::GetIO().WantTextInput) return true;  // the caret blinks
  return working();
}

// A pass draws no frame while the only thing changing is the paced work (ModelView::paced,
// SolversWindow::paced) and the last frame is younger than paced_frames_: no event, no line to
// step, no other work.
bool Viewer::frame_held() const {
  if (paced_frames_.count() == 0 || FrameClock::now() - last_pass_ >= paced_frames_) return false;
  if (frames_to_draw_ > 0 || fonts_stale_ || flying() || !screenshots_.empty() || !input_.empty() || idle_until_) return false;
  if (script_ && !script_->finished()) return false;
  if (!queued_lines_.empty() && !queued_lines_.front().runner.finished()) return false;
  if (classroom_.moving() || ImGui::GetIO().WantTextInput || difference_.refining()) return false;
  if (solvers_.working() && !solvers_.paced()) return false;
  bool paced = solvers_.paced();
  for (const ModelEntry* m : panes_)
    if (const auto found = views_.find(m->name); found != views_.end() && found->second->animating()) {
      if (!found->second->paced()) return false;
      paced = true;
    }
  return paced;
}

// A held pass: the paced work (the views', slide 36's window's) on the GL thread.
void Viewer::work_between_frames() {
  solvers_.step_between_frames();
  for (const ModelEntry* m : panes_)
    if (const auto found = views_.find(m->name); found != views_.end() && found->second->animating())
      found->second->between_frames();
}

// Work that changes what the window shows from frame to frame: a model running (a trace, the
// solver), its reference refining, slide 36's methods stepping.
bool Viewer::working() const {
  if (solvers_.working()) return true;
  if (difference_.refining()) return true;
  for (const ModelEntry* m : panes_)
    if (const auto found = views_.find(m->name); found != views_.end() && found->second->animating()) return true;
  return false;
}

// Waits for an event or a script's time unless a frame is due; in the page the browser calls
// every pass, and one with nothing due draws nothing (WindowContext::wait).
std::optional<int> Viewer::pass() {
  if (window_.should_close() || quit_) return 0;
  // `idle` and a script's `wait 2s` sleep until their time is up, unless an event comes.
  std::optional<std::chrono::steady_clock::time_point> wake = idle_until_;
  if (script_ && !idle_until_) wake = script_->waiting_until();
  if (needs_frames()) {
    window_.poll();
  } else if (!window_.wait(wake)) {
    return std::nullopt;
  }
  if (frame_held()) {
    work_between_frames();
    return std::nullopt;
  }
  if (idle_until_ && std::chrono::steady_clock::now() >= *idle_until_) {
    idle_cpu_fraction_ = (cpu_seconds() - idle_cpu_start_) / idle_wall_;
    idle_until_.reset();
  }
  while (!input_.empty()) {  // this frame's share of the keys (see the key callback)
    const InputEvent e = input_.front();
    input_.pop_front();
    if (!e.is_key) {
      ImGui_ImplGlfw_CharCallback(window_.handle(), e.codepoint);  // ImGui's, then ours
      continue;
    }
    ImGui_ImplGlfw_KeyCallback(window_.handle(), e.key, e.scancode, e.action, e.mods);
    if (e.action != GLFW_RELEASE) break;
  }

  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - last_pass_).count();
  last_pass_ = now;
  state_.frame_ms = 0.9 * state_.frame_ms + 0.1 * 1000.0 * std::min(seconds, 1.0);  // smoothed for reading
  if (state_.status_ms_live) state_.status_ms = state_.frame_ms;
  if (std::string error; !classroom_.step(*this, error)) {  // a lesson's move: a script's failure, else a warning
    if (script_) {
      fmt::print(stderr, "luz: {}\n", error);
      return 1;
    }
    warn(error);
  }
  if (script_) {
    std::string error;
    if (!script_->step(*this, error)) {
      fmt::print(stderr, "luz: {}\n", error);
      return 1;
    }
    const char* waits_for = busy_with();
    script_watch::at(fmt::format("{}, waiting for: {}", script_->position(),
                                 waits_for ? waits_for : script_->waiting_until() ? "time" : "frames"));
    script_watch::frame_begins();
  }
  step_queued_line();
  const bool line_waits = !queued_lines_.empty() && queued_lines_.front().runner.finished() && busy();
  fly(float(std::min(seconds, 0.1)));
  const bool worked = working();
  frame();
  if (frames_to_draw_ > 0) --frames_to_draw_;
  // Work ends inside a frame (its last tiles uploaded, the solver at its stopping rule), after
  // the panel and the status line were laid out with it still running: more frames show the
  // end, else the window would keep "tracing 98%" until the next event. Two: ImGui sizes a
  // window's scrollbar from the frame before's contents.
  if (worked && !working()) frames_to_draw_ = std::max(frames_to_draw_, 2);
  // A line that waited for work which ended in this frame (a trace's last tiles, the solver's
  // rule) is answered now, its picture drawn, rather than at the next frame's start: in the page
  // a frame can take tens of milliseconds. The next line starts at the next frame, as always.
  if (line_waits) answer_finished_line();
  if (failure_.empty()) return std::nullopt;
  if (script_ || queued_lines_.empty()) return 1;
  const LineDone done = std::move(queued_lines_.front().done);  // the failure is the running line's
  queued_lines_.pop_front();
  done(std::exchange(failure_, {}));
  return std::nullopt;
}

void Viewer::run_later(const std::string& line, LineDone done) {
  try {
    queued_lines_.push_back({ScriptRunner(parse_script_text(line, "luz.run")), std::move(done)});
    frames_to_draw_ = std::max(frames_to_draw_, 1);
  } catch (const Error& error) {
    done(error.what());
  }
}

// The first queued line's commands of this frame. It is done once its commands have run and
// what they started is over (busy()) and drawn: the frame after its last command.
void Viewer::step_queued_line() {
  if (queued_lines_.empty()) return;
  if (answer_finished_line()) return step_queued_line();
  QueuedLine& line = queued_lines_.front();
  std::string error;
  if (!line.runner.step(*this, error)) {
    const LineDone done = std::move(line.done);
    queued_lines_.pop_front();
    done(error);
  }
}

// The front line, once it has run and the work it asked for is done: its promise is kept.
bool Viewer::answer_finished_line() {
  if (queued_lines_.empty() || !queued_lines_.front().runner.finished() || busy()) return false;
  const LineDone done = std::move(queued_lines_.front().done);
  queued_lines_.pop_front();
  done("");
  return true;
}

// ---- [run_viewer] ------------------------------------------------------------------------------
int start_viewer(const ViewerSettings& settings) {
  io::LoadedScene loaded = io::load_gltf(settings.scene);
  auto viewer = std::make_shared<Viewer>(std::move(loaded), settings.scene, settings);
  if (settings.started) settings.started(*viewer);
  return gl::WindowContext::drive_frames([viewer] { return viewer->pass(); });
}

int run_viewer(const ViewerSettings& settings) {
  try {
    return start_viewer(settings);
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return 1;
  }
}

}  // namespace luz::app
