#pragma once
// One illumination model in the viewer, behind one interface: the Viewer keeps the window, the
// input, the layout and the dispatch; a ModelView keeps what its model needs (a solver, a trace,
// a renderer) and draws into whatever rectangle of the window it is given, so that two views can
// share the window side by side.
//
// The frame, for the view that is shown:
//   advance()  its work of this frame (shots within a budget, finished tiles uploaded);
//   draw()     its picture's radiance into the picture framebuffer (the viewport's pixels), or
//              draw_into_window() what the window shows, when nothing needs the radiance;
//   windows()  its windows over the picture (inspector, hints), inside the viewport;
//   panel()    its section of the panel, under the model's radio buttons.
// The registry (model_registry.h) makes one view per model the first time it is shown.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/common.hpp>
#include <nlohmann/json_fwd.hpp>
#include <glm/vec2.hpp>

#include "app/viewer/picking.h"
#include "app/script/script.h"
#include "app/script/key_binding.h"
#include "app/viewer/viewer_state.h"
#include "core/camera.h"
#include "core/image.h"
#include "gl/framebuffer.h"

namespace luz {
class LocalRenderer;
}

namespace luz::app {

// A rectangle of the window a view draws into. Window coordinates (GLFW's, ImGui's, the
// script's) have their origin at the top left; on a HiDPI screen a window unit can be several
// framebuffer pixels.
struct Viewport {
  glm::vec2 origin{0.0f};     // top-left corner, window units
  glm::vec2 size{0.0f};       // window units
  glm::vec2 scale{1.0f};      // framebuffer pixels per window unit
  glm::ivec2 pixels{0};       // its size in framebuffer pixels
  glm::ivec2 gl_origin{0};    // its lower-left corner in GL's window pixels

  bool contains(glm::vec2 p) const {
    return p.x >= origin.x && p.y >= origin.y && p.x < origin.x + size.x && p.y < origin.y + size.y;
  }
  glm::ivec2 pixel_of(glm::vec2 p) const {  // row 0 at the top of the picture
    return glm::ivec2(glm::floor((p - origin) * scale));
  }
  glm::vec2 window_of(glm::ivec2 pixel) const { return origin + (glm::vec2(pixel) + 0.5f) / scale; }
  glm::vec2 centre() const { return origin + 0.5f * size; }
  bool empty() const { return pixels.x <= 0 || pixels.y <= 0; }
};

// The clicked surface point the inspectors read, shared by the models that inspect a surface
// (the local models, radiosity), so that switching between them keeps the point.
struct Inspection {
  std::optional<Pick> pick;
  Camera picked_with;          // the view the pick was made in: moving the camera re-picks
  glm::ivec2 picked_size{0};
};

class ModelView;
class DifferenceView;     // difference_window.h
struct ModelEntry;        // common/model_registry.h
struct InspectorReading;  // inspector.h

// A reference model's picture (the path tracer's), which the difference view compares against.
struct PathPicture {
  Image mean;
  int spp = 0;
  // Mean over the lit pixels of Y(standard error) / Y(mean), Y the luminance (relative_noise).
  double noise = 0.0;
  double seconds = 0.0;      // since the film started
  long version = 0;          // one more at every pass published
};

// What a view may use of the viewer: the shared state, the scene's local renderer and picker,
// the inspected point and the other models' views (the hybrid reads radiosity's solution).
class ViewerServices {
public:
  virtual ~ViewerServices() = default;
  virtual ViewerState& state() = 0;
  virtual LocalRenderer& local_renderer() = 0;
  virtual Picker& picker() = 0;
  virtual Inspection& inspection() = 0;
  virtual ModelView& view(std::string_view model) = 0;  // made when first asked for
  virtual float ui_scale() const = 0;
  // A warning about the scene in this model (a light radiosity cannot shoot): shown in the
  // window with the loader's, and printed.
  virtual void warn(const std::string& warning) = 0;
  // For the models' script verbs: the model shown, showing another, the views of the panes.
  virtual const ModelEntry& model() const = 0;
  virtual void set_model(const ModelEntry& model) = 0;
  virtual ModelView& shown() = 0;
  virtual std::vector<ModelView*> pane_views() = 0;  // in order; one pane: the view shown
  // The difference view against the reference (the path model's verbs switch it and wait for it).
  virtual DifferenceView& difference() = 0;
  // A line of the script language, run as a key runs its own (a panel button that does what a
  // key does runs the key's line); what went wrong goes to the status line.
  virtual void run_line(const std::string& line) = 0;
};

// Where a view may put its floating windows without covering the picture's centre or each
// other: the corners of the viewport, handed out one at a time (overlays.h).
class WindowCorners;

class ModelView {
public:
  virtual ~ModelView() = default;

  // The scene was replaced or its emitters edited: everything made from the old one goes (a
  // running trace is cancelled first).
  virtual void scene_changed() {}
  // Another model is shown instead: a running trace stops.
  virtual void hidden() {}

  virtual void advance(const Camera& /*camera*/, const Viewport& /*viewport*/) {}
  // The picture's radiance (and depth) into `picture`, viewport.pixels in size, bound.
  virtual void draw(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) = 0;
  // Whether the last draw() also left what the window shows in the picture's display buffer
  // (gl::Framebuffer::display_texture), so that the window copies it instead of running the
  // display pass over the radiance.
  virtual bool drew_display() const { return false; }
  // What the window shows, drawn straight into the window's rectangle `viewport`
  // (gl::bind_window_for_display) instead of a picture: the viewer asks on the frames that need
  // no radiance (no heat map, no screenshot of the picture). False, having drawn nothing, where
  // the view cannot; then draw() runs.
  // `window_unseen`: nothing of the window outside `viewport` is shown this frame, so the view may
  // clear all of it (LocalRenderer::draw_display's clear_everywhere).
  virtual bool draw_into_window(const Camera& /*camera*/, const Viewport& /*viewport*/, bool /*window_unseen*/) {
    return false;
  }
  // A left click (no drag) on a pixel of the picture.
  virtual void click(const Camera& /*camera*/, const Viewport& /*viewport*/, glm::ivec2 /*pixel*/) {}
  virtual void panel() = 0;
  virtual void windows(const Viewport& /*viewport*/, WindowCorners& /*corners*/) {}
  // The status line's words about this model ("shot 12, 3.2% unshot, running").
  virtual std::string status() const { return {}; }
  // A script command still playing out (a trace the script waits for, shots it asked for).
  virtual bool busy() const { return false; }
  // Something is running (a trace, the solver): the viewer keeps drawing frames for it.
  virtual bool animating() const { return false; }
  // Animating only by work that has nothing to show at once but its progress, on threads of its
  // own (a trace's tiles) or between frames (radiosity's shots): its frames may be paced
  // (ViewerSettings::paced_frames).
  virtual bool paced() const { return false; }
  // A pass whose frame is held for pacing: a paced view's work on the GL thread (radiosity's
  // shots) goes on here, nothing drawn.
  virtual void between_frames() {}
  // Whether the picture holds the scene's light: radiosity's does not before its first shot, when
  // only the emitters show. A scene's exposure is checked against the first picture that does.
  virtual bool shows_the_light() const { return true; }
  // The scene's emitters were edited (the panel's Le): what was made from them goes.
  virtual void emitters_changed() {}
  // Whether a script's `wait-until` condition of this model holds (trace-done, radiosity-done).
  virtual bool holds(std::string_view /*condition*/) const { return false; }
  // What the keys change of this model beyond the settings, into `dump-state`'s `out`.
  virtual void dump_state(nlohmann::json& /*out*/) const {}
  // A traced view's trace: "raster" (not asked for), "tracing" or "done"; nullptr for a view
  // that does not trace.
  virtual const char* trace_state() const { return nullptr; }
  // The inspector's values at the clicked point, where the view inspects (the local models).
  virtual const InspectorReading* inspector_reading() const { return nullptr; }
  // The reference's picture of `camera` at `size` pixels, where this view is a reference model
  // (the path tracer's): nullptr until its first pass of that view.
  virtual const PathPicture* picture_for(const Camera& /*camera*/, glm::ivec2 /*size*/) const { return nullptr; }
};

}  // namespace luz::app
