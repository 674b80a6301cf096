#pragma once
// The path tracer (slide 14's equation by Monte Carlo, the reference model) in the viewer: a
// picture that refines while the view stays as it is.
//
//   advance()  when anything the picture depends on changed (PathFingerprint), the worker is
//              cancelled and a new film starts; while the film has fewer samples per pixel than
//              the target, a worker thread adds passes of one sample per pixel to it
//              (rt::PathRenderer::add_samples, its tiles on TBB) and publishes the mean, the
//              samples per pixel and the noise after each whole pass;
//   draw()     on the GL thread: the latest published mean goes up into a float texture and
//              into the picture (the raster view until the first pass is done).
//
// A pixel's k-th sample depends only on (pixel, seed, k) (path_tracer.h), and every published
// picture is made of whole passes, so the picture after N passes is `luz render --model path
// --spp N --seed S` of the same view, bit for bit.
//
// Hidden (another model shown), the worker finishes its pass and stops; the film is kept and
// goes on when the view is shown again or the difference view (difference_window.h) asks for the
// reference. The worker reads its own copy of the scene, refreshed at every new film
// (background_render.h): the panel may edit the viewer's scene while a pass runs. A cancelled
// worker is not waited for (the browser's main thread never waits, background_render.h): it
// ends on its own, and the next film starts once it has ended.
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "app/viewer/background_render.h"
#include "app/viewer/model_view.h"
#include "core/image.h"
#include "core/scene.h"
#include "gl/framebuffer.h"
#include "raytracing/path_options.h"
#include "raytracing/path_tracer.h"

namespace luz::app {

// The path picture's options in it have spp 0: the target number of samples only says how far
// to go.
using PathFingerprint = ViewFingerprint<rt::PathOptions>;

// What one whole pass leaves: the mean so far and how good it is.
// The noise estimate the panel and dump-path show: over the pixels lit in `mean` (luminance
// above 1% of the picture's mean, as image_compare.h counts them), the mean of the standard
// error's luminance over the mean's. Since the luminance is a sum of the channels with positive
// weights, Y(error) bounds the standard error of Y from above.
double relative_noise(const Image& mean, const Image& standard_error);

class PathView final : public ModelView {
public:
  explicit PathView(ViewerServices& viewer);
  ~PathView() override;  // cancels; a worker still ending keeps what it reads

  void scene_changed() override;
  void hidden() override;
  void advance(const Camera& camera, const Viewport& viewport) override;
  void draw(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) override;
  void panel() override;
  void windows(const Viewport& viewport, WindowCorners& corners) override;
  std::string status() const override;
  bool busy() const override;
  bool animating() const override { return running_ || !worker_.idle(); }

  // The settings the panel, `set path.NAME` and the `path` verb change, the viewer's struct of
  // the path tracer's options table (path_options.h); the next advance() follows them.
  rt::PathOptions& options;  // options.spp: the target
  void restart() { restart_ = true; }
  // The script's `wait-path [N]`: busy until N samples per pixel (the target when N <= 0, and
  // never more than it) are published and drawn.
  void wait_for(int spp) { wait_for_ = spp <= 0 ? options.spp : spp; }

  // The latest whole pass of the view `camera` and `size` are of; nullptr until there is one
  // (the film is of another view, or no pass is done yet).
  const PathPicture* picture_for(const Camera& camera, glm::ivec2 size) const override;
  const PathPicture& latest() const { return shown_; }
  int restarts() const { return restarts_; }  // films started (the view or the settings changed)
  bool running() const { return running_; }
  glm::ivec2 size() const { return {started_.width, started_.height}; }

private:
  PathFingerprint fingerprint(const Camera& camera, glm::ivec2 size) const;
  void cancel();                    // stops the worker (it ends on its own) and drops its film
  void start(const Camera& camera, glm::ivec2 size);  // a worker on the film as it is
  void collect();                   // the published pass, and a finished worker joined

  ViewerServices& viewer_;
  // What the worker reads and writes, shared with its thread, so that a worker let go of (the
  // destructor, a new scene) still has it. The film and the tracer are the worker's while it runs.
  struct Shared {
    std::unique_ptr<Scene> copy;    // the worker's scene (made with the tracer)
    std::unique_ptr<rt::PathRenderer> tracer;
    rt::PathFilm film;
    std::mutex mutex;
    PathPicture published;          // under the mutex
    std::atomic<bool> pause{false};  // stop after this pass
    std::atomic<int> target{1};      // samples per pixel to stop at
    size_t next_tile = 0;            // the pass's first tile not traced yet (the worker's)
    std::chrono::steady_clock::time_point began;  // of the film
  };
  std::shared_ptr<Shared> shared_ = std::make_shared<Shared>();
  PathFingerprint started_;         // the view the film is of
  bool have_film_ = false;
  bool restart_ = false;
  int restarts_ = 0;
  int wait_for_ = 0;

  // The GL thread's.
  bool running_ = false;
  PathPicture shown_;               // the pass on screen (its mean is the texture's)
  long uploaded_ = -1;
  std::unique_ptr<gl::Framebuffer> texture_;
  std::vector<float> upload_;
  BackgroundWorker worker_;
};

// The path model's script verbs (its registry entry): path spp|depth|seed N, path restart,
// wait-path [N], dump-path FILE.json, and the difference view's (difference_window.h).
std::span<const ScriptVerb> path_verbs();

}  // namespace luz::app
