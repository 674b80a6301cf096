#include "app/viewer/background_render.h"

#include <initializer_list>

#include "gl/functions.h"

namespace luz::app {

std::vector<float> editable_values(const Scene& scene) {
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

void copy_editable(const Scene& from, Scene& copy) {
  copy.lights = from.lights;
  copy.materials = from.materials;
  copy.area_lights = from.area_lights;
  copy.ambient = from.ambient;
  copy.background = from.background;
}

void upload_pixels(const gl::Framebuffer& target, const Image& image, int x0, int y0, int x1, int y1,
                   std::vector<float>& scratch) {
  // GL's rows go bottom-up: image row y is texture row height - 1 - y. Four floats a pixel: an
  // RGBA32F texture takes RGBA floats everywhere, where WebGL 2 refuses RGB ones.
  const int w = x1 - x0, h = y1 - y0;
  scratch.resize(size_t(w) * size_t(h) * 4);
  for (int row = 0; row < h; ++row)
    for (int x = 0; x < w; ++x) {
      const Rgb& p = image.at(x0 + x, y1 - 1 - row);
      float* out = &scratch[(size_t(row) * size_t(w) + size_t(x)) * 4];
      out[0] = p.r, out[1] = p.g, out[2] = p.b, out[3] = 1.0f;
    }
  glBindTexture(GL_TEXTURE_2D, target.colour_texture());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, x0, image.height - y1, w, h, GL_RGBA, GL_FLOAT, scratch.data());
  glBindTexture(GL_TEXTURE_2D, 0);
}

void BackgroundWorker::start(Job job) {
  stop();
  run_ = std::make_shared<Run>();
  began_ = std::chrono::steady_clock::now();
  if constexpr (!threaded()) {
    steps_ = std::move(job);  // settle() runs it, a few steps a frame
    return;
  }
  thread_ = std::thread([run = run_, job = std::move(job)] {
    while (job(run->cancel) && !run->cancel) {
    }
    run->finished.store(true, std::memory_order_release);
  });
#if defined(__EMSCRIPTEN__)
  thread_.detach();  // still running (or not yet started): no join, now or later
  held_ = true;
#endif
}

void BackgroundWorker::run_steps() {
  // A few milliseconds a frame, so that the page keeps drawing while a job runs (a step longer
  // than that takes its frame).
  constexpr auto budget = std::chrono::milliseconds(25);
  const auto begin = std::chrono::steady_clock::now();
  while (steps_ && !run_->finished) {
    if (run_->cancel || !steps_(run_->cancel)) run_->finished = true;
    if (std::chrono::steady_clock::now() - begin > budget) break;
  }
}

void BackgroundWorker::stop() {
  if constexpr (!threaded()) {
    if (run_) {
      run_->cancel = true;
      run_->finished = true;
    }
    steps_ = nullptr;
    return;
  }
  if (!joinable()) return;
  run_->cancel = true;
#if defined(__EMSCRIPTEN__)
  held_ = false;  // the main thread never waits: the job ends on its own, as a released one
#else
  thread_.join();
#endif
}

void BackgroundWorker::cancel() {
#if defined(__EMSCRIPTEN__)
  if constexpr (!threaded()) return stop();  // no step is running: it takes no more
  if (run_) run_->cancel = true;  // settle() joins it once it has ended
#else
  stop();  // the window may wait for the tile in hand: what follows starts in the same frame
#endif
}

bool BackgroundWorker::settle() {
  if constexpr (!threaded()) run_steps();
  if (joinable() && finished()) join();
  return !joinable();
}

void BackgroundWorker::release() {
#if defined(__EMSCRIPTEN__)
  cancel();
  held_ = false;
#else
  stop();
#endif
}

void BackgroundWorker::join() {
  if constexpr (!threaded()) {
    steps_ = nullptr;  // ended: its captures go
    return;
  }
  if (!joinable()) return;
#if defined(__EMSCRIPTEN__)
  // The job has returned (finished(): its results are seen); its detached thread ends and frees
  // itself, which the main thread does not wait for.
  held_ = false;
#else
  thread_.join();
#endif
}

double BackgroundWorker::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
}

}  // namespace luz::app
