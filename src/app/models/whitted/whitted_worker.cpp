#include "app/models/whitted/whitted_worker.h"

#include <thread>
#include <utility>

namespace luz::app {

WhittedWorker::WhittedWorker(const Scene& scene) : scene_(&scene), shared_(std::make_shared<Shared>(scene)) {}

WhittedWorker::~WhittedWorker() { worker_.release(); }

void WhittedWorker::start(const Scene& scene, const Camera& camera, int width, int height,
                        const rt::WhittedOptions& options, const gl::Framebuffer& raster, bool held) {
  cancel();
  scene_ = &scene;
  started_ = {camera.to_world, camera.yfov, width, height, options, editable_values(scene)};

  // The picture starts as the raster view; tiles replace it as they are traced.
  if (!picture_ || picture_->width() != width || picture_->height() != height)
    picture_ = std::make_unique<gl::Framebuffer>(width, height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, raster.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, picture_->id());
  glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  uploaded_done_ = 0;
  total_ = int(rt::make_tiles(width, height, options.tile_size).size());
  counters_ = {};
  cancelled_ = false;
  phase_ = TracePhase::tracing;
  waiting_ = Request{camera, width, height, options, held};
  if (worker_.settle()) launch(*std::exchange(waiting_, std::nullopt));
}

// The trace before has ended: nothing else reads the tracer, its copy of the scene or the tiles.
void WhittedWorker::launch(const Request& request) {
  Shared& s = *shared_;
  copy_editable(*scene_, s.copy);
  if (next_diffuse_ != s.diffuse) {
    s.diffuse = next_diffuse_;
    s.tracer.set_diffuse_source(s.diffuse.get());
  }
  s.pixels = Image(request.width, request.height);
  s.pending.clear();
  s.done = 0;
  launched_ = true;
  worker_.start([shared = shared_, request](const std::atomic<bool>& cancel) {
    if (request.held) {  // no tile until cancelled: the tracer then skips them all
      while (!cancel) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    Shared& t = *shared;
    t.tracer.render(request.camera, request.width, request.height, request.options,
                    [&t](const rt::TileDone& tile) {
                      std::lock_guard lock(t.mutex);
                      for (int y = tile.tile.y0; y < tile.tile.y1; ++y)
                        for (int x = tile.tile.x0; x < tile.tile.x1; ++x) t.pixels.at(x, y) = tile.image.at(x, y);
                      t.pending.push_back(tile.tile);
                      t.done = tile.done;
                    },
                    &cancel);
  });
}

bool WhittedWorker::cancel() {
  const bool was_running = phase_ == TracePhase::tracing;
  if (was_running) {
    waiting_.reset();
    if (launched_) {
      worker_.cancel();
      std::lock_guard lock(shared_->mutex);
      uploaded_done_ = shared_->done;
      seconds_ = worker_.seconds();
    } else {
      seconds_ = 0.0;
    }
    cancelled_ = uploaded_done_ < total_;  // it may have finished before this frame saw it
  }
  launched_ = false;
  phase_ = TracePhase::raster;
  return was_running;
}

bool WhittedWorker::idle() { return worker_.settle() && !waiting_; }

void WhittedWorker::set_diffuse_source(std::shared_ptr<const rt::DiffuseSource> source) {
  next_diffuse_ = std::move(source);
  if (worker_.settle() && next_diffuse_ != shared_->diffuse) {
    shared_->diffuse = next_diffuse_;
    shared_->tracer.set_diffuse_source(shared_->diffuse.get());
  }
}

void WhittedWorker::update() {
  if (phase_ != TracePhase::tracing) return;
  if (waiting_) {
    if (!worker_.settle()) return;  // the cancelled trace is still ending
    launch(*std::exchange(waiting_, std::nullopt));
  }
  // Read before the tiles: every tile of a finished render was queued before it finished.
  const bool finished = worker_.finished();
  {
    std::lock_guard lock(shared_->mutex);
    for (const rt::Tile& t : rt::joined_tiles(shared_->pending, shared_->pixels.width))
      upload_pixels(*picture_, shared_->pixels, t.x0, t.y0, t.x1, t.y1, upload_);
    shared_->pending.clear();
    uploaded_done_ = shared_->done;
  }
  if (finished) {
    worker_.join();
    launched_ = false;
    counters_ = shared_->tracer.counters();  // written by render() before it returned
    seconds_ = counters_.seconds;
    phase_ = TracePhase::done;
  }
}

double WhittedWorker::seconds() const {
  if (phase_ == TracePhase::tracing) return launched_ ? worker_.seconds() : 0.0;
  return seconds_;
}

rt::RayTree WhittedWorker::trace_pixel(const Scene& scene, const Camera& camera, int width, int height, int x,
                                     int y, const rt::WhittedOptions& options) {
  // A trace running or ending reads the copy; the viewer cancels it on any edit, so the copy is
  // current until one ends.
  if (worker_.settle()) copy_editable(scene, shared_->copy);
  return shared_->tracer.trace_pixel(camera, width, height, x, y, options);
}

}  // namespace luz::app
