// Embree 3: one device, one scene, one triangle geometry per mesh. Single rays use rtcIntersect1
// / rtcOccluded1; batches of coherent rays go through Embree's stream API (rtcIntersect1M with
// the coherent flag), which Embree's performance recommendations prefer for coherent rays
// ("Embree API: Performance Recommendations": use stream or packet queries, mark them coherent).
#include "raytracing/embree_scene.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <mutex>
#include <vector>

#include <embree3/rtcore.h>
#include <fmt/format.h>

#include "core/error.h"
#include "core/i18n.h"
#include "core/parallel_for.h"

namespace luz::rt {

struct EmbreeIntersector::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

// Reading the device's error clears it: `error` is the value read.
[[noreturn]] void fail(RTCError error, const char* what) {
  throw Error(ErrorKind::bad_value, i18n::trf("Embree: {} failed (error {})", what, int(error)));
}

[[noreturn]] void fail(RTCDevice device, const char* what) { fail(rtcGetDeviceError(device), what); }

// Fields written one by one straight into Embree's structures: building a temporary RTCRay and
// copying it makes the compiler store fields and reload them as 16-byte blocks, a
// store-forwarding stall per ray that cost more than the conversion itself.
void fill(RTCRay& r, const Ray& ray) {
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.tnear = 0.0f;  // origins are already offset off their surface (whitted.cpp, offset_origin)
  r.dir_x = ray.direction.x;
  r.dir_y = ray.direction.y;
  r.dir_z = ray.direction.z;
  r.time = 0.0f;
  r.tfar = ray.tfar;
  r.mask = 0xFFFFFFFFu;
  r.id = 0;
  r.flags = 0;
}

void fill(RTCRayHit& rh, const Ray& ray) {
  fill(rh.ray, ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

Hit from_embree(const RTCRayHit& rh) {
  Hit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.t = rh.ray.tfar;
  hit.mesh = int(rh.hit.geomID);
  hit.triangle = int(rh.hit.primID);
  hit.u = rh.hit.u;  // Embree's barycentrics: p = (1-u-v) p0 + u p1 + v p2
  hit.v = rh.hit.v;
  return hit;
}

// A device for this intersector. With oneTBB (the desktop), one of its own, scheduled by the
// parallel loops' scheduler. Built with its own scheduler (the web page's Embree), a device would
// start a thread per core wherever it is first used: it is given the parallel loops' count
// instead, which on the browser's main thread is one (that thread must never wait for a thread
// to start). Those devices are kept for the program's life, one per count: releasing one deletes
// its thread-local error slot, and Emscripten's pthread_key_delete leaves the slot's value behind
// for the next key of the same number, so that the next device would read its errors from freed
// memory.
RTCDevice new_device() {
#if LUZ_PARALLEL_TBB
  return rtcNewDevice(nullptr);
#else
  static std::mutex mutex;
  static std::map<unsigned, RTCDevice> devices;
  const unsigned threads = parallel::thread_count();
  const std::lock_guard lock(mutex);
  RTCDevice& device = devices[threads];
  if (!device) device = rtcNewDevice(fmt::format("threads={}", threads).c_str());
  if (device) rtcRetainDevice(device);  // the map keeps its own reference
  return device;
#endif
}

}  // namespace

EmbreeIntersector::EmbreeIntersector(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->device = new_device();
  if (!impl_->device) throw Error(ErrorKind::bad_value, i18n::tr("Embree: cannot create a device"));
  impl_->scene = rtcNewScene(impl_->device);
  if (!impl_->scene) fail(impl_->device, "rtcNewScene");
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);  // built once, traced often
  // Watertight: otherwise a ray exactly through the edge two triangles share may miss both.
  // Streams did, for the row of pixel centres that a square face seen head-on puts on its
  // diagonal (rtcSetSceneFlags(3): "avoiding artifacts caused by rays shooting through edges of
  // neighboring primitives"). Measured, it costs nothing visible next to the rounds' noise.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);

  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    RTCGeometry geometry = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry) fail(impl_->device, "rtcNewGeometry");
    // New buffers owned by Embree: it reads 16 bytes past a vertex, so a shared std::vector of
    // vec3 would need padding anyway.
    auto* positions = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
        mesh.positions.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
        mesh.triangle_count()));
    if (!positions || !indices) fail(impl_->device, "rtcSetNewGeometryBuffer");
    std::memcpy(positions, mesh.positions.data(), mesh.positions.size() * 3 * sizeof(float));
    std::memcpy(indices, mesh.indices.data(), mesh.triangle_count() * 3 * sizeof(unsigned));
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(impl_->scene, geometry, unsigned(m));  // geomID = mesh index
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(impl_->scene);
  if (const RTCError error = rtcGetDeviceError(impl_->device); error != RTC_ERROR_NONE) fail(error, "rtcCommitScene");
}

EmbreeIntersector::~EmbreeIntersector() = default;

Hit EmbreeIntersector::intersect(const Ray& ray, uint64_t&) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  fill(rh, ray);
  rtcIntersect1(impl_->scene, &context, &rh);
  return from_embree(rh);
}

bool EmbreeIntersector::occluded(const Ray& ray, uint64_t&) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r;
  fill(r, ray);
  rtcOccluded1(impl_->scene, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar to -inf when it finds an occluder
}

void EmbreeIntersector::intersect(std::span<const Ray> rays, std::span<Hit> hits,
                                  uint64_t&) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  thread_local std::vector<RTCRayHit> stream;  // reused: no allocation per batch
  stream.resize(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) fill(stream[i], rays[i]);
  rtcIntersect1M(impl_->scene, &context, stream.data(), unsigned(stream.size()), sizeof(RTCRayHit));
  for (size_t i = 0; i < rays.size(); ++i) hits[i] = from_embree(stream[i]);
}

// In batches on the stack: no allocation, and no thread-local buffer, whose first use on a thread
// could wait for another on the page's main thread (core/parallel_for.h, MainThread), where the
// radiosity's rays call this.
void EmbreeIntersector::occluded(std::span<const Ray> rays, std::span<bool> blocked,
                                 uint64_t&) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  constexpr size_t kBatch = 64;
  std::array<RTCRay, kBatch> batch;
  for (size_t first = 0; first < rays.size(); first += kBatch) {
    const size_t count = std::min(kBatch, rays.size() - first);
    for (size_t i = 0; i < count; ++i) fill(batch[i], rays[first + i]);
    rtcOccluded1M(impl_->scene, &context, batch.data(), unsigned(count), sizeof(RTCRay));
    for (size_t i = 0; i < count; ++i) blocked[first + i] = batch[i].tfar < 0.0f;
  }
}

}  // namespace luz::rt
