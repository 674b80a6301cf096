#pragma once
// The viewer's Whitted model: the view traced on demand, tile by tile, off the GL
// thread, and shown as the tiles arrive.
//
//   start()   the trace runs on a worker thread (rt::WhittedRenderer::render, its tiles on TBB);
//             each finished tile is copied, under a mutex, into a CPU image and queued;
//   update()  on the GL thread, every frame: the queued tiles go up into a float texture
//             (glTexSubImage2D, one call per rectangle of adjacent tiles), and a finished worker
//             is joined;
//   cancel()  sets the cancel flag and returns: tiles not started are skipped, and the worker
//             ends on its own (the browser's main thread never waits for it, background_render.h).
//             A trace started meanwhile starts once it has ended: one trace at a time reads the
//             tracer.
//
// The tracer reads its own copy of the scene, whose lights, materials, area lights, ambient and
// background are refreshed from the viewer's at every start (and before a ray tree is traced):
// the panel can edit the viewer's scene while a trace runs without a data race, and the viewer
// cancels the trace when it sees such an edit (see Fingerprint).
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "core/scene.h"
#include "app/viewer/background_render.h"
#include "app/viewer/viewer_state.h"
#include "gl/framebuffer.h"
#include "raytracing/counters.h"
#include "raytracing/ray_tree.h"
#include "raytracing/renderer.h"
#include "raytracing/whitted_options.h"

namespace luz::app {

using Fingerprint = ViewFingerprint<rt::WhittedOptions>;

class WhittedWorker {
public:
  explicit WhittedWorker(const Scene& scene);
  ~WhittedWorker();  // cancels; a trace still ending keeps what it reads (BackgroundWorker::release)
  WhittedWorker(const WhittedWorker&) = delete;
  WhittedWorker& operator=(const WhittedWorker&) = delete;

  // Starts tracing (a running trace is cancelled first). `raster` holds the picture the local
  // model drew of the same view, w x h: the tiles not traced yet show it. A `held` trace keeps
  // every tile back until it is cancelled: a trace surely still running, for the tests of
  // cancelling.
  void start(const Scene& scene, const Camera& camera, int width, int height,
             const rt::WhittedOptions& options, const gl::Framebuffer& raster, bool held = false);
  // Back to the raster view; true when a trace was running (and is now cancelled).
  bool cancel();
  // GL thread, once a frame: starts a trace that waited for a cancelled one to end, uploads the
  // finished tiles, joins a finished worker.
  void update();
  // No trace is running or ending: what the tracer reads may change.
  bool idle();

  // The hybrid's diffuse part (rt::WhittedRenderer::set_diffuse_source), for the traces started
  // from now on; a trace running or ending keeps the one it was started with.
  void set_diffuse_source(std::shared_ptr<const rt::DiffuseSource> source);

  TracePhase phase() const { return phase_; }
  bool cancelled() const { return cancelled_; }  // the last trace was cancelled before its end
  bool showing() const { return phase_ != TracePhase::raster; }
  // A trace runs on its thread and has not ended: a frame only uploads its tiles.
  bool tracing_on_its_thread() const { return phase_ == TracePhase::tracing && launched_ && !worker_.finished(); }
  const Fingerprint& fingerprint() const { return started_; }
  const gl::Framebuffer& picture() const { return *picture_; }  // while showing()
  int tiles_done() const { return uploaded_done_; }
  int tiles_total() const { return total_; }
  double seconds() const;                                       // so far, or in all once done
  const rt::Counters& counters() const { return counters_; }    // of the finished trace

  // Slide 24: the ray tree of pixel (x, y) of a width x height view, with the viewer's current
  // scene (copied in first when no trace runs).
  rt::RayTree trace_pixel(const Scene& scene, const Camera& camera, int width, int height, int x, int y,
                          const rt::WhittedOptions& options);

private:
  // What a trace reads and writes, shared with its thread, so that a trace let go of
  // (the destructor) still has it. One trace at a time uses the tracer.
  struct Shared {
    explicit Shared(const Scene& scene) : copy(scene), tracer(copy) {}
    Scene copy;
    rt::WhittedRenderer tracer;
    std::shared_ptr<const rt::DiffuseSource> diffuse;  // the tracer's, kept while it reads it
    // The tiles finished and not yet uploaded, and their pixels (under the mutex).
    std::mutex mutex;
    Image pixels;
    std::vector<rt::Tile> pending;
    int done = 0;
  };
  // A trace asked for, started once the one before has ended.
  struct Request {
    Camera camera;
    int width = 0, height = 0;
    rt::WhittedOptions options;
    bool held = false;
  };
  void launch(const Request& request);

  const Scene* scene_;  // the viewer's, whose editable values each trace copies
  std::shared_ptr<Shared> shared_;
  std::shared_ptr<const rt::DiffuseSource> next_diffuse_;  // for the next trace
  std::optional<Request> waiting_;
  bool launched_ = false;  // the trace shown has its worker
  TracePhase phase_ = TracePhase::raster;
  bool cancelled_ = false;
  Fingerprint started_;
  std::unique_ptr<gl::Framebuffer> picture_;  // the traced tiles over the raster picture

  int uploaded_done_ = 0, total_ = 0;
  double seconds_ = 0.0;
  rt::Counters counters_;
  std::vector<float> upload_;  // one rectangle's rows, for upload_pixels
  BackgroundWorker worker_;
};

}  // namespace luz::app
