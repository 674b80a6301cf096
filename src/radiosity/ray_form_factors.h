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
// edge the next shots average out. Each ray counts with what the element it ends on sends
// (ShooterEmission), so V_ij is the visible share of the light the patch sends, not of its area.
// Unlike the hemicube there is no aliasing of small or distant elements (each is asked about
// directly), and no GL: a row is computed on TBB's threads.
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/light.h"
#include "core/scene.h"
#include "radiosity/hemicube.h"
#include "radiosity/patch_mesh.h"

namespace luz {

namespace rt { class EmbreeIntersector; }

// Where a shooting patch's light leaves from, as its visibility rays sample it: points spread over
// the patch by area, each weighted by what the element it lies in sends. A floor patch that a block
// stands on sends nothing from the covered part (its elements there got no light); a ray that ends
// there, blocked by the block, must not dim what the open part sends, or the light the open part
// reflects would be lost under the block (a few percent of the Cornell box's interreflection).
class ShooterEmission {
public:
  // `sent[k]`: what the patch's k-th element (in PatchMesh::members order) sends per square metre;
  // empty: every element the same. A patch has at least one element.
  ShooterEmission(const PatchMesh& mesh, size_t shooter, std::span<const Rgb> sent = {});

  struct Point {
    glm::vec3 position;
    float weight;  // what the element there sends (the mean of its channels)
  };
  // The point at (s, t) in [0, 1)^2: s picks the element by its share of the patch's area (so
  // strata of s are strata of area), the rest of s and t pick the point in it, uniformly.
  Point at(const PatchMesh& mesh, float s, float t) const;

private:
  std::span<const uint32_t> members_;
  std::vector<float> cumulative_;  // area of the first k + 1 elements, over the patch's area
  std::vector<float> weight_;
};

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
  // `sent`: what each of its elements sends (see ShooterEmission; empty: all alike).
  const std::vector<FormFactor>& row(size_t shooter, int rays, uint32_t seed, uint32_t shot,
                                     std::span<const Rgb> sent = {});
  // For a point or spot light: the spot-weighted solid angle each element covers seen from it,
  // spot(direction of its centre) x Omega (its triangle's exact solid angle, Van Oosterom &
  // Strackee 1983) x the fraction of m rays from the light to random points of the element that
  // arrive, so an element across a shadow's edge gets the part of it that is lit. The same
  // quantity as PointSource::solid_angles, without a cube of item buffers. A light shoots once,
  // so the solver gives it more rays than a patch.
  const std::vector<FormFactor>& solid_angles(const Light& light, int rays, uint32_t seed,
                                              uint32_t shot);
  // For a directional light (a sun, SCENES.md: parallel light): each element's area lit by it,
  // A_j cos(theta_j) (its area seen across the beam) x the fraction of m rays from stratified
  // points of the element toward the light that nothing blocks. E_perp times it is the flux the
  // element receives, so its irradiance is E_perp cos(theta) where the sun reaches it.
  const std::vector<FormFactor>& sunlit_areas(const Light& sun, int rays, uint32_t seed, uint32_t shot);
  // Rays traced for the last row or lights' solid angles.
  uint64_t last_rays() const { return last_rays_; }

  // One element's entry of row() and of solid_angles() (safe on any thread, for an element
  // added since the last row); `traced` grows by the rays they trace.
  double element_factor(size_t shooter, const ShooterEmission& emission, size_t element,
                        size_t rays, uint32_t seed, uint32_t shot, uint64_t& traced) const;
  double element_solid_angle(const Light& light, size_t element, size_t rays, uint32_t seed,
                             uint32_t shot, uint64_t& traced) const;
  double element_sunlit_area(const Light& sun, size_t element, size_t rays, uint32_t seed,
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
