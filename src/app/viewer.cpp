// The viewer's loop: a window with the panel on the left, the picture on the right and the
// status line under it. Every change comes in as an Action (shortcuts.h), a panel edit of the
// ViewerState, a mouse gesture or a script line, and is drawn on the next frame.
//
// Sections: [layout] [the viewer] [loading] [input] [actions] [script] [the frame]
//           [the windows over the picture] [run_viewer]
#include "app/viewer.h"

#include "gl/functions.h"  // before GLFW: GLFW_INCLUDE_NONE keeps GLFW from including GL

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <vector>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "app/inspector.h"
#include "app/ui_glyphs.h"
#include "app/orbit_camera.h"
#include "app/overlays.h"
#include "app/panel.h"
#include "app/picking.h"
#include "app/radiosity_view.h"
#include "app/ray_tree_drawing.h"
#include "app/render_whitted.h"
#include "app/screenshot.h"
#include "app/shortcuts.h"
#include "app/solvers_view.h"
#include "app/viewer_state.h"
#include "app/whitted_view.h"
#include "core/error.h"
#include "gl/framebuffer.h"
#include "gl/shader.h"
#include "gl/window_context.h"
#include "hybrid/radiosity_diffuse.h"
#include "io/gltf_loader.h"
#include "local/local_renderer.h"

namespace luz::app {
namespace {

constexpr int default_width = 1280;
constexpr int default_height = 760;
constexpr float panel_width = 440.0f;   // window units at a UI scale of 1
constexpr float font_size = 16.0f;      // pixels at a content scale of 1
constexpr float drag_threshold = 3.0f;  // window units a press may move and still be a click
const char* const font_file = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// ---- [layout] ----------------------------------------------------------------------------------
// Window coordinates (GLFW's, ImGui's, the script's) have their origin at the top left; on a
// HiDPI screen a window unit can be several framebuffer pixels.
struct Layout {
  glm::vec2 window{0.0f};
  glm::ivec2 framebuffer{0};
  glm::vec2 scale{1.0f};         // framebuffer pixels per window unit
  float panel = 0.0f;            // panel width, window units
  float status = 0.0f;           // status line height, window units
  glm::vec2 view_origin{0.0f};   // the picture's top-left corner, window units
  glm::ivec2 view_pixels{0};     // the picture's size in framebuffer pixels
  glm::ivec2 view_gl_origin{0};  // its lower-left corner in GL's window pixels

  bool in_view(glm::vec2 p) const {
    return p.x >= view_origin.x && p.y >= view_origin.y && p.x < window.x && p.y < window.y - status;
  }
  glm::ivec2 pixel_of(glm::vec2 p) const {  // row 0 at the top of the picture
    return glm::ivec2(glm::floor((p - view_origin) * scale));
  }
  glm::vec2 window_of(glm::ivec2 pixel) const {
    return view_origin + (glm::vec2(pixel) + 0.5f) / scale;
  }
};

enum class DragButton { none, left, right };

struct PendingScreenshot {
  std::filesystem::path path;
  bool with_panel = false;
  std::string origin;  // "demo.txt:12" for a script's, empty for a key's
};

// ---- [the viewer] ------------------------------------------------------------------------------
class Viewer : public ScriptTarget {
public:
  Viewer(io::LoadedScene loaded, const std::filesystem::path& path, const ViewerSettings& settings);
  ~Viewer() override;
  int loop();  // until Esc, the window closes or the script quits; the exit code

  bool run(const ScriptCommand& command, std::string& error) override;
  // A click's press and release, a `trace` the script waits for, or radiosity shots it asked for
  // (`radiosity step N`, `wait-shots N`).
  bool busy() const override {
    const bool tracing = state_.trace_requested || (whitted_ && whitted_->phase() == TracePhase::tracing);
    const RadiosityState& r = state_.radiosity;
    const bool solving = state_.model == Model::radiosity || state_.model == Model::hybrid;
    const bool shooting = solving && (r.steps > 0 || r.stop_at > 0 || r.remesh);
    const SolversState& s = state_.solvers;
    const bool solving_system = s.run_to_rows > 0 || s.reset || s.status.phase == SolversState::Phase::building;
    return scripted_click_frames_ > 0 || (waiting_for_trace_ && tracing) || shooting || solving_system;
  }

private:
  void adopt(io::LoadedScene loaded, const std::filesystem::path& path, bool keep_view);
  void load(const std::filesystem::path& path);
  void rebuild_renderer();
  Camera current_camera() const;
  void to_scene_camera();
  Layout layout() const;

  void on_key(int key, int mods);
  void on_mouse_button(int button, int action);
  void on_cursor(glm::vec2 p);
  void on_scroll(float steps);
  void apply(Action action);
  void set_model(Model model);
  void click(glm::vec2 p);
  void pick_ray_tree(const Layout& l, glm::ivec2 pixel);
  void move_camera(DragButton button, glm::vec2 delta);
  void fly(float seconds);

  void frame();
  void draw_picture(const Layout& l);
  rt::WhittedOptions tracer_options() const;
  Fingerprint view_fingerprint(const Camera& camera, glm::ivec2 size) const;
  void show_traced(const Layout& l, const Camera& camera);
  void draw_untraced(const Layout& l, const Camera& camera);
  bool refresh_diffuse();
  void show_radiosity(const Layout& l, const Camera& camera);
  void drop_radiosity();
  bool run_radiosity(const ScriptCommand& command, std::string& error);
  void draw_radiosity_windows(const Layout& l);
  void update_inspector(const Layout& l, const Camera& camera);
  void draw_windows(const Layout& l);
  void take_screenshots(const Layout& l);

  gl::WindowContext window_;
  ViewerState state_;
  float ui_scale_ = 1.0f;
  std::unique_ptr<LocalRenderer> renderer_;
  std::unique_ptr<Picker> picker_;
  std::unique_ptr<gl::Framebuffer> picture_;  // the picture's float radiance
  gl::Program display_{{"display.vert", "display.frag"}};
  GLuint empty_vertex_array_ = 0;  // core profile draws need one bound, even with no attributes
  OrbitCamera orbit_;

  std::optional<Pick> pick_;
  Camera picked_with_;             // the view the pick was made in: moving the camera re-picks
  glm::ivec2 picked_size_{0};
  std::optional<InspectorReading> reading_;

  // Whitted (model 4): the trace off the GL thread, made when first needed (it builds Embree's
  // BVH), and the ray tree drawn over the picture.
  std::unique_ptr<WhittedView> whitted_;
  std::unique_ptr<RayTreeDrawing> tree_drawing_;

  // Radiosity (model 5): mesh, solver and renderer, made when the model is first shown and again
  // after a remesh, a new scene or an edited Le.
  std::unique_ptr<RadiosityView> radiosity_;
  bool waiting_for_trace_ = false;  // the script's `trace` waits for the end

  // The hybrid (model 6): the same WhittedView traces it, reading radiosity_'s solution through
  // diffuse_ (which refers to radiosity_'s mesh). diffuse_ is updated only while no trace runs,
  // and goes (after the trace is cancelled) whenever radiosity_ does. `traced_model_` tells a
  // Whitted picture from a hybrid one when the model is switched.
  std::unique_ptr<hybrid::RadiosityDiffuse> diffuse_;
  Model traced_model_ = Model::whitted;

  // Slide 36's window: its own mesh, matrix and four solvers, made when first opened.
  std::unique_ptr<SolversView> solvers_;

  DragButton drag_ = DragButton::none;
  glm::vec2 press_at_{0.0f}, last_cursor_{0.0f};
  bool dragged_ = false;

  std::optional<ScriptRunner> script_;
  glm::vec2 scripted_click_at_{0.0f};
  int scripted_click_frames_ = 0;  // 2: press this frame, 1: release, 0: none
  std::string failure_;            // a script command that failed: the run ends with exit 1
  std::vector<PendingScreenshot> screenshots_;
  bool quit_ = false;
};

Viewer::Viewer(io::LoadedScene loaded, const std::filesystem::path& path, const ViewerSettings& settings)
    : window_(settings.width > 0 ? settings.width : default_width,
              settings.height > 0 ? settings.height : default_height,
              "Luz - " + path.filename().string()) {
  glGenVertexArrays(1, &empty_vertex_array_);
  if (settings.script) script_.emplace(*settings.script);

  GLFWwindow* w = window_.handle();
  glfwSetWindowUserPointer(w, this);
  // Ours first: ImGui's GLFW backend (1.86) keeps these and calls them after its own.
  glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int mods) {
    if (action != GLFW_RELEASE) static_cast<Viewer*>(glfwGetWindowUserPointer(win))->on_key(key, mods);
  });
  glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int) {
    static_cast<Viewer*>(glfwGetWindowUserPointer(win))->on_mouse_button(button, action);
  });
  glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) {
    static_cast<Viewer*>(glfwGetWindowUserPointer(win))->on_cursor(glm::vec2(float(x), float(y)));
  });
  glfwSetScrollCallback(w, [](GLFWwindow* win, double, double dy) {
    static_cast<Viewer*>(glfwGetWindowUserPointer(win))->on_scroll(float(dy));
  });
  glfwSetDropCallback(w, [](GLFWwindow* win, int count, const char** paths) {
    if (count > 0) static_cast<Viewer*>(glfwGetWindowUserPointer(win))->load(paths[count - 1]);
  });

  // Dear ImGui, scaled for the screen: fonts are rasterised at the pixel size they will have.
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the same layout every run, for the class and for the tests
  float content_x = 1.0f, content_y = 1.0f;
  glfwGetWindowContentScale(w, &content_x, &content_y);
  int window_w = 1, window_h = 1;
  glfwGetWindowSize(w, &window_w, &window_h);
  const float pixels_per_unit = float(std::max(window_.framebuffer_size().x, 1)) / float(std::max(window_w, 1));
  const float content = std::max(content_x, 1.0f);
  ui_scale_ = std::max(content / pixels_per_unit, 1.0f);
  // The formula needs Greek letters, sub- and superscripts: DejaVu Sans has them (Debian's
  // fonts-dejavu-core); without it ImGui's own font shows '?' for those.
  static_assert(sizeof(ImWchar) == sizeof(kUiGlyphRanges[0]));
  const ImWchar* ranges = kUiGlyphRanges;
  if (std::filesystem::exists(font_file)) {
    io.Fonts->AddFontFromFileTTF(font_file, font_size * content, nullptr, ranges);
  } else {
    ImFontConfig config;
    config.SizePixels = 13.0f * content;
    io.Fonts->AddFontDefault(&config);
  }
  io.FontGlobalScale = 1.0f / pixels_per_unit;
  ImGui::StyleColorsDark();
  ImGui::GetStyle().ScaleAllSizes(ui_scale_);
  ImGui_ImplGlfw_InitForOpenGL(w, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  adopt(std::move(loaded), path, false);
}

Viewer::~Viewer() {
  whitted_.reset();  // a hybrid trace reads diffuse_ and radiosity_'s mesh: join it before they go
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  if (empty_vertex_array_) glDeleteVertexArrays(1, &empty_vertex_array_);
}

Layout Viewer::layout() const {
  Layout l;
  int w = 0, h = 0;
  glfwGetWindowSize(window_.handle(), &w, &h);
  l.window = glm::vec2(float(std::max(w, 1)), float(std::max(h, 1)));
  l.framebuffer = window_.framebuffer_size();
  l.scale = glm::vec2(l.framebuffer) / l.window;
  l.panel = state_.show_panel ? std::min(panel_width * ui_scale_, 0.6f * l.window.x) : 0.0f;
  l.status = ImGui::GetFontSize() + 2.0f * ImGui::GetStyle().WindowPadding.y;
  l.view_origin = glm::vec2(l.panel, 0.0f);
  const int left = int(std::lround(l.panel * l.scale.x));
  l.view_pixels = glm::ivec2(std::max(l.framebuffer.x - left, 0),
                             std::max(int(std::lround((l.window.y - l.status) * l.scale.y)), 0));
  l.view_gl_origin = glm::ivec2(left, l.framebuffer.y - l.view_pixels.y);
  return l;
}

// ---- [loading] ---------------------------------------------------------------------------------
// A new scene replaces the old only once it has loaded: a broken file shows its error and the
// class keeps looking at the previous scene.
void Viewer::adopt(io::LoadedScene loaded, const std::filesystem::path& path, bool keep_view) {
  for (const std::string& warning : loaded.warnings) fmt::print(stderr, "warning: {}\n", warning);
  picker_.reset();
  renderer_.reset();  // both refer to the old scene
  whitted_.reset();   // cancels a trace; the tree below belongs to the old scene too
  diffuse_.reset();
  radiosity_.reset();  // its solver keeps the old scene
  solvers_.reset();    // so does the comparison
  state_.solvers.status = {};
  state_.solvers.running = false;
  state_.solvers.run_to_rows = 0;
  state_.radiosity.patch.reset();
  state_.ray_tree.reset();
  if (tree_drawing_) tree_drawing_->clear();
  pick_.reset();
  reading_.reset();
  state_.scene = std::make_unique<Scene>(std::move(loaded.scene));
  state_.scene_path = path;
  const Scene& scene = *state_.scene;
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
  if (size_t(state_.selected_material) >= scene.materials.size()) state_.selected_material = -1;
  if (!state_.free_camera) to_scene_camera();
  rebuild_renderer();
  picker_ = std::make_unique<Picker>(scene);
  state_.error.clear();
  glfwSetWindowTitle(window_.handle(), ("Luz - " + path.filename().string()).c_str());
}

void Viewer::load(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension != ".gltf" && extension != ".glb") {
    state_.error = fmt::format("{}: not a glTF scene (.gltf or .glb)", path.string());
    return;
  }
  try {
    adopt(io::load_gltf(path), path, path == state_.scene_path);
    state_.note = fmt::format("loaded {}", path.filename().string());
  } catch (const Error& error) {
    state_.error = error.what();
    state_.note = "the scene did not load; showing the previous one";
    fmt::print(stderr, "luz: {}\n", error.what());
  }
}

void Viewer::rebuild_renderer() {
  renderer_.reset();
  renderer_ = std::make_unique<LocalRenderer>(*state_.scene);
  for (const std::string& warning : renderer_->warnings()) fmt::print(stderr, "warning: {}\n", warning);
}

Camera Viewer::current_camera() const {
  return state_.free_camera ? orbit_.camera() : state_.scene->cameras[size_t(state_.scene_camera)];
}

void Viewer::to_scene_camera() {
  state_.free_camera = false;
  orbit_.start_from(state_.scene->cameras[size_t(state_.scene_camera)], state_.scene->bounds().centre());
}

// ---- [input] -----------------------------------------------------------------------------------
void Viewer::on_key(int key, int mods) {
  if (ImGui::GetIO().WantTextInput) return;  // typing a number into the panel
  if (const auto action = action_for(key, mods)) apply(*action);
}

void Viewer::on_mouse_button(int button, int action) {
  if (action == GLFW_PRESS) {
    if (ImGui::GetIO().WantCaptureMouse || !layout().in_view(last_cursor_)) return;
    drag_ = button == GLFW_MOUSE_BUTTON_LEFT ? DragButton::left : DragButton::right;
    press_at_ = last_cursor_;
    dragged_ = false;
  } else if (drag_ != DragButton::none) {
    if (drag_ == DragButton::left && !dragged_) click(press_at_);
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
  if (ImGui::GetIO().WantCaptureMouse || !layout().in_view(last_cursor_)) return;
  if (!state_.free_camera) to_scene_camera();
  state_.free_camera = true;
  orbit_.zoom(steps);
}

void Viewer::move_camera(DragButton button, glm::vec2 delta) {
  if (!state_.free_camera) to_scene_camera();  // start from what is on screen
  state_.free_camera = true;
  if (button == DragButton::left) orbit_.orbit(delta.x, delta.y);
  else orbit_.pan(delta.x, delta.y, layout().window.y);
}

// Arrows and PageUp / PageDown fly at half the scene's size per second (Shift: four times that).
void Viewer::fly(float seconds) {
  if (ImGui::GetIO().WantTextInput) return;
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

void Viewer::click(glm::vec2 p) {
  const Layout l = layout();
  if (!l.in_view(p) || l.view_pixels.x <= 0 || l.view_pixels.y <= 0) return;
  const glm::ivec2 pixel = l.pixel_of(p);
  if (state_.model == Model::whitted || state_.model == Model::hybrid) {
    pick_ray_tree(l, pixel);
    return;
  }
  const Camera camera = current_camera();
  pick_ = picker_->pick(camera, l.view_pixels.x, l.view_pixels.y, pixel.x, pixel.y);
  picked_with_ = camera;
  picked_size_ = l.view_pixels;
  if (pick_) {
    state_.selected_material = state_.scene->meshes[size_t(pick_->mesh)].material;
    state_.show_inspector = true;
  } else {
    reading_.reset();
    state_.radiosity.patch.reset();
    state_.note = fmt::format("pixel ({}, {}): background", pixel.x, pixel.y);
  }
}

// Slide 24: the clicked pixel's ray tree, traced here on the GL thread (a few dozen rays), listed
// in the panel and drawn over the picture until another click, X, or a new scene.
void Viewer::pick_ray_tree(const Layout& l, glm::ivec2 pixel) {
  pick_.reset();  // the local model's inspector is not Whitted's
  reading_.reset();
  if (!whitted_) whitted_ = std::make_unique<WhittedView>(*state_.scene);
  const Camera camera = current_camera();
  if (whitted_->showing() && whitted_->fingerprint() != view_fingerprint(camera, l.view_pixels))
    whitted_->cancel();  // an edit not seen yet by the frame: the trace must not read the old scene
  if (state_.model == Model::hybrid && !refresh_diffuse()) {
    state_.note = "hybrid: no radiosity solution yet to trace with";
    return;
  }
  rt::RayTree tree = whitted_->trace_pixel(*state_.scene, camera, l.view_pixels.x, l.view_pixels.y, pixel.x,
                                           pixel.y, tracer_options());
  if (!tree_drawing_) tree_drawing_ = std::make_unique<RayTreeDrawing>();
  tree_drawing_->set(tree, *state_.scene);
  if (!tree.nodes.empty() && tree.nodes[0].hit)
    for (size_t m = 0; m < state_.scene->meshes.size(); ++m)
      if (state_.scene->meshes[m].name == tree.nodes[0].mesh) state_.selected_material = state_.scene->meshes[m].material;
  state_.note = fmt::format("ray tree of pixel ({}, {}): {} rays", pixel.x, pixel.y, tree.nodes.size());
  state_.ray_tree = std::move(tree);
}

// ---- [actions] ---------------------------------------------------------------------------------
void Viewer::set_model(Model model) {
  const ModelInfo& m = info(model);
  if (!m.available) {
    state_.note = fmt::format("{} (key {}): not available yet", m.label, int(model) + 1);
    return;
  }
  state_.model = model;
  if (model == Model::flat) state_.local.shading = Shading::flat;
  if (model == Model::gouraud) state_.local.shading = Shading::gouraud;
  if (model == Model::phong) state_.local.shading = Shading::phong;
  state_.note = m.label;
}

void Viewer::apply(Action action) {
  LocalOptions& o = state_.local;
  auto toggle = [this](bool& term, const char* name) {
    term = !term;
    state_.note = fmt::format("{} {}", name, term ? "on" : "off");
  };
  switch (action) {
    case Action::none: break;
    case Action::model_1: set_model(Model::flat); break;
    case Action::model_2: set_model(Model::gouraud); break;
    case Action::model_3: set_model(Model::phong); break;
    case Action::model_4: set_model(Model::whitted); break;
    case Action::model_5: set_model(Model::radiosity); break;
    case Action::model_6: set_model(Model::hybrid); break;
    case Action::toggle_ambient: toggle(o.ambient, "ambient I_A"); break;
    case Action::toggle_diffuse: toggle(o.diffuse, "diffuse I_D"); break;
    case Action::toggle_specular: toggle(o.specular, "specular I_S"); break;
    case Action::toggle_emission: toggle(o.emission, "emission Le"); break;
    case Action::toggle_textures: toggle(o.textures, "kd texture"); break;
    case Action::toggle_blinn:
      o.blinn = !o.blinn;
      state_.note = o.blinn ? "Blinn's N.H" : "Phong's R.V";
      break;
    case Action::cycle_attenuation: {
      std::vector<Light>& lights = state_.scene->lights;
      const bool all_classroom = std::all_of(lights.begin(), lights.end(),
                                             [](const Light& l) { return l.attenuation.classroom; });
      for (Light& light : lights) light.attenuation.classroom = !all_classroom;
      state_.note = all_classroom ? "f_att = 1/d^2" : "f_att = 1/(c0 + c1 d + c2 d^2)";
      break;
    }
    case Action::cycle_fog:
      o.fog.mode = o.fog.mode == FogMode::off      ? FogMode::linear
                   : o.fog.mode == FogMode::linear ? FogMode::exponential
                                                   : FogMode::off;
      state_.note = fmt::format("fog {}", to_string(o.fog.mode));
      break;
    case Action::toggle_shadows: toggle(o.shadows.on, "shadows S_i"); break;
    case Action::toggle_transparency: toggle(o.transparency.on, "transparency kt"); break;
    case Action::toggle_reflection_map: toggle(o.reflection.on, "reflection map kr Ir"); break;
    case Action::exposure_up: state_.exposure += 0.5f; break;
    case Action::exposure_down: state_.exposure -= 0.5f; break;
    case Action::scene_camera: to_scene_camera(); break;
    case Action::next_camera:
      state_.scene_camera = (state_.scene_camera + 1) % int(state_.scene->cameras.size());
      to_scene_camera();
      state_.note = fmt::format("camera {}", state_.scene->cameras[size_t(state_.scene_camera)].name);
      break;
    case Action::reload: load(state_.scene_path); break;
    case Action::screenshot:
    case Action::screenshot_with_panel: {
      const bool with_panel = action == Action::screenshot_with_panel;
      screenshots_.push_back({next_screenshot_name(state_.scene_path, with_panel), with_panel, ""});
      break;
    }
    case Action::toggle_panel: state_.show_panel = !state_.show_panel; break;
    case Action::toggle_inspector: state_.show_inspector = !state_.show_inspector; break;
    case Action::help: state_.show_help = !state_.show_help; break;
    case Action::trace_view:  // Whitted's trace, or the hybrid's when it is shown
      if (state_.model != Model::whitted && state_.model != Model::hybrid) set_model(Model::whitted);
      state_.trace_requested = true;
      break;
    case Action::cancel_trace: state_.cancel_trace_requested = true; break;
    case Action::clear_ray_tree: state_.clear_ray_tree_requested = true; break;
    // Radiosity: running and stepping show model 5 (as Enter shows Whitted's); the switches only
    // change what it will display.
    case Action::radiosity_run:
      if (state_.model != Model::radiosity) set_model(Model::radiosity);
      state_.radiosity.drive.running = !state_.radiosity.drive.running;
      state_.note = state_.radiosity.drive.running ? "radiosity: running" : "radiosity: paused";
      break;
    case Action::radiosity_step:
      if (state_.model != Model::radiosity) set_model(Model::radiosity);
      state_.radiosity.drive.running = false;
      state_.radiosity.steps += 1;
      break;
    case Action::radiosity_reset:
      state_.radiosity.reset = true;
      state_.note = "radiosity: reset (step 1: unshot = E)";
      break;
    case Action::toggle_heat_map: toggle(state_.radiosity.drive.heat_map, "radiosity heat map"); break;
    case Action::toggle_patches: {
      RadiosityOptions& r = state_.radiosity.options;
      r.flat_patches = r.outlines = !(r.flat_patches && r.outlines);
      state_.note = r.outlines ? "radiosity: flat patches, outlined" : "radiosity: Gouraud";
      break;
    }
    case Action::toggle_ambient_estimate:
      toggle(state_.radiosity.options.ambient_estimate, "radiosity ambient estimate");
      break;
    case Action::toggle_solvers: state_.solvers.open = !state_.solvers.open; break;
    case Action::quit: quit_ = true; break;
  }
}

// ---- [script] ----------------------------------------------------------------------------------
bool Viewer::run(const ScriptCommand& c, std::string& error) {
  const auto& a = c.args;
  if (c.verb == "key") {
    int key = 0, mods = 0;
    parse_key(a[0], key, mods);
    on_key(key, mods);
  } else if (c.verb == "click") {
    const glm::vec2 p(std::stof(a[0]), std::stof(a[1]));
    if (layout().in_view(p)) {
      click(p);
    } else {  // the panel: ImGui sees a press this frame and the release on the next
      scripted_click_at_ = p;
      scripted_click_frames_ = 2;
    }
  } else if (c.verb == "drag") {
    const glm::vec2 from(std::stof(a[0]), std::stof(a[1])), to(std::stof(a[2]), std::stof(a[3]));
    move_camera(a.size() == 5 && a[4] == "right" ? DragButton::right : DragButton::left, to - from);
  } else if (c.verb == "scroll") {
    if (!state_.free_camera) to_scene_camera();
    state_.free_camera = true;
    orbit_.zoom(std::stof(a[0]));
  } else if (c.verb == "screenshot") {
    screenshots_.push_back({a[0], a.size() == 2, fmt::format("{}:{}", c.line, a[0])});
  } else if (c.verb == "camera") {
    const int index = state_.scene->find_camera(a[0]);
    if (index < 0) {
      error = fmt::format("the scene has no camera \"{}\"", a[0]);
      return false;
    }
    state_.scene_camera = index;
    to_scene_camera();
  } else if (c.verb == "model") {
    for (const ModelInfo& m : models())
      if (a[0] == m.name) set_model(m.model);
  } else if (c.verb == "trace") {  // as Enter; without --no-wait the script waits for the end
    apply(Action::trace_view);
    waiting_for_trace_ = a.empty();
  } else if (c.verb == "wait-trace") {
    waiting_for_trace_ = true;
  } else if (c.verb == "dump-ray-tree") {
    if (!state_.ray_tree) {
      error = "there is no ray tree: click a pixel in the Whitted model first";
      return false;
    }
    std::ofstream out(a[0]);
    out << state_.ray_tree->to_json() << '\n';
    if (!out) {
      error = fmt::format("{}: cannot write the ray tree", a[0]);
      return false;
    }
  } else if (c.verb == "radiosity" || c.verb == "wait-shots" || c.verb == "dump-patch" ||
             c.verb == "dump-radiosity") {
    return run_radiosity(c, error);
  } else if (c.verb == "solvers") {
    SolversState& s = state_.solvers;
    if (a[0] == "open") s.open = true;
    if (a[0] == "close") s.open = false;
    if (a[0] == "run") s.open = s.running = true;
    if (a[0] == "pause") s.running = false;
    if (a[0] == "reset") s.reset = true;
    if (a[0] == "budget") s.budget_ms = std::stof(a[1]);
    if (a[0] == "patches") {
      s.target_patches = std::stoi(a[1]);
      s.reset = true;
    }
  } else if (c.verb == "wait-solver-rows") {
    state_.solvers.open = true;
    state_.solvers.run_to_rows = size_t(std::stoul(a[0]));
  } else if (c.verb == "dump-solvers") {
    std::ofstream out(a[0]);
    out << to_json(state_.solvers, solvers_.get()).dump(2) << '\n';
    if (!out) {
      error = fmt::format("{}: cannot write the solvers' curves", a[0]);
      return false;
    }
  } else if (c.verb == "dump-trace") {
    const TraceProgress& t = state_.trace;
    nlohmann::json j;
    j["phase"] = t.phase == TracePhase::raster ? "raster" : t.phase == TracePhase::tracing ? "tracing" : "done";
    j["cancelled"] = t.cancelled;
    j["tiles"] = {t.done, t.total};
    j["seconds"] = t.seconds;
    for (int k = 0; k < rt::kRayKinds; ++k) j["rays"][rt::to_string(rt::RayKind(k))] = t.counters.rays[size_t(k)];
    j["intersection_tests"] = t.counters.intersection_tests;
    std::ofstream out(a[0]);
    out << j.dump(2) << '\n';
    if (!out) {
      error = fmt::format("{}: cannot write the trace's state", a[0]);
      return false;
    }
  } else if (c.verb == "set") {
    LocalOptions& o = state_.local;
    rt::WhittedOptions& w = state_.whitted;
    if (a[0] == "exposure") {
      state_.exposure = std::stof(a[1]);
    } else if (a[0] == "depth") {
      w.max_depth = std::stoi(a[1]);
    } else if (a[0] == "spp") {
      w.spp = std::stoi(a[1]);
    } else if (a[0] == "light-samples") {
      w.light_samples = std::stoi(a[1]);
    } else if (a[0] == "fresnel" || a[0] == "adaptive" || a[0] == "brute-force" || a[0] == "shadow-rays") {
      const bool on = a[1] == "on";
      if (a[0] == "fresnel") w.fresnel = on;
      if (a[0] == "adaptive") w.sampling = on ? rt::Sampling::adaptive : rt::Sampling::stratified;
      if (a[0] == "brute-force") w.brute_force = on;
      if (a[0] == "shadow-rays") w.shadows = on;
    } else if (a[0] == "fog") {
      o.fog.mode = a[1] == "linear" ? FogMode::linear : a[1] == "exponential" ? FogMode::exponential : FogMode::off;
    } else {
      bool* flags[] = {&o.ambient, &o.diffuse, &o.specular, &o.emission, &o.textures, &o.blinn,
                       &state_.show_panel, &state_.show_inspector, &o.shadows.on, &o.transparency.on,
                       &o.reflection.on};
      const char* names[] = {"ambient", "diffuse", "specular", "emission", "textures", "blinn", "panel", "inspector",
                             "shadows", "transparency", "reflection-map"};
      for (size_t i = 0; i < std::size(names); ++i)
        if (a[0] == names[i]) *flags[i] = a[1] == "on";
    }
  } else if (c.verb == "resize") {
    glfwSetWindowSize(window_.handle(), std::stoi(a[0]), std::stoi(a[1]));
  } else if (c.verb == "load") {
    load(a[0]);
  } else if (c.verb == "reload") {
    load(state_.scene_path);
  } else if (c.verb == "dump-inspector") {
    if (!reading_) {
      error = "the inspector shows nothing: click an object in the picture first";
      return false;
    }
    std::ofstream out(a[0]);
    out << to_json(*state_.scene, *reading_).dump(2) << '\n';
    if (!out) {
      error = fmt::format("{}: cannot write the inspector's values", a[0]);
      return false;
    }
  } else if (c.verb == "quit") {
    quit_ = true;
  }
  return true;
}

// ---- [the frame] -------------------------------------------------------------------------------
void Viewer::draw_picture(const Layout& l) {
  const glm::ivec2 size = l.view_pixels;
  if (size.x <= 0 || size.y <= 0) return;
  if (!picture_ || picture_->width() != size.x || picture_->height() != size.y)
    picture_ = std::make_unique<gl::Framebuffer>(size.x, size.y);
  const Camera camera = current_camera();
  if (state_.model == Model::whitted || state_.model == Model::hybrid) {
    show_traced(l, camera);
  } else {
    if (whitted_) whitted_->cancel();  // another model was chosen (key or panel)
    if (state_.model == Model::radiosity) {
      show_radiosity(l, camera);
    } else {
      picture_->bind();
      renderer_->draw(camera, size.x, size.y, state_.local);
    }
    update_inspector(l, camera);
  }

  // The display pass: radiance -> exposure -> sRGB, pixel for pixel into the window.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(l.view_gl_origin.x, l.view_gl_origin.y, size.x, size.y);
  glDisable(GL_DEPTH_TEST);
  display_.use();
  display_.set("u_radiance", 0);
  display_.set("u_scale", std::exp2(state_.exposure));
  display_.set("u_origin", glm::vec2(l.view_gl_origin));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, picture_->colour_texture());
  glBindVertexArray(empty_vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
}

rt::WhittedOptions Viewer::tracer_options() const {
  const rt::WhittedOptions whitted = app::tracer_options(state_.whitted, state_.local);
  if (state_.model == Model::hybrid && diffuse_) return hybrid::hybrid_options(whitted, *diffuse_);
  return whitted;
}

Fingerprint Viewer::view_fingerprint(const Camera& camera, glm::ivec2 size) const {
  return {camera.to_world, camera.yfov, size.x, size.y, tracer_options(), editable_values(*state_.scene)};
}

// Whitted's and the hybrid's picture: the untraced view (Whitted: the raster Phong view; the
// hybrid: the radiosity picture) until a trace is asked for; then the traced tiles over it as
// they come; back to the untraced view when anything the trace depends on changes. The ray tree
// is drawn over either.
void Viewer::show_traced(const Layout& l, const Camera& camera) {
  const glm::ivec2 size = l.view_pixels;
  const bool hybrid = state_.model == Model::hybrid;
  if (state_.cancel_trace_requested) {
    state_.cancel_trace_requested = false;
    if (whitted_ && whitted_->cancel()) state_.note = "trace cancelled: back to the untraced view";
  }
  if (state_.clear_ray_tree_requested) {
    state_.clear_ray_tree_requested = false;
    state_.ray_tree.reset();
    if (tree_drawing_) tree_drawing_->clear();
  }
  if (state_.trace_requested && whitted_) whitted_->cancel();  // a fresh untraced picture under the new trace
  // A remesh replaces the mesh a hybrid trace reads (done by show_radiosity below).
  if (hybrid && state_.radiosity.remesh && whitted_) whitted_->cancel();
  if (whitted_ && whitted_->showing() &&
      (traced_model_ != state_.model || whitted_->fingerprint() != view_fingerprint(camera, size))) {
    if (whitted_->cancel()) state_.note = "the view changed: trace cancelled, back to the untraced view";
    else state_.note = "the view changed: back to the untraced view (Enter traces it)";
  }

  if (!whitted_ || !whitted_->showing()) draw_untraced(l, camera);
  // The hybrid traces over the viewer's radiosity solution: while the solver is still running to
  // its stopping rule (the first solve, or a run asked for), the trace waits for it.
  const bool solving = hybrid && (!radiosity_ || state_.radiosity.drive.running);
  if (state_.trace_requested && !solving) {
    state_.trace_requested = false;
    if (!whitted_) whitted_ = std::make_unique<WhittedView>(*state_.scene);
    if (!hybrid || refresh_diffuse()) {
      whitted_->start(*state_.scene, camera, size.x, size.y, tracer_options(), *picture_);
      traced_model_ = state_.model;
      state_.note = fmt::format("tracing {}x{}", size.x, size.y);
    }
  }
  if (whitted_ && whitted_->showing()) {
    const TracePhase before = whitted_->phase();
    whitted_->update();
    if (before == TracePhase::tracing && whitted_->phase() == TracePhase::done)
      state_.note = fmt::format("traced in {:.2f} s", whitted_->seconds());
    // The traced picture's colour over the picture; its depth stays the untraced one's of this
    // very view (the trace is cancelled when the view changes), which the ray tree is tested against.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, whitted_->picture().id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, picture_->id());
    glBlitFramebuffer(0, 0, size.x, size.y, 0, 0, size.x, size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    picture_->bind();
  }
  if (state_.ray_tree && tree_drawing_)
    tree_drawing_->draw(camera, size.x, size.y, picture_far_plane(camera, *state_.scene), std::exp2(state_.exposure),
                        l.scale.y);

  TraceProgress& t = state_.trace;
  if (whitted_) {
    t.phase = whitted_->phase();
    t.cancelled = whitted_->cancelled();
    t.done = whitted_->tiles_done();
    t.total = whitted_->tiles_total();
    t.seconds = whitted_->seconds();
    t.counters = whitted_->counters();
  } else {
    t = TraceProgress{};
  }
}

// What a trace starts from and what shows until then.
void Viewer::draw_untraced(const Layout& l, const Camera& camera) {
  if (state_.model == Model::whitted) {
    // The local model with the lecture's Phong shading, whatever flat / Gouraud was last used.
    LocalOptions raster = state_.local;
    raster.shading = Shading::phong;
    picture_->bind();
    renderer_->draw(camera, l.view_pixels.x, l.view_pixels.y, raster);
    return;
  }
  // The hybrid: the radiosity picture, stepping as in model 5 (the first time, meshed and run
  // to the stopping rule: "computed first when there is none"). It shows B/pi as the trace will
  // read it, so model 5's heat map and shooter highlight are left out here.
  const bool first = !radiosity_;
  RadiosityDrive& drive = state_.radiosity.drive;
  const bool heat_map = drive.heat_map, shooter = drive.show_shooter;
  drive.heat_map = drive.show_shooter = false;
  show_radiosity(l, camera);
  drive.heat_map = heat_map;
  drive.show_shooter = shooter;
  if (first && radiosity_ && !radiosity_->solver().done()) drive.running = true;
}

// The hybrid's diffuse part takes the viewer's radiosity solution as it is now. Only while no
// trace runs (a running one reads it); false when there is no solution to take.
bool Viewer::refresh_diffuse() {
  if (!radiosity_) return false;
  if (whitted_ && whitted_->phase() == TracePhase::tracing) return diffuse_ != nullptr;
  if (diffuse_) diffuse_->update(RadianceField::of(radiosity_->solver()));
  else diffuse_ = std::make_unique<hybrid::RadiosityDiffuse>(radiosity_->mesh(), RadianceField::of(radiosity_->solver()));
  return true;
}

// The radiosity solution goes (a remesh, an edited Le): first the hybrid trace that reads it.
void Viewer::drop_radiosity() {
  if (whitted_ && traced_model_ == Model::hybrid) whitted_->cancel();
  diffuse_.reset();
  radiosity_.reset();
}

// Radiosity: the solver steps here, on the GL thread, within the frame's budget; the picture is
// the solution so far (vertex colours uploaded after the shots), the shooter highlighted.
void Viewer::show_radiosity(const Layout& l, const Camera& camera) {
  RadiosityState& r = state_.radiosity;
  if (!radiosity_ || r.remesh) {
    r.remesh = false;
    drop_radiosity();  // the old solver's GL objects go before the new ones are made
    r.status = RadiosityStatus{};
    r.patch.reset();
    try {
      radiosity_ = std::make_unique<RadiosityView>(*state_.scene, r.options);
      state_.note = fmt::format("radiosity: {} patches, hemicube {}", radiosity_->mesh().size(), r.options.hemicube_res);
    } catch (const Error& error) {
      state_.note = error.what();
      fmt::print(stderr, "luz: {}\n", error.what());
      r.drive.running = false;
      r.steps = r.stop_at = 0;
      picture_->bind();
      const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
      glClearBufferfv(GL_COLOR, 0, black);
      return;
    }
  }
  const bool was_running = r.drive.running;
  radiosity_->advance(r, state_.exposure);
  if (was_running && !r.drive.running && r.status.done)
    state_.note = fmt::format("radiosity: done after {} shots, {:.2f} % unshot", r.status.shots,
                              100.0 * r.status.unshot_fraction);
  picture_->bind();
  radiosity_->draw(camera, l.view_pixels.x, l.view_pixels.y, r);
}

bool Viewer::run_radiosity(const ScriptCommand& c, std::string& error) {
  const auto& a = c.args;
  RadiosityState& r = state_.radiosity;
  if (c.verb == "wait-shots") {
    if (state_.model != Model::radiosity && state_.model != Model::hybrid) {
      error = "`wait-shots` runs the radiosity solver: choose it first (`model radiosity` or `model hybrid`)";
      return false;
    }
    r.stop_at = std::stoi(a[0]);
    r.drive.running = true;
  } else if (c.verb == "dump-patch" || c.verb == "dump-radiosity") {
    if (c.verb == "dump-patch" && !r.patch) {
      error = "no patch is inspected: click a surface in the radiosity model first";
      return false;
    }
    std::ofstream out(a[0]);
    out << (c.verb == "dump-patch" ? to_json(*r.patch) : to_json(r)).dump(2) << '\n';
    if (!out) {
      error = fmt::format("{}: cannot write the radiosity values", a[0]);
      return false;
    }
  } else if (a[0] == "run") {
    r.drive.running = true;
  } else if (a[0] == "pause") {
    r.drive.running = false;
  } else if (a[0] == "reset") {
    r.reset = true;
  } else if (a[0] == "step") {
    r.drive.running = false;
    r.steps += std::stoi(a[1]);
  } else if (a[0] == "patch-size") {
    r.options.patch_size = std::stof(a[1]);
    r.remesh = true;
  } else if (a[0] == "hemicube") {
    r.options.hemicube_res = std::stoi(a[1]);
    r.remesh = true;
  } else if (a[0] == "budget") {
    r.drive.by_time = true;
    r.drive.budget_ms = std::stof(a[1]);
  } else {
    const bool on = a[1] == "on";
    if (a[0] == "heat-map") r.drive.heat_map = on;
    if (a[0] == "outlines") r.options.outlines = on;
    if (a[0] == "flat-patches") r.options.flat_patches = on;
    if (a[0] == "ambient-estimate") r.options.ambient_estimate = on;
    if (a[0] == "shooter") r.drive.show_shooter = on;
    if (a[0] == "item-buffer") r.drive.show_item_buffer = on;
    if (a[0] == "rotation") r.options.random_rotation = on;
  }
  return true;
}

// The patch inspector at the bottom of the picture, on the side away from the clicked point, and
// the shooter's hemicube in the top-right corner.
void Viewer::draw_radiosity_windows(const Layout& l) {
  const float margin = 8.0f * ui_scale_;
  if (pick_ && state_.radiosity.patch && state_.show_inspector) {
    const glm::vec2 at = l.window_of(glm::ivec2(pick_->x, pick_->y));
    const bool right = at.x > 0.5f * (l.view_origin.x + l.window.x);
    ImGui::SetNextWindowPos(ImVec2(right ? l.view_origin.x + margin : l.window.x - margin, l.window.y - l.status - margin),
                            ImGuiCond_Always, ImVec2(right ? 0.0f : 1.0f, 1.0f));
    draw_patch_inspector(*state_.scene, *state_.radiosity.patch, state_.show_inspector);
    const float r = 7.0f * ui_scale_;
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    draw->AddLine(ImVec2(at.x - r, at.y), ImVec2(at.x + r, at.y), IM_COL32(255, 60, 200, 255), 2.0f);
    draw->AddLine(ImVec2(at.x, at.y - r), ImVec2(at.x, at.y + r), IM_COL32(255, 60, 200, 255), 2.0f);
  }
  draw_item_buffer_window(state_, l.window.x - margin, margin, 200.0f * ui_scale_);
}

void Viewer::update_inspector(const Layout& l, const Camera& camera) {
  if (!pick_) return;
  // The camera or the picture's size changed: the clicked pixel now shows another point.
  if (picked_size_ != l.view_pixels || picked_with_.to_world != camera.to_world) {
    const glm::ivec2 pixel = glm::min(glm::ivec2(pick_->x, pick_->y), l.view_pixels - 1);
    pick_ = picker_->pick(camera, l.view_pixels.x, l.view_pixels.y, pixel.x, pixel.y);
    picked_with_ = camera;
    picked_size_ = l.view_pixels;
    picture_->bind();
    if (!pick_) {
      reading_.reset();
      state_.radiosity.patch.reset();
      return;
    }
  }
  if (state_.model == Model::radiosity) {  // the patch's values, live as the shots go on
    reading_.reset();
    if (radiosity_) state_.radiosity.patch = radiosity_->read(*pick_);
    return;
  }
  // The shadow maps and the reflection map the picture was drawn with, read texel by texel.
  const std::optional<ShadowLookup> shadows = renderer_->shadow_lookup();
  DrawnLookups lookups;
  lookups.shadows = shadows ? &*shadows : nullptr;
  lookups.reflection = renderer_->reflection_lookup(pick_->mesh);
  reading_ = read_terms(*state_.scene, renderer_->area_lights(), *pick_, state_.local, lookups);
  float rgba[4] = {};
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(pick_->x, l.view_pixels.y - 1 - pick_->y, 1, 1, GL_RGBA, GL_FLOAT, rgba);
  reading_->gl_pixel = Rgb(rgba[0], rgba[1], rgba[2]);
}

void Viewer::take_screenshots(const Layout& l) {
  for (const PendingScreenshot& shot : screenshots_) {
    try {
      if (shot.with_panel) save_window(l.framebuffer.x, l.framebuffer.y, shot.path);
      else if (picture_) save_picture(*picture_, shot.path, state_.exposure);
      state_.note = fmt::format("saved {}", shot.path.string());
      fmt::print("{}\n", state_.note);
    } catch (const Error& error) {
      state_.note = error.what();
      if (!shot.origin.empty() && failure_.empty()) failure_ = error.what();
      fmt::print(stderr, "luz: {}\n", error.what());
    }
  }
  screenshots_.clear();
}

void Viewer::frame() {
  // Requests the panel made during the last frame.
  if (state_.emitters_changed) {
    state_.emitters_changed = false;
    state_.scene->find_area_lights();
    rebuild_renderer();
    drop_radiosity();  // the patches' E come from the scene's Le when meshed
  }
  if (state_.reload) {
    state_.reload = false;
    load(state_.scene_path);
  }
  if (state_.back_to_scene_camera) {
    state_.back_to_scene_camera = false;
    to_scene_camera();
  }
  // Slide 36's solvers step here, on the GL thread, within their own budget per frame.
  const SolversState& s = state_.solvers;
  if (s.open || s.run_to_rows > 0 || s.reset) {
    if (!solvers_) solvers_ = std::make_unique<SolversView>(*state_.scene);
    solvers_->advance(state_.solvers);
  }

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  if (scripted_click_frames_ > 0) {  // a script's click on the panel
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(scripted_click_at_.x, scripted_click_at_.y);
    io.MouseDown[0] = scripted_click_frames_-- == 2;
  }
  ImGui::NewFrame();
  const Layout l = layout();
  if (state_.show_panel) draw_panel(state_, l.panel, l.window.y - l.status);
  draw_windows(l);
  ImGui::Render();

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, l.framebuffer.x, l.framebuffer.y);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.06f, 0.06f, 0.07f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  draw_picture(l);
  glViewport(0, 0, l.framebuffer.x, l.framebuffer.y);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  take_screenshots(l);
  window_.swap();
}

int Viewer::loop() {
  auto last = std::chrono::steady_clock::now();
  while (!window_.should_close() && !quit_) {
    window_.poll();
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last).count();
    last = now;
    state_.frame_ms = 0.9 * state_.frame_ms + 0.1 * 1000.0 * seconds;  // smoothed for reading
    if (script_) {
      std::string error;
      if (!script_->step(*this, error)) {
        fmt::print(stderr, "luz: {}\n", error);
        return 1;
      }
    }
    fly(float(std::min(seconds, 0.1)));
    frame();
    if (!failure_.empty()) return 1;
  }
  return 0;
}

// ---- [the windows over the picture] --------------------------------------------------------------
void Viewer::draw_windows(const Layout& l) {
  const Scene& scene = *state_.scene;

  draw_status_line(state_, l.window.y - l.status, l.window.x, l.status);
  const float view_middle = l.view_origin.x + 0.5f * (l.window.x - l.view_origin.x);

  if (pick_ && reading_ && state_.show_inspector) {
    // In the corner of the picture farthest from the inspected pixel, so both stay in view.
    const glm::vec2 at = l.window_of(glm::ivec2(pick_->x, pick_->y));
    const float margin = 8.0f * ui_scale_;
    const bool right = at.x > 0.5f * (l.view_origin.x + l.window.x), low = at.y > 0.5f * (l.window.y - l.status);
    ImGui::SetNextWindowPos(ImVec2(right ? l.view_origin.x + margin : l.window.x - margin,
                                   low ? margin : l.window.y - l.status - margin),
                            ImGuiCond_Always, ImVec2(right ? 0.0f : 1.0f, low ? 0.0f : 1.0f));
    draw_inspector(scene, *reading_, state_.show_inspector);
    // A cross on the inspected pixel (drawn over the picture, never into it).
    const float r = 7.0f * ui_scale_;
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    draw->AddLine(ImVec2(at.x - r, at.y), ImVec2(at.x + r, at.y), IM_COL32(255, 60, 200, 255), 2.0f);
    draw->AddLine(ImVec2(at.x, at.y - r), ImVec2(at.x, at.y + r), IM_COL32(255, 60, 200, 255), 2.0f);
  }

  draw_trace_hint(state_, view_middle, 8.0f * ui_scale_);
  if (state_.model == Model::radiosity) draw_radiosity_windows(l);
  state_.solvers.status.plot_min = state_.solvers.status.plot_max = glm::vec2(0.0f);
  if (state_.solvers.open && solvers_)
    solvers_->draw(state_.solvers, l.view_origin.x + 8.0f * ui_scale_, 8.0f * ui_scale_,
                   0.62f * (l.window.x - l.view_origin.x), l.window.y - l.status - 16.0f * ui_scale_);
  if (state_.show_help) draw_help(state_.show_help, view_middle, 0.45f * l.window.y);
  if (!state_.error.empty()) draw_load_error(state_, view_middle, 0.5f * l.window.y, l.window.x - l.view_origin.x);
}

}  // namespace

// ---- [run_viewer] ------------------------------------------------------------------------------
int run_viewer(const ViewerSettings& settings) {
  try {
    io::LoadedScene loaded = io::load_gltf(settings.scene);
    Viewer viewer(std::move(loaded), settings.scene, settings);
    return viewer.loop();
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return 1;
  }
}

}  // namespace luz::app
