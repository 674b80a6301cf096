#pragma once
// Punctual lights as radiosity sources (SCENES.md: "they shoot first, as point sources").
//
// A point light of radiant intensity I (W/sr) sends the flux I d_omega into a small solid angle
// d_omega; all of it lands on the first surface in that direction. So a full cube of item
// buffers around the light (six 90-degree faces) gives, for each patch j, the solid angle
// omega_j it covers as seen from the light, and the flux it receives is
//     Phi_j = I * sum over j's pixels of spot(direction) * d_omega,
// with d_omega = dA / r^3 for a pixel at (x, y, 1) on a face (r^2 = x^2 + y^2 + 1). The mean
// irradiance of the patch is Phi_j / A_j: that is I cos(theta_j) / d^2 averaged over the patch,
// without ever evaluating the cosine (the projection does it). Only front faces count.
// The classroom attenuation 1/(c0 + c1 d + c2 d^2) is not physical; it scales each patch's flux
// by f_att(d) d^2 at the patch centre (1 for the physical 1/d^2).
//
// A patch that covers fewer than kResolvedPixels pixels of the cube would alias (it is hit by
// a pixel or missed): it gets the solid angle it should subtend, A cos(theta) / d^2 at its
// centre, when the cube's depth buffer (as a shadow map) says its centre sees the light.
#include <vector>

#include "core/light.h"
#include "gl/item_framebuffer.h"
#include "radiosity/hemicube.h"
#include "radiosity/item_buffer.h"
#include "radiosity/patch_mesh.h"

namespace luz {

class PointSource {
public:
  static constexpr int kFaces = 6;  // +X, -X, +Y, -Y, +Z, -Z
  static constexpr double kResolvedPixels = 32.0;

  // `resolution`: pixels across each cube face (same bounds as the hemicube's).
  PointSource(const PatchMesh& mesh, const PatchItems& items, int resolution);

  // For a point or spot light: the spot-weighted solid angle sum(spot * d_omega) each patch
  // covers, in steradians. Valid until the next call.
  const std::vector<FormFactor>& solid_angles(const Light& light);
  // sum(spot * d_omega) over the whole cube for the last light: its power is I times this
  // (4 pi for a point light).
  double emitted_solid_angle() const { return emitted_; }

  int resolution() const { return res_; }

private:
  const PatchMesh& mesh_;
  const PatchItems& items_;
  int res_;
  float far_;
  gl::ItemFramebuffer target_;
  std::vector<uint32_t> ids_;
  std::vector<double> sums_;
  std::vector<FormFactor> result_;
  double emitted_ = 0.0;
};

}  // namespace luz
