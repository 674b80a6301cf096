#pragma once
// The Whitted tracer as the command, the viewer and the tests use it: built once from a scene,
// it renders a camera's view tile by tile on TBB's worker threads into a float image, reports
// each finished tile, can be cancelled, and traces one pixel's ray tree on demand.
// A tile of stratified samples is traced by the wavefront renderer (wavefront.h) or by slide 26's
// recursion (WhittedOptions::renderer), to the picture of slide 26's own pixel loop
// (render_per_pixel); adaptive sampling and the ray tree always take the recursion.
//
//   WhittedRenderer tracer(scene);                       // Embree's BVH built here, once
//   Image image = tracer.render(camera, w, h, options, on_tile, &cancel);
//   RayTree tree = tracer.trace_pixel(camera, w, h, x, y, options);
//
// The scene must outlive the renderer. Lights, materials, the ambient term and the background
// are read at every render (a panel may edit them between renders); after a change of geometry
// call scene_changed(), which rebuilds the intersectors.
//
// Threads: one render() at a time per renderer (the viewer runs it off its GL thread, e.g. in a
// std::async task, and cancels it before starting the next). trace_pixel() and primary_hit() may
// run on another thread during a render; scene_changed() may not.
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "core/scene.h"
#include "raytracing/counters.h"
#include "raytracing/diffuse_source.h"
#include "raytracing/intersector.h"
#include "raytracing/ray_tree.h"
#include "raytracing/tiles.h"
#include "raytracing/whitted.h"
#include "raytracing/whitted_options.h"

namespace luz::rt {

struct LaneMesh;

// A finished tile: its pixels are final in `image` (the image being rendered).
struct TileDone {
  Tile tile;
  int done = 0;   // tiles finished so far, this one included
  int total = 0;  // tiles in the image
  const Image& image;
};
// Called once per finished tile, on a worker thread, never by two threads at once (the renderer
// serialises the calls), so it may copy pixels or update a progress bar without locking.
using TileCallback = std::function<void(const TileDone&)>;

class WhittedRenderer {
public:
  explicit WhittedRenderer(const Scene& scene);
  ~WhittedRenderer();
  WhittedRenderer(const WhittedRenderer&) = delete;
  WhittedRenderer& operator=(const WhittedRenderer&) = delete;

  // Rebuilds the intersectors, and the wavefront's copy of the triangles, from the scene's
  // current geometry.
  void scene_changed();

  // The hybrid model (slides 41-43): with a source set, the diffuse part of every hit (primary
  // and secondary) is its radiance (radiosity's B/pi) instead of Ia*ka + sum S_i IL_i kd
  // cos(theta) + Le, and rays add only the view-dependent part: highlights, kr*Ir and kt*It
  // (see Whitted::color). Not owned; it must outlive the renders that use it, and it may not be
  // changed while a render() runs. nullptr (the default): Whitted's model.
  void set_diffuse_source(const DiffuseSource* source) { diffuse_ = source; }

  // Renders the view, tiles in parallel. When `cancel` becomes true the tiles not yet started are
  // skipped and the image comes back with them black. Same scene, camera, size and options: the
  // same image bit for bit, however the threads are scheduled.
  Image render(const Camera& camera, int width, int height, const WhittedOptions& options,
               const TileCallback& on_tile = {}, const std::atomic<bool>* cancel = nullptr);

  // render() in steps, for a caller that traces a few tiles at a time between other work (the
  // page built without threads traces between its frames): begin() takes render()'s view, each
  // trace() renders the next `tiles` tiles in parallel (on_tile and cancel as render()'s), and
  // finish() gives the image and the counters once done(). render() is begin(), one trace() of
  // every tile, and finish(): the same image bit for bit, however the tiles are split.
  class Steps {
  public:
    Steps();
    ~Steps();
    Steps(Steps&&) noexcept;
    Steps& operator=(Steps&&) noexcept;
    bool done() const;       // every tile traced (or skipped by a cancel)
    size_t tiles() const;    // in the image
  private:
    friend class WhittedRenderer;
    struct State;
    std::unique_ptr<State> state_;
  };
  Steps begin(const Camera& camera, int width, int height, const WhittedOptions& options);
  void trace(Steps& steps, size_t tiles, const TileCallback& on_tile = {},
             const std::atomic<bool>* cancel = nullptr);
  Image finish(Steps& steps);

  // Slide 26's loop over the whole picture, on the calling thread: each pixel's primary rays
  // traced one by one by the recursion, nothing traced ahead. The reference render() is held to
  // (to within 1e-6, see renderer.cpp); stratified sampling only.
  Image render_per_pixel(const Camera& camera, int width, int height, const WhittedOptions& options);

  // The ray tree of pixel (x, y) of that render (slide 24): every ray its samples spawned.
  RayTree trace_pixel(const Camera& camera, int width, int height, int x, int y,
                      const WhittedOptions& options);

  // The nearest hit of the ray through image point (x, y) in pixel units (picking, masks).
  Hit primary_hit(const Camera& camera, int width, int height, glm::vec2 image_point,
                  const WhittedOptions& options);

  // The counters of the last render() (or finish()).
  const Counters& counters() const { return counters_; }

  // Benchmark support: while on, render() also keeps every ray it traces (in tile order).
  void keep_rays(bool on) { keep_rays_ = on; }
  std::vector<RecordedRay> take_rays() { return std::move(rays_); }

  const Intersector& intersector(const WhittedOptions& options);

private:
  // `meshes`: lane_meshes() for the wavefront renderer (hit_lanes.h), else empty.
  void render_tile(const Tile& tile, const Camera& camera, int width, int height,
                   const WhittedOptions& options, std::span<const LaneMesh> meshes, Image& image,
                   Counters& counters, std::vector<RecordedRay>* log, RayTree* tree = nullptr);

  const Scene& scene_;
  std::unique_ptr<Intersector> embree_;
  std::unique_ptr<Intersector> brute_force_;  // built when first asked for
  std::mutex brute_force_mutex_;
  std::vector<std::vector<float>> corners_;  // triangle_corners() of each mesh (hit_lanes.h)
  Counters counters_;
  const DiffuseSource* diffuse_ = nullptr;
  bool keep_rays_ = false;
  std::vector<RecordedRay> rays_;
};

}  // namespace luz::rt
