// The wavefront's shading lanes (hit_lanes.h). Sections: [the hits] [lights] [colour] [rays]
// Each vectorised loop reads and writes the lanes' arrays and loop-invariant locals only, so the
// compiler can see that no store of one lane touches another's input.
#include "raytracing/hit_lanes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <numbers>
#include <type_traits>

#include <glm/geometric.hpp>

#include "raytracing/hit_math.h"
#include "raytracing/vector_clones.h"

namespace luz::rt {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// k at k: each lane's own index.
constexpr std::array<uint32_t, kLanes> kLaneIndices = [] {
  std::array<uint32_t, kLanes> indices{};
  for (size_t k = 0; k < kLanes; ++k) indices[k] = uint32_t(k);
  return indices;
}();

// GCC's and Clang's vector types: their operations compile to SSE instructions in the baseline
// clone of a LUZ_VECTOR_CLONES function and to AVX ones in its AVX2 and AVX-512 clones.
using Float4 = float __attribute__((vector_size(16)));
using Float8 = float __attribute__((vector_size(32)));

Float4 load_row(const std::byte* row) {
  Float4 r;
  std::memcpy(&r, row, sizeof r);
  return r;
}

// Eight rows of four floats, lying anywhere in memory, into four arrays of eight lanes:
// x[k] = row k's first float, y[k] its second, z[k] its third, w[k] its fourth (z and w where
// given); row k starts at rows[k] + offset bytes. A transpose in registers: eight 16-byte loads,
// twelve shuffles and four 32-byte stores, where copying float by float takes 32 loads and 32
// stores, and leaves eight-lane loops reading values stored one at a time (which stalls them:
// the processor cannot forward several small stores to one wide load).
[[gnu::always_inline]] inline void transpose_rows(const std::byte* const* rows, size_t offset, void* x,
                                                  void* y, void* z, void* w) {
  // Row i in the low half, row i + 4 in the high half: each half is then a 4x4 transpose.
  // (Plain statements, no helper taking or returning a Float8: the baseline clone has no such
  // registers to pass it in.)
#define LUZ_ROW_PAIR(i)                                                                          \
  __builtin_shufflevector(load_row(rows[i] + offset), load_row(rows[(i) + 4] + offset), 0, 1, 2, 3, 4, 5, \
                          6, 7)
  const Float8 r0 = LUZ_ROW_PAIR(0), r1 = LUZ_ROW_PAIR(1), r2 = LUZ_ROW_PAIR(2), r3 = LUZ_ROW_PAIR(3);
#undef LUZ_ROW_PAIR
  const Float8 xy01 = __builtin_shufflevector(r0, r1, 0, 8, 1, 9, 4, 12, 5, 13);
  const Float8 xy23 = __builtin_shufflevector(r2, r3, 0, 8, 1, 9, 4, 12, 5, 13);
  const Float8 zw01 = __builtin_shufflevector(r0, r1, 2, 10, 3, 11, 6, 14, 7, 15);
  const Float8 zw23 = __builtin_shufflevector(r2, r3, 2, 10, 3, 11, 6, 14, 7, 15);
  const Float8 xs = __builtin_shufflevector(xy01, xy23, 0, 1, 8, 9, 4, 5, 12, 13);
  const Float8 ys = __builtin_shufflevector(xy01, xy23, 2, 3, 10, 11, 6, 7, 14, 15);
  const Float8 zs = __builtin_shufflevector(zw01, zw23, 0, 1, 8, 9, 4, 5, 12, 13);
  const Float8 ws = __builtin_shufflevector(zw01, zw23, 2, 3, 10, 11, 6, 7, 14, 15);
  std::memcpy(x, &xs, sizeof xs);
  std::memcpy(y, &ys, sizeof ys);
  if (z) std::memcpy(z, &zs, sizeof zs);
  if (w) std::memcpy(w, &ws, sizeof ws);
}

// The rows load() transposes out of a Hit and a Ray.
static_assert(offsetof(Hit, triangle) == offsetof(Hit, mesh) + 4 && offsetof(Hit, u) == offsetof(Hit, mesh) + 8);
static_assert(offsetof(Hit, v) == offsetof(Hit, mesh) + 12 && sizeof(int) == sizeof(float));
static_assert(offsetof(Ray, tfar) == offsetof(Ray, direction) + 12);

}  // namespace

std::vector<float> triangle_corners(const Mesh& mesh) {
  std::vector<float> corners;
  corners.reserve(mesh.indices.size() * 6 + 2);
  for (size_t t = 0; 3 * t + 2 < mesh.indices.size(); ++t)
    for (const std::vector<glm::vec3>* attribute : {&mesh.positions, &mesh.normals})
      for (size_t c = 0; c < 3; ++c) {
        const glm::vec3& v = (*attribute)[mesh.indices[3 * t + c]];
        corners.insert(corners.end(), {v.x, v.y, v.z});
      }
  corners.insert(corners.end(), {0.0f, 0.0f});
  return corners;
}

std::vector<LaneMesh> lane_meshes(const Scene& scene, const Whitted& shading, const WhittedOptions& options,
                                  std::span<const std::vector<float>> corners) {
  const bool diffuse = options.terms.diffuse && !shading.diffuse_source();
  std::vector<LaneMesh> meshes;
  meshes.reserve(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    const Material& o = shading.surfaces().material_of(mesh);
    meshes.push_back({.corners = corners[m].data(),
                      .material = &o,
                      .kd_uniform = !diffuse || shading.surfaces().kd_is_uniform(o, mesh),
                      .kd = o.kd,
                      .ks = o.ks,
                      .kr = o.kr,
                      .kt = o.kt,
                      .ambient = options.terms.ambient ? scene.ambient * o.ka : Rgb(0.0f),
                      .emission = options.terms.emission ? o.emission : Rgb(0.0f),
                      .emission_textured = options.terms.emission && o.is_emissive() &&
                                           scene.shown_emission_texture(mesh, o) >= 0,
                      .shininess = o.shininess,
                      .ior = o.ior,
                      .shiny = options.terms.specular && positive(o.ks),
                      .reflective = positive(o.kr),
                      .transmissive = positive(o.kt)});
  }
  return meshes;
}

void HitLanes::shade_with(const Scene& scene, const Whitted& shading, const WhittedOptions& options,
                          std::span<const LaneMesh> meshes) {
  scene_ = &scene;
  shading_ = &shading;
  options_ = &options;
  meshes_ = meshes;
  // The lights each lane meets: the enabled punctual ones, then every area light's samples.
  light_passes_ = size_t(std::max(1, options.light_samples)) * scene.area_lights.size();
  for (const Light& light : scene.lights) light_passes_ += light.enabled ? 1 : 0;
}

// ---- [the hits] ---------------------------------------------------------------------------------
LUZ_VECTOR_CLONES
void HitLanes::load(std::span<const uint32_t> queue, std::span<const Ray> rays, std::span<const Hit> hits,
                    std::span<const uint64_t> seeds) {
  count_ = queue.size();
  const size_t n = count_;
  // Where each lane's hit, ray direction and triangle lie: rows to transpose into the lanes.
  // Lanes past the last (up to a multiple of 8) repeat the first lane's rows.
  const std::byte* hit_rows[kLanes];
  const std::byte* direction_rows[kLanes];
  const std::byte* triangle_rows[kLanes];
  for (size_t k = 0; k < n; ++k) {
    const Hit& hit = hits[queue[k]];
    hit_rows[k] = reinterpret_cast<const std::byte*>(&hit.mesh);
    direction_rows[k] = reinterpret_cast<const std::byte*>(&rays[queue[k]].direction);
    const float* corners = meshes_[size_t(hit.mesh)].corners + 18 * size_t(hit.triangle);
    triangle_rows[k] = reinterpret_cast<const std::byte*>(corners);
    ray_[k] = queue[k];
    seed_[k] = seeds[queue[k]];
  }
  for (size_t k = n; k % 8 != 0; ++k) {
    hit_rows[k] = hit_rows[0];
    direction_rows[k] = direction_rows[0];
    triangle_rows[k] = triangle_rows[0];
  }
  // Each hit's mesh, triangle and barycentrics, its ray's direction, and its triangle's corners
  // and vertex normals, 8 lanes at a time.
  for (size_t k = 0; k < n; k += 8) {
    transpose_rows(hit_rows + k, 0, mesh_ + k, triangle_ + k, u_ + k, v_ + k);
    transpose_rows(direction_rows + k, 0, d_.x + k, d_.y + k, d_.z + k, nullptr);
    // The triangle's 18 floats in five rows of four: p0 p1.x, p1.yz p2.xy, p2.z n0, n1 n2.x,
    // n2.yz (and two floats past it, dropped).
    const std::byte* const* rows = triangle_rows + k;
    transpose_rows(rows, 0, p0_.x + k, p0_.y + k, p0_.z + k, p1_.x + k);
    transpose_rows(rows, 16, p1_.y + k, p1_.z + k, p2_.x + k, p2_.y + k);
    transpose_rows(rows, 32, p2_.z + k, n0_.x + k, n0_.y + k, n0_.z + k);
    transpose_rows(rows, 48, n1_.x + k, n1_.y + k, n1_.z + k, n2_.x + k);
    transpose_rows(rows, 64, n2_.y + k, n2_.z + k, nullptr, nullptr);
  }
  // "calcular la normal", every lane at once.
  for (size_t k = 0; k < n; ++k) {
    const SurfaceGeometry g =
        surface_geometry(p0_[k], p1_[k], p2_[k], n0_[k], n1_[k], n2_[k], u_[k], v_[k], d_[k]);
    position_.set(k, g.position);
    geometric_.set(k, g.geometric);
    N_.set(k, g.N);
    front_[k] = g.front;
  }
  // What the light terms and the secondary rays read of each material: kd (x COLOR_0 x the
  // texture), ks and the exponent, kr, kt and the index of refraction. Where every lane hit the
  // same mesh of uniform kd (most chunks of a first generation), its factors for all lanes at
  // once, and only those a later step reads: ks and the exponent for a shiny material, kr, kt and
  // the index for one that reflects or transmits (a matte wall's chunk fills kd alone).
  bool one_mesh = n > 0;
  for (size_t k = 0; k < n; ++k) one_mesh &= mesh_[k] == mesh_[0];
  one_mesh_ = one_mesh;
  if (one_mesh && meshes_[size_t(mesh_[0])].kd_uniform) {
    const LaneMesh& m = meshes_[size_t(mesh_[0])];
    const auto fill = [n](Vec3Lanes& lanes, const glm::vec3& v) {
      std::fill_n(lanes.x, n, v.x);
      std::fill_n(lanes.y, n, v.y);
      std::fill_n(lanes.z, n, v.z);
    };
    fill(kd_, m.kd);
    if (m.shiny) {
      fill(ks_, m.ks);
      std::fill_n(shininess_, n, m.shininess);
      std::fill_n(shiny_, n, m.shiny);
    }
    if (m.reflective || m.transmissive) {
      fill(kr_, m.kr);
      fill(kt_, m.kt);
      std::fill_n(ior_, n, m.ior);
    }
    any_shiny_ = m.shiny != 0;
    any_reflective_ = m.reflective;
    any_transmissive_ = m.transmissive;
    return;
  }
  bool shiny = false, reflective = false, transmissive = false;
  for (size_t k = 0; k < n; ++k) {
    const LaneMesh& m = meshes_[size_t(mesh_[k])];
    if (m.kd_uniform) {
      kd_.set(k, m.kd);
    } else {
      const Mesh& mesh = scene_->meshes[size_t(mesh_[k])];
      const glm::vec2 barycentrics(u_[k], v_[k]);
      const glm::vec2 uv = mesh.uv_at(size_t(triangle_[k]), barycentrics);
      kd_.set(k, shading_->surfaces().kd_at(*m.material, mesh_[k], triangle_[k], barycentrics, uv));
    }
    ks_.set(k, m.ks);
    shininess_[k] = m.shininess;
    shiny_[k] = m.shiny;
    kr_.set(k, m.kr);
    kt_.set(k, m.kt);
    ior_[k] = m.ior;
    shiny |= m.shiny != 0;
    reflective |= m.reflective;
    transmissive |= m.transmissive;
  }
  any_shiny_ = shiny;
  any_reflective_ = reflective;
  any_transmissive_ = transmissive;
}

// ---- [lights] -----------------------------------------------------------------------------------
// Whitted::light_samples, light by light: the punctual lights, then each emissive triangle's
// samples, so that each lane meets its lights in the recursion's order.
void HitLanes::light_samples(LaneLights& out) {
  // With a single light the samples come lane by lane already: straight into `out`, named by
  // their rays in the queue. Else by their lanes, for the sort.
  const bool one = light_passes_ == 1;
  LaneLights& made = one ? out : by_light_;
  const uint32_t* hit_ids = one ? ray_ : kLaneIndices.data();
  by_light_.size = 0;
  for (size_t i = 0; i < scene_->lights.size(); ++i) {
    if (!scene_->lights[i].enabled) continue;
    toward_light(scene_->lights[i]);
    add_light(made, hit_ids);
  }
  area_light_samples(made, hit_ids);
  if (!one) sort_by_lane(by_light_, out);
}

void HitLanes::area_light_samples(LaneLights& out, const uint32_t* hit_ids) {
  if (scene_->area_lights.empty()) return;
  const int samples = std::max(1, options_->light_samples);
  if (samples > 1)
    for (size_t k = 0; k < count_; ++k) random_[k] = Random(seed_[k]);
  for (const AreaLight& area : scene_->area_lights) {
    area_points_.resize(size_t(samples));
    if (samples == 1) {
      // The centroid, for every lane: exactly the rasteriser's light.
      for (size_t k = 0; k < count_; ++k) area_points_[0].set(k, area.centroid);
    } else {
      // N-rooks points on the emitter, each lane's from its own generator (scalar: the
      // permutation). A lane on the emitter itself draws none, as in the recursion.
      const Mesh& mesh = scene_->meshes[size_t(area.mesh)];
      const size_t t = size_t(area.triangle);
      const glm::vec3 &a = mesh.positions[mesh.indices[3 * t]], &b = mesh.positions[mesh.indices[3 * t + 1]],
                      &c = mesh.positions[mesh.indices[3 * t + 2]];
      for (size_t k = 0; k < count_; ++k) {
        if (mesh_[k] == area.mesh && triangle_[k] == area.triangle) continue;
        triangle_samples(a, b, c, samples, random_[k], triangle_points_);
        for (int j = 0; j < samples; ++j) area_points_[size_t(j)].set(k, triangle_points_[size_t(j)]);
      }
    }
    for (int j = 0; j < samples; ++j) {
      toward_area_sample(area, samples, area_points_[size_t(j)]);
      add_light(out, hit_ids);
    }
  }
}

// A punctual light: IL = I * f_att(d) * spot / pi, or E_perp / pi for a directional one.
LUZ_VECTOR_CLONES
void HitLanes::toward_light(const Light& light) {
  const size_t n = count_;
  if (light.type == LightType::directional) {
    const glm::vec3 L = -glm::normalize(light.direction);
    const Rgb IL = light.intensity / kPi;
    for (size_t k = 0; k < n; ++k) {
      L_.set(k, L);
      IL_.set(k, IL);
      distance_[k] = kInfinity;
      lit_[k] = true;
    }
    return;
  }
  const glm::vec3 origin = light.position;
  for (size_t k = 0; k < n; ++k) {
    const glm::vec3 to_light = origin - position_[k];
    const float d = glm::length(to_light);
    L_.set(k, to_light / d);
    distance_[k] = d;
    lit_[k] = !(d <= 0.0f);
  }
  // The spot's cone (scalar: Warn's exponent calls pow); 1 for a point light.
  if (light.type == LightType::spot)
    for (size_t k = 0; k < n; ++k) spot_[k] = light.spot_factor(-L_[k]);
  else
    std::fill(spot_, spot_ + n, 1.0f);
  const Rgb intensity = light.intensity;
  const Attenuation attenuation = light.attenuation;
  for (size_t k = 0; k < n; ++k) IL_.set(k, intensity * attenuation.factor(distance_[k]) * spot_[k] / kPi);
}

// One sample point y of an emissive triangle per lane (of `samples`): it stands for area A/N and
// lights like a point of intensity Le (A/N) cos(theta_e) (SCENES.md).
LUZ_VECTOR_CLONES
void HitLanes::toward_area_sample(const AreaLight& area, int samples, const Vec3Lanes& points) {
  const size_t n = count_;
  const glm::vec3 normal = area.normal;
  const Rgb radiance = area.radiance;
  const float share = area.area / float(samples);
  const int mesh = area.mesh, triangle = area.triangle;
  for (size_t k = 0; k < n; ++k) {
    const glm::vec3 to_light = points[k] - position_[k];
    const float d = glm::length(to_light);
    const glm::vec3 L = to_light / d;
    const float cos_theta_e = std::max(glm::dot(normal, -L), 0.0f);  // dark behind it
    L_.set(k, L);
    IL_.set(k, radiance * share * cos_theta_e / (d * d) / kPi);
    distance_[k] = d;
    // An emitter cannot light itself.
    lit_[k] = !(d < 1e-6f) & !((mesh_[k] == mesh) & (triangle_[k] == triangle));
  }
}

LUZ_VECTOR_CLONES
void HitLanes::add_light(LaneLights& out, const uint32_t* hit_ids) {
  const size_t n = count_;
  const bool diffuse = options_->terms.diffuse && !shading_->diffuse_source();
  const bool blinn = options_->terms.blinn;
  // "si (L·N) > 0", and cos(alpha) of every lane.
  for (size_t k = 0; k < n; ++k) {
    const float cos_theta = glm::dot(N_[k], L_[k]);
    lit_[k] = lit_[k] & !(cos_theta <= 0.0f) & positive(IL_[k]);
  }
  // cos^n(alpha), where a highlight counts; on lanes of matte materials only (a Cornell box)
  // nothing to compute.
  if (any_shiny_) {
    for (size_t k = 0; k < n; ++k) {
      const float power = cos_power(cos_alpha(N_[k], L_[k], -d_[k], blinn), shininess_[k]);
      highlight_[k] = (shiny_[k] & lit_[k]) != 0 ? power : 0.0f;
    }
  }

  // The terms of every lane, then their shadow rays; those that count appended in lane order.
  // (Three loops, not one: GCC 12 vectorises each of them, and gives up on the three together.)
  const size_t first = out.size;
  if (out.shadow.size() < first + n) {
    out.shadow.resize(first + n + kLanes);
    out.hit.resize(out.shadow.size());
    out.term.resize(out.shadow.size());
  }
  // A lane's term: its diffuse part, then its specular one where some lane is shiny (else load()
  // left ks and the highlight unset: a matte chunk adds no zeros); and whether the term lights
  // the lane's hit, from its factors (lights_the_hit).
  const auto terms = [&](size_t k, auto specular) __attribute__((always_inline)) {
    const float cos_theta = glm::dot(N_[k], L_[k]);
    const Rgb IL = IL_[k];
    const Rgb I_D = IL * kd_[k] * cos_theta;  // in the hybrid radiosity has it already
    Rgb t(0.0f);
    t += select(diffuse, I_D, Rgb(0.0f));
    const Rgb kd = select(diffuse, kd_[k], Rgb(0.0f));
    if constexpr (specular) {
      const Rgb I_S = IL * ks_[k] * highlight_[k];
      t += select(shiny_[k] != 0, I_S, Rgb(0.0f));
      lit_[k] = lit_[k] & lights_the_hit(kd, shiny_[k] != 0, highlight_[k]);
    } else {
      lit_[k] = lit_[k] & lights_the_hit(kd, false, 0.0f);
    }
    term_.set(k, t);
  };
  if (any_shiny_)
    for (size_t k = 0; k < n; ++k) terms(k, std::true_type{});
  else
    for (size_t k = 0; k < n; ++k) terms(k, std::false_type{});
  for (size_t k = 0; k < n; ++k) {
    const Ray shadow = shadow_ray(position_[k], geometric_[k], L_[k], distance_[k]);
    origin_.set(k, shadow.origin);
    tfar_[k] = shadow.tfar;
  }
  size_t m = first;
  for (size_t k = 0; k < n; ++k) {
    out.shadow[m] = Ray{origin_[k], L_[k], tfar_[k]};
    out.hit[m] = hit_ids[k];
    out.term[m] = term_[k];
    m += lit_[k] ? 1 : 0;
  }
  out.size = m;
}

// The samples lane by lane, each lane's in the order of its lights, as the recursion makes them.
// Embree may answer a shadow ray that grazes an edge differently with other rays beside it in a
// packet, so the stream holds the recursion's rays in the recursion's order: the same shadows.
void HitLanes::sort_by_lane(const LaneLights& in, LaneLights& out) const {
  uint32_t first[kLanes + 1] = {};  // lane k's samples go to first[k] ...
  first[0] = uint32_t(out.size);
  for (size_t j = 0; j < in.size; ++j) ++first[in.hit[j] + 1];
  for (size_t k = 0; k < count_; ++k) first[k + 1] += first[k];
  out.size += in.size;
  if (out.shadow.size() < out.size) {
    out.shadow.resize(2 * out.size);
    out.hit.resize(out.shadow.size());
    out.term.resize(out.shadow.size());
  }
  for (size_t j = 0; j < in.size; ++j) {
    const uint32_t to = first[in.hit[j]]++;
    out.shadow[to] = in.shadow[j];
    out.hit[to] = ray_[in.hit[j]];
    out.term[to] = in.term[j];
  }
}

// ---- [colour] -----------------------------------------------------------------------------------
LUZ_VECTOR_CLONES
void HitLanes::unlit_colors(std::span<Rgb> local) const {
  const DiffuseSource* diffuse = shading_->diffuse_source();
  if (!diffuse) {
    // An emitter shows Le on its front. Where all lanes hit one mesh, its terms are read once
    // (the loop-invariant choice of lane lets the compiler take them out of the loop).
    for (size_t k = 0; k < count_; ++k) {
      const LaneMesh& m = meshes_[size_t(mesh_[one_mesh_ ? 0 : k])];
      local[ray_[k]] = m.ambient + select(front_[k] != 0, m.emission, Rgb(0.0f));
    }
    // An emissive texture: the texel where the lane hit.
    for (size_t k = 0; k < count_; ++k)
      if (front_[k] != 0 && meshes_[size_t(mesh_[k])].emission_textured)
        local[ray_[k]] += scene_->emission_at(mesh_[k], size_t(triangle_[k]), glm::vec2(u_[k], v_[k])) -
                          meshes_[size_t(mesh_[k])].emission;
    return;
  }
  for (size_t k = 0; k < count_; ++k) {
    const bool lit = options_->terms.diffuse && front_[k];
    local[ray_[k]] = lit ? diffuse->diffuse_radiance(mesh_[k], triangle_[k], glm::vec2(u_[k], v_[k])) : Rgb(0.0f);
  }
}

// ---- [rays] -------------------------------------------------------------------------------------
LUZ_VECTOR_CLONES
void HitLanes::secondary_rays(SpawnLanes& out) const {
  // Every lane's rays, computed for all lanes at once (a lane that spawns none is left out when
  // they are queued): where a chunk's lanes mix mirrors and walls this costs no more than
  // gathering the mirrors' lanes first. A chunk where no lane reflects or transmits computes
  // nothing.
  out.any = any_reflective_ || any_transmissive_;
  out.any_transmits = any_transmissive_;
  if (!out.any) return;
  const size_t n = count_;
  // "si o es reflexivo": R := rayo de reflexión, where it leaves, which way.
  for (size_t k = 0; k < n; ++k) {
    out.kr.set(k, kr_[k]);
    out.kt.set(k, kt_[k]);
    out.reflected_origin.set(k, offset_origin(position_[k], geometric_[k]));
    out.reflected_direction.set(k, keep_on_side(reflect(d_[k], N_[k]), geometric_[k]));
    out.reflects[k] = positive(kr_[k]);
    out.transmits[k] = false;
  }
  // Where some lane transmits: kr and kt split by Fresnel or total internal reflection (a lane
  // that transmits nothing keeps its kr, split_at adds kt x F = 0 to it), and "si o es
  // transmisivo y no hay reflexión interna total": T := rayo de refracción.
  // GCC 12 vectorises these loops only as written: Fresnel on or off as a constant (not a flag
  // the loop chooses by), the lambda inlined into each loop (an outlined call is scalar), and the
  // flags in a loop of their own (with them the split's loop writes too many arrays).
  if (!any_transmissive_) return;
  const auto split = [&](size_t k, auto fresnel) __attribute__((always_inline)) {
    const Split s = split_at(kr_[k], kt_[k], ior_[k], front_[k] != 0, d_[k], N_[k], fresnel);
    out.kr.set(k, s.kr);
    out.kt.set(k, s.kt);
    out.transmits[k] = s.refracts;
    out.transmitted_direction.set(k, s.T);
  };
  if (options_->fresnel)
    for (size_t k = 0; k < n; ++k) split(k, std::true_type{});
  else
    for (size_t k = 0; k < n; ++k) split(k, std::false_type{});
  for (size_t k = 0; k < n; ++k) {
    out.reflects[k] = positive(out.kr[k]);
    out.transmits[k] = out.transmits[k] & positive(out.kt[k]);
  }
  for (size_t k = 0; k < n; ++k) {
    out.transmitted_origin.set(k, offset_origin(position_[k], -geometric_[k]));
    out.transmitted_direction.set(k, keep_on_side(out.transmitted_direction[k], -geometric_[k]));
  }
}

}  // namespace luz::rt
