// The hemicube (slide 37; Cohen and Greenberg 1985): item buffer through GL, delta form
// factors on the CPU.
//
// Sections: [delta form factors] [construction] [one row]
#include "radiosity/hemicube.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/i18n.h"
#include "gl/framebuffer.h"
#include "radiosity/gpu_row_sums.h"
#include "radiosity/radiosity_options.h"

namespace luz {

// ---- [delta form factors] ----------------------------------------------------------------------
// A pixel at (x, y, 1) on the top face, seen from the origin: cos(theta_i) = cos(theta_pixel)
// = 1/r with r^2 = x^2 + y^2 + 1, so dF = cos_i cos_p dA / (pi r^2) = dA / (pi r^4).
double top_delta_form_factor(double x, double y, double dA) {
  const double r2 = x * x + y * y + 1.0;
  return dA / (std::numbers::pi * r2 * r2);
}

// A pixel at (1, y, z) on a side face: cos_i = z/r (the patch normal is the height axis),
// cos_p = 1/r (the face's normal is the x axis), so dF = z dA / (pi r^4).
double side_delta_form_factor(double y, double z, double dA) {
  const double r2 = y * y + z * z + 1.0;
  return z * dA / (std::numbers::pi * r2 * r2);
}

// ---- [construction] ----------------------------------------------------------------------------
namespace {

int checked_resolution(int res) {
  if (res < kMinHemicubeRes || res > kMaxHemicubeRes || res % 2 != 0)
    throw Error(ErrorKind::bad_value, i18n::trf("hemicube resolution {} must be even and in {} .. {}", res,
                                                kMinHemicubeRes, kMaxHemicubeRes));
  return res;
}

float far_plane(const PatchMesh& mesh) {
  Bounds bounds;
  for (const glm::vec3& v : mesh.vertices) bounds.grow(v);
  return bounds.empty() ? 1.0f : 1.5f * glm::length(bounds.extent()) + 1e-3f;
}

}  // namespace

Hemicube::Rect Hemicube::face_rect(int face) const {
  if (face == 0) return {0, 0, res_, res_};
  const int side = face - 1;  // two half faces stacked in each of the atlas's next two columns
  return {res_ * (1 + side / 2), (side % 2) * (res_ / 2), res_, res_ / 2};
}

Hemicube::Hemicube(const PatchMesh& mesh, const PatchItems& items, int resolution,
                   HemicubePasses passes, HemicubeSums sums)
    : mesh_(mesh), items_(items), res_(checked_resolution(resolution)), passes_(passes),
      far_(far_plane(mesh)),
      target_(3 * res_, res_), sums_(mesh.size(), 0.0) {
  // The table of delta form factors, in the atlas's layout. Pixel centres at
  // -1 + (k + 1/2) * 2/res across a face; side faces keep the upper half, z in (0, 1).
  weights_.assign(size_t(atlas_width()) * size_t(atlas_height()), 0.0f);
  const double step = 2.0 / res_, dA = step * step;
  for (int face = 0; face < kFaces; ++face) {
    const Rect r = face_rect(face);
    for (int py = 0; py < r.height; ++py)
      for (int px = 0; px < r.width; ++px) {
        const double u = -1.0 + (px + 0.5) * step;
        const double v = face == 0 ? -1.0 + (py + 0.5) * step : (py + 0.5) * step;
        const double dF = face == 0 ? top_delta_form_factor(u, v, dA) : side_delta_form_factor(u, v, dA);
        weights_[size_t(r.y + py) * size_t(atlas_width()) + size_t(r.x + px)] = float(dF);
      }
  }
  if (sums == HemicubeSums::gpu) gpu_sums_ = std::make_unique<GpuRowSums>(weights_, atlas_width(), atlas_height());
}

Hemicube::~Hemicube() = default;

// ---- [one row] ---------------------------------------------------------------------------------
const std::vector<FormFactor>& Hemicube::row(size_t element, float rotation) {
  const Patch& p = mesh_.patches[element];
  return row(p.centre, p.normal, p.clearance, rotation);
}

const std::vector<FormFactor>& Hemicube::row(const glm::vec3& centre, const glm::vec3& normal,
                                             float clearance, float rotation) {
  const auto t0 = Clock::now();

  // The hemicube's frame: n the patch normal, (t, b) turned by `rotation` about it.
  const glm::vec3 n = normal;
  const glm::vec3 t0_axis = any_tangent(n), b0_axis = glm::cross(n, t0_axis);
  const glm::vec3 t = std::cos(rotation) * t0_axis + std::sin(rotation) * b0_axis;
  const glm::vec3 b = glm::cross(n, t);

  // The eye just off the patch, with a near plane as close: anything nearer than the patch's
  // clearance (centroid to nearest edge) can only be in the patch's own plane, which lies below
  // every face. A wall meeting this floor patch is at least the clearance away, so it is never
  // clipped and no light leaks along the join.
  const float near = eye_height(clearance);
  const glm::vec3 eye = centre + near * n;
  const glm::mat4 top_projection = glm::frustum(-near, near, -near, near, near, far_);
  const glm::mat4 side_projection = glm::frustum(-near, near, 0.0f, near, near, far_);
  struct Face { glm::vec3 forward, up; };
  const Face faces[kFaces] = {{n, b}, {t, n}, {-t, n}, {b, n}, {-b, n}};
  AtlasFace atlas[kFaces];
  for (int face = 0; face < kFaces; ++face) {
    const Rect r = face_rect(face);
    const glm::mat4 view = glm::lookAt(eye, eye + faces[face].forward, faces[face].up);
    atlas[face] = {(face == 0 ? top_projection : side_projection) * view, r.x, r.y, r.width, r.height};
  }

  auto kept = std::make_optional<gl::KeptBinding>();  // the caller's target, back once read
  target_.bind_and_clear();
  items_.begin();
  if (passes_ == HemicubePasses::one) {
    items_.draw_atlas(atlas, atlas_width(), atlas_height());
  } else {
    for (const AtlasFace& face : atlas) {
      glViewport(face.x, face.y, face.width, face.height);
      items_.draw(face.view_projection);
    }
  }
  items_.end();
  glFinish();
  const auto t1 = Clock::now();
  if (gpu_sums_) {
    const std::vector<float>& sums = gpu_sums_->sum(target_.id_texture(), mesh_.size());
    kept.reset();
    const auto t2 = Clock::now();
    row_.clear();
    for (size_t j = 0; j < sums.size(); ++j)
      if (sums[j] != 0.0f) row_.push_back({uint32_t(j), sums[j]});
    record_times(t0, t1, t2);
    return row_;
  }
  target_.read(ids_);
  kept.reset();
  const auto t2 = Clock::now();

  // F_ij = sum of the delta form factors of the pixels showing patch j.
  sums_.resize(mesh_.size(), 0.0);  // adaptive subdivision adds elements between rows
  touched_.clear();
  for (size_t pixel = 0; pixel < ids_.size(); ++pixel) {
    const uint32_t id = ids_[pixel];
    if (id == 0) continue;
    const uint32_t j = id - 1;
    if (sums_[j] == 0.0) touched_.push_back(j);
    sums_[j] += double(weights_[pixel]);
  }
  row_.clear();
  for (const uint32_t j : touched_) {
    row_.push_back({j, float(sums_[j])});
    sums_[j] = 0.0;
  }
  record_times(t0, t1, t2);
  return row_;
}

void Hemicube::record_times(Clock::time_point drawn_from, Clock::time_point read_from,
                            Clock::time_point summed_from) {
  const auto seconds = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  times_.draw = seconds(drawn_from, read_from);
  times_.read = seconds(read_from, summed_from);
  times_.accumulate = seconds(summed_from, Clock::now());
}

}  // namespace luz
