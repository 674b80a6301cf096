#pragma once
// What the traced models' views (Whitted's, the hybrid's, the path tracer's) share to show a
// picture computed off the GL thread: a worker thread that can be cancelled, the scene numbers
// it depends on, and the upload of finished pixels into a texture. GL stays on the GL thread;
// the worker only computes and copies pixels (DESIGN.md "Threads").
#include <atomic>
#include <chrono>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "core/scene.h"
#include "core/std_compat.h"
#include "gl/framebuffer.h"

namespace luz::app {

// Everything a picture computed in the background depends on, to tell when the picture on
// screen is no longer the view's: the camera, the size, the renderer's options and the scene's
// editable numbers (the camera moved, the window was resized, an option or the scene was edited).
template <class Options>
struct ViewFingerprint {
  glm::mat4 to_world{1.0f};
  float yfov = 0.0f;
  int width = 0, height = 0;
  Options options;
  std::vector<float> scene;  // editable_values()
  bool operator==(const ViewFingerprint&) const = default;
};

// What the panel can change of a scene (its Lights, Material and Scene sections), flattened:
// comparing two such lists tells whether the scene a worker saw is still the viewer's.
std::vector<float> editable_values(const Scene& scene);

// A worker's own copy of the scene takes the viewer's editable values, so that the panel may
// edit the viewer's scene while the worker reads its copy. The geometry stays: a new geometry
// is a new scene, and a new copy.
void copy_editable(const Scene& from, Scene& copy);

// Copies the pixels of `image` in columns [x0, x1) and rows [y0, y1) (row 0 at the top) into
// `target`'s colour texture, whose rows go bottom-up. `scratch` holds the rows meanwhile.
void upload_pixels(const gl::Framebuffer& target, const Image& image, int x0, int y0, int x1, int y1,
                   std::vector<float>& scratch);

// One job at a time on a thread of its own. The job reads the cancel flag (the renderers'
// `cancel` argument) and should return soon once it is set; whatever it publishes before it
// returns is visible to the thread that sees finished().
class BackgroundWorker {
public:
  using Job = std::function<void(const std::atomic<bool>& cancel)>;

  BackgroundWorker() = default;
  ~BackgroundWorker() { stop(); }
  BackgroundWorker(const BackgroundWorker&) = delete;
  BackgroundWorker& operator=(const BackgroundWorker&) = delete;

  void start(Job job);  // a job still running is stopped first
  void stop();          // sets the cancel flag and joins; nothing when no job runs
  bool finished() const { return finished_.load(std::memory_order_acquire); }
  void join();          // once finished(): the thread is gone, the job's results are all seen
  bool joinable() const { return thread_.joinable(); }
  double seconds() const;  // since the last start
  const std::atomic<bool>& cancel_flag() const { return cancel_; }

private:
  std::atomic<bool> cancel_{false};
  std::atomic<bool> finished_{false};
  std::chrono::steady_clock::time_point began_;
  luz::jthread thread_;
};

}  // namespace luz::app
