#pragma once
// What the traced models' views (Whitted's, the hybrid's, the path tracer's) share to show a
// picture computed off the GL thread: a worker thread that can be cancelled, the scene numbers
// it depends on, and the upload of finished pixels into a texture. GL stays on the GL thread;
// the worker only computes and copies pixels (DESIGN.md "Threads").
#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "core/scene.h"
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
  // The same view at another size: only the picture's room changed (the window resized, the
  // panel shown or hidden, a lesson's caption settling beside or below the picture).
  bool resized_from(const ViewFingerprint& before) const {
    return (width != before.width || height != before.height) && to_world == before.to_world &&
           yfov == before.yfov && options == before.options && scene == before.scene;
  }
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

// One job at a time, in steps: on a thread of its own, which runs the job's steps one after
// another, or, in the page built without threads (LUZ_WEB_THREADS=OFF), on the browser's main
// thread between frames, as many steps each frame as fit in a few milliseconds (at least one).
// A step reads the cancel flag (the renderers' `cancel` argument) and should return soon once it
// is set; it returns true while steps remain. Whatever a job publishes before it ends is visible
// to the thread that sees finished().
//
// The browser's main thread must never wait for another thread: a thread that starts threads
// (the parallel loops, Embree's) asks the main thread for them, so a main thread waiting for it
// would wait forever. So in the page a job is cancelled without waiting (cancel(), then settle()
// once a frame until it has ended) and let go of (release(): it ends on its own, its captures
// keeping what it reads alive). Its thread is detached as it starts: the job's end is its
// `finished` flag, and the thread frees itself. Detached later, a thread already ending would be
// joined (musl's pthread_detach does so), a short wait on the main thread all the same. The
// window may wait for the tile in hand: there cancel() and release() join, and what follows
// starts in the same frame. stop() and the destructor join in the window; in the page they
// cancel and let go, as release() does. Without threads a job has no thread: settle() takes its
// steps, and a cancelled one takes no more.
class BackgroundWorker {
public:
  using Job = std::function<bool(const std::atomic<bool>& cancel)>;  // one step; true: more to come

  BackgroundWorker() = default;
  ~BackgroundWorker() { stop(); }
  BackgroundWorker(const BackgroundWorker&) = delete;
  BackgroundWorker& operator=(const BackgroundWorker&) = delete;

  void start(Job job);  // a job still running is stopped first
  void stop();          // sets the cancel flag; the window joins, the page lets the job end on its own
  void cancel();        // sets the cancel flag; the page's job ends on its own, the window's is joined
  // Once a frame: joins a job that has ended; true when no job is left. Without threads, runs
  // this frame's steps of the job first.
  bool settle();
  void release();       // cancels; the page lets the job end on its own, the desktop joins it
  bool finished() const { return run_ && run_->finished.load(std::memory_order_acquire); }
  bool idle() const { return !joinable() || finished(); }  // settle() would leave no job
  void join();          // once finished(): the job's results are all seen, its thread let go of
  bool joinable() const;  // a job started and not yet joined or let go of
  double seconds() const;  // since the last start

  // Whether jobs run on a thread of their own (false in the page built without threads).
  static constexpr bool threaded() {
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    return false;
#else
    return true;
#endif
  }

private:
  // A job's flags, shared with its thread: a released job still reads and writes them.
  struct Run {
    std::atomic<bool> cancel{false};
    std::atomic<bool> finished{false};
  };
  void run_steps();      // without threads: this frame's steps
  std::shared_ptr<Run> run_;
  std::chrono::steady_clock::time_point began_;
  std::thread thread_;
  Job steps_;  // without threads: the job whose steps are left
#if defined(__EMSCRIPTEN__)
  bool held_ = false;  // joinable(): the page's thread is detached as it starts
#endif
};

inline bool BackgroundWorker::joinable() const {
#if defined(__EMSCRIPTEN__)
  if constexpr (!threaded()) return static_cast<bool>(steps_);
  return held_;
#else
  return thread_.joinable();
#endif
}

}  // namespace luz::app
