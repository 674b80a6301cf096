// The loop bodies the page's main thread runs beside the kept threads (core/parallel_for.h,
// MainThread::joins: the radiosity's rays, its arriving power and its adaptive gather). On the
// browser's main thread a first call that meets a function-local static being initialised by
// another thread, or that registers the thread's first thread-local destructor while another
// thread sets up the runtime's list of them, waits on a condition variable: Emscripten warns,
// and the page's tests fail on the warning. Those waits cannot be seen natively, but what leads
// to them can: this program stands between the compiled code and the C++ runtime's one-time
// initialisation (__cxa_guard_acquire) and thread-local destructors (__cxa_thread_atexit), and
// counts the calls, and the allocations (one lock for the whole page), made on a thread of its own
// that runs each body over the Cornell box for the first time, after the work done before a loop
// (loading the scene, cutting its mesh, building Embree's BVH). None may happen there.
// Its own program: the counting stands in for the runtime's functions for every test in it.
#include <dlfcn.h>

#include <atomic>
#include <cstdlib>
#include <cxxabi.h>
#include <new>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "io/gltf_loader.h"
#include "radiosity/element_form_factor.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/polygon_form_factor.h"
#include "radiosity/ray_form_factors.h"
#include "support.h"

namespace {

// Per thread, constant-initialised and trivially destroyed: counting registers nothing itself.
thread_local int guarded_initialisations = 0;
thread_local int destructors_registered = 0;
thread_local int allocations = 0;

using GuardAcquire = int (*)(__cxxabiv1::__guard*);
std::atomic<GuardAcquire> runtime_guard_acquire{nullptr};

}  // namespace

extern "C" {

// The C++ runtime's one-time initialisation of a function-local static, counted.
int __cxa_guard_acquire(__cxxabiv1::__guard* guard) {
  ++guarded_initialisations;
  GuardAcquire acquire = runtime_guard_acquire.load();
  if (!acquire) {
    acquire = reinterpret_cast<GuardAcquire>(dlsym(RTLD_NEXT, "__cxa_guard_acquire"));
    runtime_guard_acquire.store(acquire);
  }
  return acquire(guard);
}

// glibc's registration of a thread-local object's destructor, which the C++ runtime's calls.
int __cxa_thread_atexit_impl(void (*destructor)(void*), void* object, void* dso);
int __cxa_thread_atexit(void (*destructor)(void*), void* object, void* dso) noexcept {
  ++destructors_registered;
  return __cxa_thread_atexit_impl(destructor, object, dso);
}

}  // extern "C"

void* operator new(std::size_t size) {
  ++allocations;
  if (void* memory = std::malloc(size == 0 ? 1 : size)) return memory;
  throw std::bad_alloc();
}
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }

namespace luz {
namespace {

struct Counts {
  int guarded = 0, destructors = 0, allocations = 0;
};

// Runs `body` on a new thread, and what it made there.
template <class Body>
Counts on_a_new_thread(const Body& body) {
  Counts counts;
  std::thread([&] {
    body();
    counts = {guarded_initialisations, destructors_registered, allocations};
  }).join();
  return counts;
}

void expect_none(const Counts& counts, const char* what) {
  EXPECT_EQ(counts.guarded, 0) << what << ": a function-local static initialised in the body";
  EXPECT_EQ(counts.destructors, 0) << what << ": a thread-local object with a destructor in the body";
  EXPECT_EQ(counts.allocations, 0) << what << ": an allocation in the body";
}

// The counting works: a body that does each of the three is seen doing it.
TEST(MainThreadBodies, TheCountingSeesEachOfTheThree) {
  const Counts counts = on_a_new_thread([] {
    static const std::vector<int> table(3, 1);
    thread_local std::vector<int> buffer;
    buffer.push_back(table[0]);
  });
  EXPECT_GE(counts.guarded, 1);
  EXPECT_GE(counts.destructors, 1);
  EXPECT_GE(counts.allocations, 2);
}

class BodiesOnTheCornellBox : public ::testing::Test {
protected:
  BodiesOnTheCornellBox() : loaded_(io::load_gltf(test::scene_dir() / "cornell_box.gltf")) {
    RadiosityOptions options;
    options.patch_size = 0.3f;
    mesh_ = PatchMesh::build(loaded_.scene, options);
  }
  io::LoadedScene loaded_;
  PatchMesh mesh_;
};

// The rays' bodies (ray_form_factors.cpp): every element's factor from every patch, and the
// solid angles and sunlit areas of a point light, a spot and a sun.
TEST_F(BodiesOnTheCornellBox, TheRaysBodiesAllocateNothingAndInitialiseNothing) {
  const RayFormFactors rays(loaded_.scene, mesh_);
  std::vector<ShooterEmission> emissions;
  for (size_t i = 0; i < mesh_.shooters.size(); ++i) emissions.emplace_back(mesh_, i, std::span<const Rgb>{});
  Light point, spot, sun;
  point.position = spot.position = glm::vec3(0.0f, 1.9f, 0.0f);
  spot.type = LightType::spot;
  spot.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  double sum = 0.0;
  uint64_t traced = 0;
  const Counts counts = on_a_new_thread([&] {
    for (size_t i = 0; i < mesh_.shooters.size(); ++i)
      for (size_t j = 0; j < mesh_.size(); ++j) sum += rays.element_factor(i, emissions[i], j, 4, 1, 2, traced);
    for (size_t j = 0; j < mesh_.size(); ++j)
      sum += rays.element_solid_angle(point, j, kMaxVisibilityRays, 1, 2, traced) +
             rays.element_solid_angle(spot, j, kMaxVisibilityRays, 1, 2, traced) +
             rays.element_sunlit_area(sun, j, kMaxVisibilityRays, 1, 2, traced);
  });
  EXPECT_GT(sum, 0.0);
  EXPECT_GT(traced, 0u);
  expect_none(counts, "rays");
}

// The contour integrals of the arriving power and the gather (shooting.cpp's form_factor_to and
// seen_from, element_form_factor.cpp): every element to every patch, in both precisions.
TEST_F(BodiesOnTheCornellBox, TheContourIntegralsAllocateNothingAndInitialiseNothing) {
  double sum = 0.0;
  const Counts counts = on_a_new_thread([&] {
    for (const ShootingPatch& shooter : mesh_.shooters)
      for (const Patch& element : mesh_.patches) {
        const glm::vec3 corners[3] = {mesh_.vertices[element.vertices[0]], mesh_.vertices[element.vertices[1]],
                                      mesh_.vertices[element.vertices[2]]};
        sum += element_to_patch_form_factor(mesh_, element, shooter) +
               point_to_polygon_form_factor(shooter.centre, shooter.normal, corners) +
               triangle_to_polygon_form_factor(corners[0], corners[1], corners[2], element.normal,
                                               shooter.corners, 1);
      }
  });
  EXPECT_GT(sum, 0.0);
  expect_none(counts, "contour integrals");
}

}  // namespace
}  // namespace luz
