#include "app/models/whitted/whitted_worker.h"

#include <algorithm>

namespace luz::app {

std::vector<float> editable_values(const Scene& scene) {
  // What the panel can change (Lights, Material, Scene sections), flattened: comparing two such
  // lists tells whether the scene the tracer saw is still the viewer's.
  std::vector<float> v;
  auto add = [&v](std::initializer_list<float> values) { v.insert(v.end(), values); };
  auto rgb = [&add](const Rgb& c) { add({c.r, c.g, c.b}); };
  for (const Light& l : scene.lights) {
    add({float(l.enabled), float(l.type), l.inner_cone, l.outer_cone, l.warn_exponent,
         float(l.attenuation.classroom), l.attenuation.c.x, l.attenuation.c.y, l.attenuation.c.z});
    rgb(l.intensity);
    rgb(l.position);
    rgb(l.direction);
  }
  for (const Material& m : scene.materials) {
    rgb(m.ka), rgb(m.kd), rgb(m.ks), rgb(m.kr), rgb(m.kt), rgb(m.emission);
    add({m.shininess, m.ior});
  }
  rgb(scene.ambient);
  rgb(scene.background);
  v.push_back(float(scene.area_lights.size()));
  return v;
}

WhittedView::WhittedView(const Scene& scene) : copy_(scene), tracer_(copy_) {}

WhittedView::~WhittedView() { cancel(); }

void WhittedView::sync(const Scene& scene) {
  // Geometry is the same (a new geometry is a new scene, and a new WhittedView).
  copy_.lights = scene.lights;
  copy_.materials = scene.materials;
  copy_.area_lights = scene.area_lights;
  copy_.ambient = scene.ambient;
  copy_.background = scene.background;
}

void WhittedView::start(const Scene& scene, const Camera& camera, int width, int height,
                        const rt::WhittedOptions& options, const gl::Framebuffer& raster, bool held) {
  cancel();
  sync(scene);
  started_ = {camera.to_world, camera.yfov, width, height, options, editable_values(scene)};

  // The picture starts as the raster view; tiles replace it as they are traced.
  if (!picture_ || picture_->width() != width || picture_->height() != height)
    picture_ = std::make_unique<gl::Framebuffer>(width, height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, raster.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, picture_->id());
  glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  pixels_ = Image(width, height);
  pending_.clear();
  done_ = 0;
  uploaded_done_ = 0;
  total_ = int(rt::make_tiles(width, height, options.tile_size).size());
  counters_ = {};
  cancel_ = false;
  cancelled_ = false;
  finished_ = false;
  phase_ = TracePhase::tracing;
  began_ = std::chrono::steady_clock::now();
  // GL stays on this thread; the worker only traces and copies pixels (DESIGN.md "Threads").
  worker_ = std::jthread([this, camera, width, height, options, held] {
    if (held) {  // no tile until cancelled: the tracer then skips them all
      while (!cancel_) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    tracer_.render(camera, width, height, options,
                   [this](const rt::TileDone& tile) {
                     std::lock_guard lock(mutex_);
                     for (int y = tile.tile.y0; y < tile.tile.y1; ++y)
                       for (int x = tile.tile.x0; x < tile.tile.x1; ++x) pixels_.at(x, y) = tile.image.at(x, y);
                     pending_.push_back(tile.tile);
                     done_ = tile.done;
                   },
                   &cancel_);
    finished_.store(true, std::memory_order_release);
  });
}

bool WhittedView::cancel() {
  const bool was_running = phase_ == TracePhase::tracing;
  if (worker_.joinable()) {
    cancel_ = true;
    worker_.join();
  }
  if (was_running) {
    cancelled_ = done_ < total_;  // it may have finished before this frame saw it
    uploaded_done_ = done_;  // the worker has stopped: no lock needed
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
  }
  phase_ = TracePhase::raster;
  return was_running;
}

void WhittedView::update() {
  if (phase_ != TracePhase::tracing) return;
  // Read before the tiles: every tile of a finished render was queued before `finished_`.
  const bool finished = finished_.load(std::memory_order_acquire);
  {
    std::lock_guard lock(mutex_);
    glBindTexture(GL_TEXTURE_2D, picture_->colour_texture());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (const rt::Tile& t : pending_) {
      // GL's rows go bottom-up: image row y is texture row height - 1 - y.
      const int w = t.x1 - t.x0, h = t.y1 - t.y0;
      upload_.resize(size_t(w) * h * 3);
      for (int row = 0; row < h; ++row)
        for (int x = 0; x < w; ++x) {
          const Rgb& p = pixels_.at(t.x0 + x, t.y1 - 1 - row);
          float* out = &upload_[(size_t(row) * w + x) * 3];
          out[0] = p.r, out[1] = p.g, out[2] = p.b;
        }
      glTexSubImage2D(GL_TEXTURE_2D, 0, t.x0, pixels_.height - t.y1, w, h, GL_RGB, GL_FLOAT, upload_.data());
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    pending_.clear();
    uploaded_done_ = done_;
  }
  if (finished) {
    worker_.join();
    counters_ = tracer_.counters();  // written by render() before it returned
    seconds_ = counters_.seconds;
    phase_ = TracePhase::done;
  }
}

double WhittedView::seconds() const {
  if (phase_ == TracePhase::tracing)
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
  return seconds_;
}

rt::RayTree WhittedView::trace_pixel(const Scene& scene, const Camera& camera, int width, int height, int x,
                                     int y, const rt::WhittedOptions& options) {
  // A running trace reads the copy; the viewer cancels it on any edit, so then it is current.
  if (phase_ != TracePhase::tracing) sync(scene);
  return tracer_.trace_pixel(camera, width, height, x, y, options);
}

}  // namespace luz::app
