#pragma once
// The wavefront's shading of up to kLanes hits at once (wavefront.h, steps 2 and 4), as a
// structure of arrays: each quantity of slide 26's Color() (the point and its normals, each
// light's L, distance and term, the split into kr and kt) is an array with one lane per hit, and
// each step is a loop over the lanes whose body is the recursion's own arithmetic (hit_math.h).
// Such loops compile to vector instructions, several hits an instruction. The hits' triangles,
// scattered in memory, come into the arrays by transposes in registers, 8 hits at a time; what
// cannot be vectorised (fetching each hit's material, collecting the light samples and rays that
// survive) runs in short scalar loops of its own between them.
//
// Per lane, the operations are those of SurfaceReader::surface_at and Whitted's light_samples,
// local_color and secondary_rays, in the same order, so every ray is the recursion's to the bit
// and every light's term too (test_whitted_streams).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/scene.h"
#include "raytracing/ray.h"
#include "raytracing/sampling.h"
#include "raytracing/whitted.h"
#include "raytracing/whitted_options.h"

namespace luz::rt {

inline constexpr size_t kLanes = 64;  // hits shaded together: their arrays stay in the L1 cache
static_assert(kLanes % 8 == 0, "HitLanes::load fills the lanes 8 at a time");

// The lanes' flags are 32-bit integers, not bools: as wide as the floats they select between, so
// the compiler keeps them in the same vector registers (with bools it gives up on the loop).

// Three floats a lane, as three arrays.
struct Vec3Lanes {
  float x[kLanes], y[kLanes], z[kLanes];
  glm::vec3 operator[](size_t k) const { return {x[k], y[k], z[k]}; }
  void set(size_t k, const glm::vec3& v) {
    x[k] = v.x;
    y[k] = v.y;
    z[k] = v.z;
  }
};

// Light samples that count: the shadow rays contiguous for Embree's stream, and for each the hit
// it lights (a lane while the lanes make them, then its ray's place in the queue) and its term.
// Sized once, never shrunk.
struct LaneLights {
  std::vector<Ray> shadow;
  std::vector<uint32_t> hit;
  std::vector<Rgb> term;
  size_t size = 0;
};

// The rays spawned ("Trazar(R, d+1) * kr", "Trazar(T, d+1) * kt") by each lane, when its flag is
// set: entry k is lane k's. Nothing is set when no lane spawns a ray (`any` false), nothing of
// the transmitted rays when no lane transmits (`any_transmits` false).
struct SpawnLanes {
  bool any = false, any_transmits = false;
  Vec3Lanes reflected_origin, reflected_direction, kr;
  Vec3Lanes transmitted_origin, transmitted_direction, kt;
  int32_t reflects[kLanes], transmits[kLanes];
};

// Each triangle of a mesh as one piece: its corners and vertex normals side by side, p0 p1 p2
// n0 n1 n2 (18 floats a triangle), and two floats more at the end. The lanes fetch a hit's triangle
// from one place instead of through its indices from six, in five 16-byte rows that they
// transpose into their arrays (HitLanes::load), the last row of the last triangle reaching into
// those two floats.
// Geometry only: built once per scene, not per render.
std::vector<float> triangle_corners(const Mesh& mesh);

// What the lanes read of a mesh, looked up once per render instead of once per hit: its
// triangle_corners(), its material, and what the light terms and the secondary rays take of that
// material.
struct LaneMesh {
  const float* corners;
  const Material* material;
  // kd is `kd` all over the mesh, or not read at all (the diffuse term off, or the hybrid's
  // radiosity has it); else kd_at gives it (COLOR_0, the texture).
  bool kd_uniform;
  Rgb kd;
  Rgb ks, kr, kt;
  Rgb ambient;      // Ia * ka, zero where the ambient term is off
  Rgb emission;     // Le, zero where the emission term is off
  bool emission_textured;  // Le varies over the mesh: Scene::emission_at gives it per lane
  float shininess, ior;
  int32_t shiny;    // ks > 0 and the specular term on: the highlight counts
  bool reflective, transmissive;
};

// Every mesh of the scene as the lanes read it, for `shading` with `options`; corners[m] is
// triangle_corners() of mesh m.
std::vector<LaneMesh> lane_meshes(const Scene& scene, const Whitted& shading, const WhittedOptions& options,
                                  std::span<const std::vector<float>> corners);

class HitLanes {
public:
  // What the lanes shade with, until told again: `shading` is the recursion whose surfaces() and
  // diffuse source they share, `meshes` lane_meshes() of the same. (The lanes are kept per thread
  // and reused, so this is no constructor.)
  void shade_with(const Scene& scene, const Whitted& shading, const WhittedOptions& options,
                  std::span<const LaneMesh> meshes);

  // The lanes are hits[queue[k]] of rays[queue[k]], all found (queue.size() <= kLanes), whose
  // rays have seeds[queue[k]] (sampling.h): their triangles fetched, then every surface point
  // ("calcular la normal") at once.
  void load(std::span<const uint32_t> queue, std::span<const Ray> rays, std::span<const Hit> hits,
            std::span<const uint64_t> seeds);
  // Every lane's light samples (Whitted::light_samples), the area lights' points drawn from the
  // generator of the lane's seed; those whose term counts appended to `out`, lane by lane and
  // each lane's in the order of its lights, as the recursion makes them.
  void light_samples(LaneLights& out);
  // Each lane's local colour before its lights' terms (Whitted::local_color: Ia*ka + Le, or the
  // hybrid's diffuse radiance), into local[q] for the lane's ray q of the queue.
  void unlit_colors(std::span<Rgb> local) const;
  // The lanes' reflected and transmitted rays (Whitted::secondary_rays).
  void secondary_rays(SpawnLanes& out) const;

  size_t size() const { return count_; }
  uint32_t ray(size_t lane) const { return ray_[lane]; }  // the lane's place in the queue

private:
  // The emissive triangles' samples, after the punctual lights', appended to `out`, lane k's
  // named by hit_ids[k] (add_light).
  void area_light_samples(LaneLights& out, const uint32_t* hit_ids);
  // Fills L, distance, IL and lit for one punctual light or one area-light sample point per lane.
  void toward_light(const Light& light);
  void toward_area_sample(const AreaLight& area, int samples, const Vec3Lanes& points);
  // Whitted::add_light for every lane toward the light in L, distance, IL, lit: the terms, the
  // shadow rays, and those that count appended to `out`, each naming its hit by hit_ids[k] (the
  // lane's ray in the queue, or the lane itself for sort_by_lane).
  void add_light(LaneLights& out, const uint32_t* hit_ids);
  void sort_by_lane(const LaneLights& in, LaneLights& out) const;

  const Scene* scene_ = nullptr;
  std::span<const LaneMesh> meshes_;
  const Whitted* shading_ = nullptr;
  const WhittedOptions* options_ = nullptr;
  size_t light_passes_ = 0;  // lights a lane meets (add_light calls of light_samples)
  size_t count_ = 0;

  // The hits: their rays' places in the queue and directions, their triangles (corners, vertex
  // normals) and barycentrics. (Arrays of a multiple of 8 lanes: load() writes 8 at a time.)
  uint32_t ray_[kLanes];
  Vec3Lanes d_, p0_, p1_, p2_, n0_, n1_, n2_;
  float u_[kLanes], v_[kLanes];
  int mesh_[kLanes], triangle_[kLanes];
  // The surface points and what their materials give the light terms.
  Vec3Lanes position_, geometric_, N_;
  int32_t front_[kLanes];
  Vec3Lanes kd_, ks_;
  float shininess_[kLanes];
  int32_t shiny_[kLanes];  // ks > 0 and the specular term on: the highlight counts
  bool any_shiny_ = false;  // on some lane
  // What the secondary rays read: kr, kt and the index of refraction, and whether some lane
  // reflects, some transmits.
  Vec3Lanes kr_, kt_;
  float ior_[kLanes];
  bool any_reflective_ = false, any_transmissive_ = false;
  bool one_mesh_ = false;  // every lane hit the same mesh
  // One light at a time: the direction to it, its distance and IL, whether it can light the lane.
  Vec3Lanes L_, IL_;
  float distance_[kLanes], spot_[kLanes], highlight_[kLanes];
  int32_t lit_[kLanes];
  // Its terms and shadow rays (toward L_, up to tfar_) before those that count are collected.
  Vec3Lanes term_, origin_;
  float tfar_[kLanes];
  uint64_t seed_[kLanes];                  // each lane's seed, and its generator for the
  Random random_[kLanes];                  // area-light samples
  std::vector<glm::vec3> triangle_points_;  // scratch of triangle_samples()
  std::vector<Vec3Lanes> area_points_;     // sample j of one area light, per lane
  LaneLights by_light_;                    // the samples as made: light by light
};

}  // namespace luz::rt
