#pragma once
// The viewer's window: input, layout and dispatch. What is drawn in the picture, what the panel
// shows of a model and what its windows say belong to the model's view (model_view.h); the
// Viewer turns keys, clicks and script lines into actions on the shared ViewerState or on the
// view shown, and each frame lays out the panel, the picture's viewport and the status line.
#include <chrono>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include "app/classroom/classroom.h"
#include "app/common/model_registry.h"
#include "app/viewer/model_view.h"
#include "app/viewer/orbit_camera.h"
#include "app/viewer/panel_cache.h"
#include "app/script/script.h"
#include "app/viewer/shortcuts.h"
#include "app/viewer/difference_window.h"
#include "app/viewer/solvers_window.h"
#include "app/viewer/viewer.h"
#include "app/viewer/viewer_state.h"
#include "gl/framebuffer.h"
#include "gl/shader.h"
#include "gl/window_context.h"
#include "io/gltf_loader.h"
#include "local/local_renderer.h"

namespace luz::app {

enum class DragButton { none, left, right };

struct PendingScreenshot {
  std::filesystem::path path;
  bool with_panel = false;
  bool shown = false;  // the window as the display shows it (the front buffer), panel and all
  std::string origin;  // "demo.txt:12" for a script's, empty for a key's
  bool quiet = false;  // no "saved FILE" on the status line: a picture for a program (the page's luz.picture())
};

// The window's parts, in window units: the panel on the left, the picture's viewport beside it,
// the status line under both.
struct Layout {
  glm::vec2 window{0.0f};
  glm::ivec2 framebuffer{0};
  float panel = 0.0f;    // panel width
  float status = 0.0f;   // status line height
  Viewport view;
  std::vector<Viewport> panes;  // the view split side by side (panes.h); one pane: the view
  // With a lesson open, a column right of the picture for the caption and the picture's windows
  // (WindowCorners docks them there), so that nothing covers what the class looks at, or a row
  // under it for the caption alone (a wide scene, a folded caption); empty without a lesson.
  Viewport dock;
};

class Viewer final : public ScriptTarget, public ViewerServices, public LineQueue {
public:
  Viewer(io::LoadedScene loaded, const std::filesystem::path& path, const ViewerSettings& settings);
  ~Viewer() override;
  // One pass of the frame loop (frame_loop.h): the exit code once Esc, the window or the script
  // ends the run.
  std::optional<int> pass();

  // LineQueue: lines run one after the other, each from the frame after the one before it is done.
  void run_later(const std::string& line, LineDone done) override;

  // ScriptTarget: a command runs through its verb's handler (script.h).
  bool run(const ScriptCommand& command, std::string& error) override;
  bool busy() const override { return busy_with() != nullptr; }
  bool holds(const std::string& condition) override;  // widget_verbs.cpp

  // ViewerServices.
  ViewerState& state() override { return state_; }
  LocalRenderer& local_renderer() override { return *renderer_; }
  Picker& picker() override { return *picker_; }
  Inspection& inspection() override { return inspection_; }
  ModelView& view(std::string_view model) override;
  float ui_scale() const override { return ui_scale_; }
  void warn(const std::string& warning) override;

  // What the script's verbs do (script_verbs.cpp); keys and the mouse do the same.
  void press_key(int key, int mods);
  void typed(unsigned codepoint);
  void click_at(glm::vec2 p);            // the picture, or the panel (ImGui sees press and release)
  void drag(DragButton button, glm::vec2 delta) { move_camera(button, delta); }
  void zoom(float steps);
  void screenshot(PendingScreenshot shot) { screenshots_.push_back(std::move(shot)); }
  bool choose_camera(const std::string& name_or_index, std::string& error);
  // The model shown, in the active pane: its pane becomes the active one, or it takes the active
  // pane's place when no pane shows it (panes.h).
  void set_model(const ModelEntry& model) override;
  // Side by side: 2 to 4 models (a list pane_list_problem accepts); one model: one picture.
  void set_panes(const std::vector<std::string>& models);
  const std::vector<const ModelEntry*>& panes() const { return panes_; }  // one when not side by side
  int active_pane() const { return int(active_pane_); }
  std::vector<ModelView*> pane_views() override;  // the views of the panes, in order
  const Layout& drawn_layout() const { return last_layout_; }
  const Camera& drawn_camera(size_t pane) const { return drawn_cameras_.at(pane); }  // this frame's
  // A key's line (shortcuts.h), run as the script runs it; what went wrong goes to the status line.
  void run_key(const Shortcut& shortcut) { run_line(shortcut.line); }
  void run_line(const std::string& line) override;
  void to_scene_camera();  // back to the scene camera shown (C)
  void next_camera();      // the scene's next camera (N)
  void ask_to_quit();      // Esc: quits, or asks first with a lesson open or work running
  void resize(int width, int height);
  void load(const std::filesystem::path& path);
  void quit() { quit_ = true; }  // the script's `quit`: no question asked
  bool asking_to_quit() const { return asking_to_quit_; }
  void set_ui_scale(float scale);   // the class's factor (--ui-scale), 0.5 .. 4
  float user_scale() const { return user_scale_; }
  // `idle SECONDS`: the script waits while the viewer sits idle, measuring the CPU it uses.
  void idle(double seconds);
  double idle_cpu_fraction() const { return idle_cpu_fraction_; }  // CPU seconds per second
  nlohmann::json windows_json() const;  // the viewport, the dock, the floating windows' rectangles, the tables
  nlohmann::json tables_json() const;   // every table's columns: their text's width and their room
  const ModelEntry& model() const override { return *model_; }
  ModelView& shown() override { return view(model_->name); }
  SolversWindow& solvers() { return solvers_; }
  DifferenceView& difference() override { return difference_; }
  Layout layout() const;
  Classroom& classroom() { return classroom_; }
  // "Tab: panel" while a lesson's panel is hidden since the start (too wide for the window), else null.
  const char* panel_hint() const;
  PanelCache& panel_cache() { return panel_cache_; }
  bool window_keeps_back_buffer() const { return window_.keeps_back_buffer(); }
  int copied_panes() const { return copied_panes_; }  // last frame's panes shown by a copy
  int direct_panes() const { return direct_panes_; }  // ...drawn straight into the window
  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::string& status_line() const { return status_shown_; }  // as the last frame drew it
  unsigned frames_drawn() const { return frame_number_; }

private:
  const char* busy_with() const;
  void adopt(io::LoadedScene loaded, const std::filesystem::path& path, bool keep_view);
  void rebuild_renderer();
  Camera current_camera() const;
  void rebuild_fonts();

  void on_key(int key, int mods);
  void on_char(unsigned codepoint);
  void on_mouse_button(int button, int action);
  void on_cursor(glm::vec2 p);
  void on_scroll(float steps);
  void move_camera(DragButton button, glm::vec2 delta);
  void fly(float seconds);
  bool flying() const;

  void frame();
  using FrameClock = std::chrono::steady_clock;
  double finish_phase(FrameClock::time_point& start) const;
  void smooth(double& ms, double sample) const;
  // `view_alone_shown`: nothing of the window but the view is shown this frame (its panel is kept).
  void draw_picture(const Layout& l, bool view_alone_shown);
  void clear_unpainted(const Layout& l, std::span<const FramebufferRect> panel, bool panel_painted,
                       glm::vec4 colour);
  void draw_windows(const Layout& l);
  void measure_dock(const Viewport& column, float margin);
  Layout with_dock_beside(Layout l, float width) const;
  Layout with_dock_below(Layout l, float height) const;
  bool dock_goes_below(const Layout& beside, const Layout& below) const;
  void draw_quit_question(const Viewport& view);
  const std::string& status_shown(const std::string& text);
  void take_screenshots(const Layout& l);
  void read_exposure(bool check);
  std::vector<const gl::Framebuffer*> pane_pictures() const;
  bool needs_frames() const;
  bool frame_held() const;
  bool working() const;

  gl::WindowContext window_;
  ViewerState state_;
  float ui_scale_ = 1.0f;          // the interface's size: the screen's scale times user_scale_
  float user_scale_ = 1.0f;        // the class's choice
  float content_scale_ = 1.0f;     // the screen's, from GLFW (HiDPI)
  float pixels_per_unit_ = 1.0f;   // framebuffer pixels per window unit when the window opened
  bool fonts_stale_ = false;
  std::unique_ptr<LocalRenderer> renderer_;
  std::unique_ptr<Picker> picker_;
  std::vector<std::unique_ptr<gl::Framebuffer>> pictures_;  // each pane's float radiance
  PanelCache panel_cache_;  // the panel's pixels, drawn again only when it changes
  gl::Program display_{{"display.vert", "display.frag"}, {"srgb.glsl"}};
  bool window_takes_blits_ = !gl::window_is_multisampled();  // panel and displayed values copied, not drawn
  int copied_panes_ = 0;
  int direct_panes_ = 0;
  GLuint empty_vertex_array_ = 0;  // core profile draws need one bound, even with no attributes
  OrbitCamera orbit_;
  Inspection inspection_;

  const ModelEntry* model_ = nullptr;                    // the model shown: panes_[active_pane_]
  std::vector<const ModelEntry*> panes_;                 // side by side, or the one model shown
  size_t active_pane_ = 0;
  std::vector<Camera> drawn_cameras_;                    // what each pane was drawn with
  std::map<std::string, std::unique_ptr<ModelView>, std::less<>> views_;  // made when first shown
  // Slide 36's window: its own mesh, matrix and four solvers, built when first opened.
  SolversWindow solvers_;
  // The shown model against the reference, as a heat map (difference_window.h).
  DifferenceView difference_;

  DragButton drag_ = DragButton::none;
  glm::vec2 press_at_{0.0f}, last_cursor_{0.0f};
  bool dragged_ = false;

  std::optional<ScriptRunner> script_;
  struct QueuedLine {
    ScriptRunner runner;
    LineDone done;
  };
  std::deque<QueuedLine> queued_lines_;  // run_later's
  void step_queued_line();
  bool answer_finished_line();
  Classroom classroom_;            // the lesson, when one is open
  glm::vec2 scripted_click_at_{0.0f};
  int scripted_click_frames_ = 0;  // 2: press this frame, 1: release, 0: none
  std::string failure_;            // a script command that failed: the run ends with exit 1
  std::vector<PendingScreenshot> screenshots_;
  std::function<void(const std::filesystem::path&)> screenshot_saved_;  // ViewerSettings::screenshot_saved
  std::vector<std::string> warnings_;  // the scene's loader and renderer warnings, shown in the window
  bool show_warnings_ = false;
  bool exposure_check_ = false;    // a scene came: its first picture is checked against the exposure
  std::string exposure_warning_;   // what that check found, in warnings_ until the exposure is fitted
  bool quit_ = false;
  bool asking_to_quit_ = false;    // Esc with a lesson open or work running: "Quit Luz?" shown
  unsigned frame_number_ = 0;
  bool timing_phases_ = false;     // this frame times its phases (ViewerState::frame_phases)
  int frames_to_draw_ = 3;         // frames still to draw after an event before waiting again
  bool show_whole_window_ = true;  // the next frame shows every pixel, kept or not (an expose)
  Layout last_layout_;
  float dock_wanted_ = 0.0f;  // the dock's width its windows asked for on the last frame (window units)
  float caption_wanted_ = 0.0f;  // the caption's height with all its text on the last frame (window units)
  int docked_windows_ = 0;       // windows besides the caption docked on the last frame
  bool panel_hint_ = false;      // the panel started hidden for the picture's room; the caption says "Tab: panel" until it is shown

  // Keys and typed characters in the order they came, handed to ImGui up to one key press a
  // frame (the key callback in viewer.cpp says why).
  struct InputEvent {
    bool is_key;
    int key, scancode, action, mods;
    unsigned codepoint;
  };
  std::deque<InputEvent> input_;
  bool typing_in_panel() const;

  std::optional<std::chrono::steady_clock::time_point> idle_until_;
  double idle_cpu_start_ = 0.0, idle_wall_ = 1.0, idle_cpu_fraction_ = -1.0;

  std::string status_shown_;                // the status line's text as it stands
  FrameClock::time_point status_refreshed_;  // when its figures were last brought up to date
  FrameClock::time_point last_pass_ = FrameClock::now();  // the frame loop's last pass
  std::chrono::milliseconds paced_frames_{0};              // ViewerSettings::paced_frames
};

}  // namespace luz::app
