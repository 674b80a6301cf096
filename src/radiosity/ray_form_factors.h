#pragma once
// The third form-factor method of slide 40's "multitud de métodos": form factors cast with rays
// (Wallace, Elmquist & Haines, "A Ray Tracing Algorithm for Progressive Radiosity", SIGGRAPH
// 1989). For the shooting patch i and every element j that faces it,
//
//   F_ij = V_ij * F(j -> i) * A_j / A_i
//
// with F(j -> i) the exact unoccluded factor from the element to the patch's triangle (Lambert's
// contour integral, element_form_factor.h) and V_ij the fraction of m rays between points of the
// element and points of the patch that no triangle of the scene blocks, traced through Embree's
// BVH. The patch's points are stratified over its area, so a shooting lamp casts penumbrae, not m
// hard shadows; every point moves at every shot (seeded), so what one shot gets wrong at a shadow's
// edge the next shots average out. Unlike the hemicube there is no aliasing of small or distant
// elements (each is asked about directly), and no GL: a row is computed on TBB's threads.
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/light.h"
#include "core/scene.h"
#include "radiosity/hemicube.h"
#include "radiosity/patch_mesh.h"

namespace luz {

namespace rt { class EmbreeIntersector; }

class RayFormFactors {
public:
  // Builds the BVH of the scene's triangles (the same triangles the mesh was cut from).
  RayFormFactors(const Scene& scene, const PatchMesh& mesh);
  ~RayFormFactors();
  RayFormFactors(const RayFormFactors&) = delete;
  RayFormFactors& operator=(const RayFormFactors&) = delete;

  // The row F_ij of shooting patch i (mesh.shooters[i]): the elements it reaches and their F_ij.
  // `rays` is m, the rays per element (1 .. kMaxVisibilityRays); `seed` and `shot` choose their
  // points: the same three give the same row.
  const std::vector<FormFactor>& row(size_t shooter, int rays, uint32_t seed, uint32_t shot);
  // For a point or spot light: the spot-weighted solid angle each element covers seen from it,
  // spot(direction of its centre) x Omega (its triangle's exact solid angle, Van Oosterom &
  // Strackee 1983) x the fraction of m rays from the light to random points of the element that
  // arrive, so an element across a shadow's edge gets the part of it that is lit. The same
  // quantity as PointSource::solid_angles, without a cube of item buffers. A light shoots once,
  // so the solver gives it more rays than a patch.
  const std::vector<FormFactor>& solid_angles(const Light& light, int rays, uint32_t seed,
                                              uint32_t shot);
  // Rays traced for the last row or lights' solid angles.
  uint64_t last_rays() const { return last_rays_; }

  // One element's entry of row() and of solid_angles() (safe on any thread, for an element
  // added since the last row); `traced` grows by the rays they trace.
  double element_factor(size_t shooter, size_t element, size_t rays, uint32_t seed, uint32_t shot,
                        uint64_t& traced) const;
  double element_solid_angle(const Light& light, size_t element, size_t rays, uint32_t seed,
                             uint32_t shot, uint64_t& traced) const;

private:
  template <typename Value>
  const std::vector<FormFactor>& for_each_element(const Value& value);

  const PatchMesh& mesh_;
  float offset_;  // how far a ray's ends sit off their surfaces (the scene's size x 1e-5)
  std::unique_ptr<rt::EmbreeIntersector> bvh_;
  std::vector<float> values_;  // per element, F_ij of the last row (0: not reached)
  std::vector<FormFactor> row_;
  uint64_t last_rays_ = 0;
};

}  // namespace luz
