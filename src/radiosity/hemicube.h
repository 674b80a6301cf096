#pragma once
// Form factors by the hemicube (slide 37; Cohen and Greenberg, "The Hemi-Cube", SIGGRAPH 1985).
//
// From the centre of patch i, the scene is drawn onto the five faces of a half cube of
// half-width 1 standing on the patch at height 1: the full top face and four half side faces.
// Each pixel holds the ID of the nearest patch it sees (an item buffer). A pixel of area dA
// at (x, y) on the top face subtends the delta form factor
//     dF = dA / (pi (x^2 + y^2 + 1)^2),
// and a pixel at (y, z) on a side face (z the height above the patch plane)
//     dF = z dA / (pi (y^2 + z^2 + 1)^2).
// F_ij is the sum of the delta form factors of the pixels that show patch j. The deltas are the
// exact values at pixel centres and are never rescaled: their total over the hemicube is 1 only
// up to the discretisation, and rescaling a row to sum to 1 would hide a wrong weighting.
//
// All five faces go into one atlas texture (3 res x res pixels, layout in face_rect()), read
// back with a single glReadPixels per row, or summed on the GPU.
#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "gl/item_framebuffer.h"
#include "radiosity/item_buffer.h"
#include "radiosity/patch_mesh.h"

namespace luz {

class GpuRowSums;

// One entry of a form-factor row: F_ij for patch j.
struct FormFactor {
  uint32_t patch = 0;
  float value = 0.0f;
};

// Where a row's time goes, in seconds (for `luz bench radiosity`).
struct RowTimes {
  double draw = 0.0;        // drawing the five faces (until the GPU has finished)
  double read = 0.0;        // glReadPixels of the atlas (GPU sums: summing and reading the sums)
  double accumulate = 0.0;  // summing the delta form factors per patch (GPU sums: the row's list)
};

// Delta form factors of one pixel of area dA (half-width-1 hemicube), Cohen & Greenberg 1985.
double top_delta_form_factor(double x, double y, double dA);
double side_delta_form_factor(double y, double z, double dA);

class Hemicube {
public:
  static constexpr int kFaces = 5;  // top, then the sides along +t, -t, +b, -b

  // `items` (the patches on the GPU) must outlive the hemicube. `resolution`: pixels across the
  // top face, even, kMinHemicubeRes .. kMaxHemicubeRes (throws luz::Error bad_value otherwise).
  Hemicube(const PatchMesh& mesh, const PatchItems& items, int resolution,
           HemicubePasses passes = HemicubePasses::five, HemicubeSums sums = HemicubeSums::cpu);
  ~Hemicube();

  // Row i of the form-factor matrix: F_ij of every element j seen from the centre of element i.
  // `rotation` turns the hemicube about the normal (radians), to break aliasing.
  // The result stays valid until the next call.
  const std::vector<FormFactor>& row(size_t element, float rotation = 0.0f);
  // The same from any point on a surface: F from the point (centre, normal) to every element
  // it sees. `clearance`: how far the surface around the point reaches in its own plane (the
  // near plane is a tenth of it). Substructuring shoots a patch's row from its centroid.
  const std::vector<FormFactor>& row(const glm::vec3& centre, const glm::vec3& normal,
                                     float clearance, float rotation);

  // The eye stands this far above the surface point, on the normal (the near plane is as
  // close): what the hemicube sees is seen from there.
  static float eye_height(float clearance) { return 0.1f * clearance; }

  int resolution() const { return res_; }
  const RowTimes& last_times() const { return times_; }

  // The last row's item buffer (IDs + 1, 0 = nothing), for an overlay: a GL_R32UI texture of the
  // atlas, GL row order (row 0 at the bottom).
  int atlas_width() const { return 3 * res_; }
  int atlas_height() const { return res_; }
  unsigned item_texture() const { return target_.id_texture(); }
  struct Rect { int x, y, width, height; };
  Rect face_rect(int face) const;
  // The delta form factor of every atlas pixel (0 outside the faces), same layout.
  const std::vector<float>& delta_form_factors() const { return weights_; }

private:
  using Clock = std::chrono::steady_clock;
  void record_times(Clock::time_point drawn_from, Clock::time_point read_from,
                    Clock::time_point summed_from);

  const PatchMesh& mesh_;
  const PatchItems& items_;
  int res_;
  HemicubePasses passes_;
  float far_;
  std::unique_ptr<GpuRowSums> gpu_sums_;  // null: summed on the CPU
  gl::ItemFramebuffer target_;
  std::vector<float> weights_;
  std::vector<uint32_t> ids_;
  std::vector<double> sums_;       // per patch, zero between rows
  std::vector<uint32_t> touched_;  // patches with a non-zero sum in this row
  std::vector<FormFactor> row_;
  RowTimes times_;
};

}  // namespace luz
