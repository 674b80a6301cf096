#include "app/models/whitted/whitted_worker.h"

#include <thread>

namespace luz::app {

WhittedWorker::WhittedWorker(const Scene& scene) : copy_(scene), tracer_(copy_) {}

WhittedWorker::~WhittedWorker() { cancel(); }

void WhittedWorker::start(const Scene& scene, const Camera& camera, int width, int height,
                        const rt::WhittedOptions& options, const gl::Framebuffer& raster, bool held) {
  cancel();
  copy_editable(scene, copy_);
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
  cancelled_ = false;
  phase_ = TracePhase::tracing;
  worker_.start([this, camera, width, height, options, held](const std::atomic<bool>& cancel) {
    if (held) {  // no tile until cancelled: the tracer then skips them all
      while (!cancel) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    tracer_.render(camera, width, height, options,
                   [this](const rt::TileDone& tile) {
                     std::lock_guard lock(mutex_);
                     for (int y = tile.tile.y0; y < tile.tile.y1; ++y)
                       for (int x = tile.tile.x0; x < tile.tile.x1; ++x) pixels_.at(x, y) = tile.image.at(x, y);
                     pending_.push_back(tile.tile);
                     done_ = tile.done;
                   },
                   &cancel);
  });
}

bool WhittedWorker::cancel() {
  const bool was_running = phase_ == TracePhase::tracing;
  worker_.stop();
  if (was_running) {
    cancelled_ = done_ < total_;  // it may have finished before this frame saw it
    uploaded_done_ = done_;  // the worker has stopped: no lock needed
    seconds_ = worker_.seconds();
  }
  phase_ = TracePhase::raster;
  return was_running;
}

void WhittedWorker::update() {
  if (phase_ != TracePhase::tracing) return;
  // Read before the tiles: every tile of a finished render was queued before it finished.
  const bool finished = worker_.finished();
  {
    std::lock_guard lock(mutex_);
    for (const rt::Tile& t : pending_) upload_pixels(*picture_, pixels_, t.x0, t.y0, t.x1, t.y1, upload_);
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

double WhittedWorker::seconds() const {
  if (phase_ == TracePhase::tracing) return worker_.seconds();
  return seconds_;
}

rt::RayTree WhittedWorker::trace_pixel(const Scene& scene, const Camera& camera, int width, int height, int x,
                                     int y, const rt::WhittedOptions& options) {
  // A running trace reads the copy; the viewer cancels it on any edit, so then it is current.
  if (phase_ != TracePhase::tracing) copy_editable(scene, copy_);
  return tracer_.trace_pixel(camera, width, height, x, y, options);
}

}  // namespace luz::app
