// The path model in the viewer. Sections: [the noise] [the film's worker] [the frame] [panel]
// [script verbs]
#include "app/models/path/path_view.h"

#include <algorithm>

#include <fmt/format.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/common/json_file.h"
#include "app/viewer/difference_window.h"
#include "app/common/i18n.h"
#include "app/common/model_registry.h"
#include "app/common/option_row.h"
#include "app/models/path/path_options.h"
#include "app/viewer/background_render.h"
#include "app/viewer/overlays.h"
#include "core/image_compare.h"
#include "gl/functions.h"
#include "local/local_renderer.h"
#include "raytracing/tiles.h"

namespace luz::app {

// ---- [the noise] ---------------------------------------------------------------------------------
double relative_noise(const Image& mean, const Image& standard_error) {
  const size_t n = mean.pixels.size();
  if (n == 0 || standard_error.pixels.size() != n) return 0.0;
  double mean_y = 0.0;
  for (const Rgb& c : mean.pixels) mean_y += double(rec709_luminance(c));
  mean_y /= double(n);
  double sum = 0.0;
  size_t lit = 0;
  for (size_t i = 0; i < n; ++i) {
    const double y = double(rec709_luminance(mean.pixels[i]));
    if (!(y > 0.01 * mean_y) || !(y > 0.0)) continue;
    sum += double(rec709_luminance(standard_error.pixels[i])) / y;
    ++lit;
  }
  return lit > 0 ? sum / double(lit) : 0.0;
}

// ---- [the film's worker] -------------------------------------------------------------------------
PathView::PathView(ViewerServices& viewer)
    : options(viewer.state().model_options.get<PathSettings>(path_table())), viewer_(viewer) {}

PathView::~PathView() {
  cancel();
  worker_.release();
}

void PathView::scene_changed() {
  cancel();
  shared_ = std::make_shared<Shared>();  // a new tracer: its BVH is of the old geometry
  shown_ = PathPicture{};
  uploaded_ = -1;
}

void PathView::hidden() {
  shared_->pause = true;  // the pass running finishes: the film keeps whole passes
  wait_for_ = 0;
}

void PathView::cancel() {
  worker_.cancel();  // set before the lock below: a pass published after it is never shown
  running_ = false;
  have_film_ = false;
  shown_ = PathPicture{};
  uploaded_ = -1;
  std::lock_guard lock(shared_->mutex);
  shared_->published = PathPicture{};
}

PathFingerprint PathView::fingerprint(const Camera& camera, glm::ivec2 size) const {
  rt::PathOptions o = options;
  o.spp = 0;
  o.max_depth = rt::max_depth_of(o);
  o.textures = viewer_.state().local.terms.textures;  // the panel's T switch, as --no-textures
  return {camera.to_world, camera.yfov, size.x, size.y, o, editable_values(*viewer_.state().scene)};
}

// No worker runs: the film, the tracer and the scene's copy are this thread's.
void PathView::start(const Camera& camera, glm::ivec2 size) {
  const Scene& scene = *viewer_.state().scene;
  Shared& s = *shared_;
  if (!s.tracer) {
    s.copy = std::make_unique<Scene>(scene);
    s.tracer = std::make_unique<rt::PathRenderer>(*s.copy);  // Embree's BVH, once per scene
  }
  if (!have_film_) {
    // A new film: the tracer's copy takes the viewer's editable values (the geometry is the
    // same: a new geometry is a new scene).
    copy_editable(scene, *s.copy);
    s.film = rt::PathFilm(size.x, size.y);
    started_ = fingerprint(camera, size);
    have_film_ = true;
    ++restarts_;
    s.began = std::chrono::steady_clock::now();
  }
  s.pause = false;
  running_ = true;
  const rt::PathOptions o = started_.options;  // spp unused: the worker goes one pass at a time
  s.target = std::max(1, options.spp);
  // Passes until the target, a pause or a cancel: a pass a step on a thread of its own, a tile a
  // step without threads (a few each frame).
  s.next_tile = 0;
  worker_.start([shared = shared_, camera, o](const std::atomic<bool>& cancel) {
    Shared& t = *shared;
    const auto more = [&t, &cancel] { return !cancel && !t.pause && t.film.min_samples() < t.target; };
    if (t.next_tile == 0 && !more()) return false;
    const size_t tiles = rt::make_tiles(t.film.width(), t.film.height(), o.tile_size).size();
    const size_t count = BackgroundWorker::threaded() ? tiles : 1;
    t.tracer->add_samples(t.film, camera, o, 1, t.next_tile, count, {}, &cancel);
    t.next_tile += count;
    if (cancel) return false;  // an unfinished pass: the film is dropped
    if (t.next_tile < tiles) return true;
    t.next_tile = 0;
    PathPicture pass;
    pass.mean = t.film.mean();
    pass.spp = t.film.min_samples();
    pass.noise = relative_noise(pass.mean, t.film.standard_error());
    pass.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t.began).count();
    std::lock_guard lock(t.mutex);
    if (cancel) return false;  // cancelled meanwhile: the pass belongs to a dropped film
    pass.version = t.published.version + 1;
    t.published = std::move(pass);
    return more();
  });
}

void PathView::collect() {
  worker_.settle();  // without threads, this frame's passes run here
  if (running_ && worker_.finished()) {
    worker_.join();
    running_ = false;
  }
  std::lock_guard lock(shared_->mutex);
  if (shared_->published.version != shown_.version) shown_ = shared_->published;
}

void PathView::advance(const Camera& camera, const Viewport& viewport) {
  shared_->target = std::max(1, options.spp);  // a running worker stops there (or goes on to there)
  collect();
  const glm::ivec2 size = viewport.pixels;
  const bool stale = have_film_ && started_ != fingerprint(camera, size);
  // A lower target than the film has: a new film, so that the picture is of that many samples.
  const bool too_many = have_film_ && shown_.spp > std::max(1, options.spp);
  if (restart_ || stale || too_many) {
    restart_ = false;
    cancel();
  }
  if (running_ && shared_->pause) {
    shared_->pause = false;  // shown again before the pass ended: it goes on
    if (worker_.finished()) collect();  // it had stopped already
  }
  // A cancelled worker still ending holds the film and the tracer: the next film waits for it.
  if (!running_ && (!have_film_ || shown_.spp < std::max(1, options.spp)) && worker_.settle()) start(camera, size);
  if (!busy()) wait_for_ = 0;  // a wait ends once: a later restart does not hold the script again
}

const PathPicture* PathView::picture_for(const Camera& camera, glm::ivec2 size) const {
  if (!have_film_ || shown_.spp == 0 || started_ != fingerprint(camera, size)) return nullptr;
  return &shown_;
}

// ---- [the frame] ---------------------------------------------------------------------------------
void PathView::draw(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) {
  const glm::ivec2 size = viewport.pixels;
  if (!picture_for(camera, size)) {
    // Until the first pass: the raster (Phong) view, as Whitted's model shows before a trace.
    LocalOptions raster = viewer_.state().local;
    raster.shading = Shading::phong;
    picture.bind();
    viewer_.local_renderer().draw(camera, size.x, size.y, raster);
    return;
  }
  if (!texture_ || texture_->width() != size.x || texture_->height() != size.y) {
    texture_ = std::make_unique<gl::Framebuffer>(size.x, size.y);
    uploaded_ = -1;
  }
  if (uploaded_ != shown_.version) {
    upload_pixels(*texture_, shown_.mean, 0, 0, size.x, size.y, upload_);
    uploaded_ = shown_.version;
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, texture_->id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, picture.id());
  glBlitFramebuffer(0, 0, size.x, size.y, 0, 0, size.x, size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  picture.bind();
}

bool PathView::busy() const {
  if (wait_for_ <= 0) return false;
  // What advance() publishes it draws in the same frame, so a pass seen here is on screen. A
  // worker that stopped short (hidden) ends the wait.
  const int goal = std::min(wait_for_, std::max(1, options.spp));
  return shown_.spp < goal && (running_ || restart_ || !have_film_);
}

std::string PathView::status() const {
  if (shown_.spp == 0) return tr("(first pass)");
  return trf("{} spp, noise {:.2f}%{}", shown_.spp, 100.0 * shown_.noise, running_ ? tr(", refining") : "");
}

void PathView::windows(const Viewport& viewport, WindowCorners& corners) {
  const int target = std::max(1, options.spp);
  std::string line = shown_.spp == 0 ? std::string(tr("(first pass)"))
                     : running_      ? trf("{} / {} spp, noise {:.2f}%", shown_.spp, target, 100.0 * shown_.noise)
                                     : trf("{} spp, noise {:.2f}%: done", shown_.spp, 100.0 * shown_.noise);
  draw_hint("path hint", viewport, corners, viewer_.ui_scale(), {float(shown_.spp) / float(target), {std::move(line)}});
}

// ---- [panel] -------------------------------------------------------------------------------------
void PathView::panel() {
  ImGui::TextDisabled("%s", tr("slide 14's equation by Monte Carlo: the reference"));
  ImGui::TextWrapped("L(x, V) = Le(x, V) + ∫ f(x, L, V) · L(x, L) · cos θ dL");
  // The ranges of its options table's rows (path_options.h): --spp's and --depth's.
  const SliderRange spp = slider_range(path_table(), "spp"), depth = slider_range(path_table(), "depth");
  int target = options.spp;
  if (ImGui::SliderInt(tr("samples per pixel (target)"), &target, int(spp.low), int(spp.high), "%d",
                       ImGuiSliderFlags_Logarithmic))
    options.spp = std::max(1, target);
  int max_depth = rt::max_depth_of(options);
  if (ImGui::SliderInt(tr("maximum depth"), &max_depth, 1, int(depth.high))) options.max_depth = max_depth;
  int seed = int(options.seed);
  if (ImGui::InputInt(tr("seed"), &seed)) options.seed = uint32_t(std::max(0, seed));
  if (ImGui::Button(tr("Restart"))) restart();
  const double seconds = std::max(shown_.seconds, 1e-9);
  const glm::ivec2 s = size();
  ImGui::Text("%s", trf("{} of {} samples per pixel, {:.3g} samples/s", shown_.spp, std::max(1, options.spp),
                        double(s.x) * double(s.y) * double(shown_.spp) / seconds).c_str());
  ImGui::Text("%s", trf("noise: {:.2f}% (standard error / mean, lit pixels)", 100.0 * shown_.noise).c_str());
  ImGui::TextDisabled("%s", tr("moving the camera or editing the scene starts a new picture"));
}

}  // namespace luz::app

// ---- [script verbs] ------------------------------------------------------------------------------
namespace luz::app {
namespace {

PathView& path_model(ViewerServices& viewer) { return static_cast<PathView&>(viewer.view("path")); }

// `path NAME VALUE`: a row of its options table, with the row's check; `path restart`.
std::string check_path(const ScriptCommand& c) {
  const auto& a = c.args;
  if (a.size() == 1 && a[0] == "restart") return "";
  const OptionRow* row = a.size() == 2 ? find_row(path_table(), a[0]) : nullptr;
  if (!row || !in_viewer(*row)) return "`path` takes spp N, depth N, seed S or restart";
  return parse_value(*row, a[1]) ? "" : fmt::format("`path {}` takes {}", a[0], accepted_text(*row));
}

bool run_path(ViewerServices& viewer, const ScriptCommand& c, std::string&) {
  PathView& path = path_model(viewer);
  const auto& a = c.args;
  if (a[0] == "restart") {
    path.restart();
    return true;
  }
  const OptionRow& row = *find_row(path_table(), a[0]);
  row.set(&path.options, *parse_value(row, a[1]));
  return true;
}

std::string check_wait_path(const ScriptCommand& c) {
  if (auto e = check_count(c, 0, 1); !e.empty()) return e;
  return c.args.empty() || (is_int(c.args[0]) && std::stoi(c.args[0]) >= 1) ? "" : "`wait-path N` takes N >= 1";
}

// Waits for the path picture shown, or for the difference view's reference; with neither, the
// path model is shown first.
bool run_wait_path(ViewerServices& viewer, const ScriptCommand& c, std::string&) {
  if (!viewer.difference().on() && viewer.state().model != "path") viewer.set_model(*find_model("path"));
  path_model(viewer).wait_for(c.args.empty() ? 0 : std::stoi(c.args[0]));
  viewer.difference().wait_for_reference();
  return true;
}

bool run_dump_path(ViewerServices& viewer, const ScriptCommand& c, std::string& error) {
  const PathView& path = path_model(viewer);
  const PathPicture& p = path.latest();
  nlohmann::json j = {{"spp", p.spp},
                      {"target", path.options.spp},
                      {"depth", rt::max_depth_of(path.options)},
                      {"seed", path.options.seed},
                      {"size", {path.size().x, path.size().y}},
                      {"noise", p.noise},
                      {"seconds", p.seconds},
                      {"running", path.running()},
                      {"restarts", path.restarts()}};
  return write_json(c.args[0], j, "the path tracer's state", error);
}

constexpr ScriptVerb verbs[] = {
    {"path", "path spp N|depth N|seed S|restart", check_path, run_path, false},
    {"wait-path", "wait-path [N]", check_wait_path, run_wait_path, true},
    {"dump-path", "dump-path FILE.json", check_json_file, run_dump_path, true},
    {"difference", "difference on|off", check_difference, run_difference, true},
    {"dump-difference", "dump-difference FILE.json", check_json_file, run_dump_difference, true},
};

}  // namespace

std::span<const ScriptVerb> path_verbs() { return verbs; }

}  // namespace luz::app
