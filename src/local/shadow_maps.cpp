// Shadow maps: which layer each light gets, the CPU twin of the shaders' lookup, and the GL
// passes that fill the layers (shaders/shadow.vert, shadow.frag).
//
// Sections: [the CPU twin] [layout] [the GL maps]
#include "local/shadow_maps.h"

#include "local/cube_face.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/i18n.h"
#include "gl/framebuffer.h"
#include "gl/functions.h"
#include "gl/mesh_buffers.h"
#include "gl/shader.h"
#include "gl/texture_limits.h"

namespace luz {

// ---- [the CPU twin] ----------------------------------------------------------------------------
glm::ivec3 cube_texel(const glm::vec3& D, int size) {
  // The faces were rendered with the view matrices of face_view(), whose image axes are exactly
  // the specification's sc and tc.
  const CubeFacePoint p = cube_face_point(D);
  return {std::clamp(int(std::floor(p.s * float(size))), 0, size - 1),
          std::clamp(int(std::floor(p.t * float(size))), 0, size - 1), p.face};
}

float shadow_factor(const ShadowLookup& maps, const ShadowView& view, const glm::vec3& P,
                    const glm::vec3& N, float cos_theta) {
  if (view.kind == ShadowKind::none || maps.size == 0 || !maps.texel) return 1.0f;
  const Shadows& settings = maps.settings;
  // The world size of one texel at P: the map's resolution at this distance.
  const float texel = view.kind == ShadowKind::orthographic ? view.texel
                                                             : view.texel * glm::length(P - view.origin);
  // Normal offset: look the map up a little off the surface, toward the side that is lit.
  const glm::vec3 Q = P + N * (settings.normal_offset * texel);
  // Slope-scaled bias: a surface seen at grazing angle by the light spans more depth per texel.
  const float sin_theta = std::sqrt(std::max(1.0f - cos_theta * cos_theta, 0.0f));
  const float tan_theta = std::min(sin_theta / std::max(cos_theta, 1e-4f), 10.0f);
  const float bias = settings.constant_bias + settings.slope_bias * texel * tan_theta;

  glm::ivec3 at;
  float measured = 0.0f;
  if (view.kind == ShadowKind::cube) {
    const glm::vec3 D = Q - view.origin;
    measured = glm::length(D);
    at = cube_texel(D, maps.size);
    at.z += view.layer;
  } else {
    const glm::vec4 clip = view.matrix * glm::vec4(Q, 1.0f);
    if (clip.w <= 0.0f) return 1.0f;  // behind a spot: outside its cone anyway
    const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
    if (uv.x < 0.0f || uv.y < 0.0f || uv.x >= 1.0f || uv.y >= 1.0f) return 1.0f;  // off the map
    at = glm::ivec3(int(std::floor(uv.x * float(maps.size))), int(std::floor(uv.y * float(maps.size))),
                    view.layer);
    measured = view.kind == ShadowKind::orthographic ? glm::dot(Q, view.direction)
                                                     : glm::length(Q - view.origin);
  }
  const float stored = maps.texel(at.z, at.x, at.y);
  return measured - bias > stored ? 0.0f : 1.0f;  // S_i
}

// ---- [layout] ----------------------------------------------------------------------------------
namespace {

// The six faces in GL's order, with the up vectors that make their image axes sc, tc of the
// cube-map rule (the same as rendering into a GL cube map).
const glm::vec3 face_forward[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const glm::vec3 face_up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};

struct Range {
  float near, far;
};

// Near and far planes for a map seen from `origin`: past the farthest corner of the scene.
Range depth_range(const Bounds& bounds, const glm::vec3& origin) {
  float farthest = 1e-3f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p(corner & 1 ? bounds.max.x : bounds.min.x, corner & 2 ? bounds.max.y : bounds.min.y,
                      corner & 4 ? bounds.max.z : bounds.min.z);
    farthest = std::max(farthest, glm::length(p - origin));
  }
  return {1e-4f * farthest, 1.5f * farthest};
}

glm::vec3 any_perpendicular_up(const glm::vec3& direction) {
  return std::abs(direction.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

ShadowView cube_view(const glm::vec3& origin, int layer, int size) {
  ShadowView view;
  view.kind = ShadowKind::cube;
  view.layer = layer;
  view.origin = origin;
  view.texel = 2.0f / float(size);  // a face spans 2 units at distance 1
  return view;
}

ShadowView spot_view(const Light& light, const Bounds& bounds, int layer, int size) {
  ShadowView view;
  view.kind = ShadowKind::perspective;
  view.layer = layer;
  view.origin = light.position;
  const glm::vec3 direction = glm::normalize(light.direction);
  const float fov = std::max(2.0f * light.outer_cone * 1.05f, 0.05f);  // a margin past the cone
  const Range range = depth_range(bounds, light.position);
  view.matrix = glm::perspective(fov, 1.0f, range.near, range.far) *
                glm::lookAt(light.position, light.position + direction, any_perpendicular_up(direction));
  view.texel = 2.0f * std::tan(0.5f * fov) / float(size);
  return view;
}

// An orthographic map fitted to the scene's bounds as the light sees them.
ShadowView directional_view(const Light& light, const Bounds& bounds, int layer, int size) {
  ShadowView view;
  view.kind = ShadowKind::orthographic;
  view.layer = layer;
  view.direction = glm::normalize(light.direction);
  const float radius = 0.5f * glm::length(bounds.extent()) + 1e-3f;
  const glm::vec3 eye = bounds.centre() - view.direction * (2.0f * radius);
  const glm::mat4 look = glm::lookAt(eye, bounds.centre(), any_perpendicular_up(view.direction));
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p(corner & 1 ? bounds.max.x : bounds.min.x, corner & 2 ? bounds.max.y : bounds.min.y,
                      corner & 4 ? bounds.max.z : bounds.min.z);
    const glm::vec3 q = glm::vec3(look * glm::vec4(p, 1.0f));
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const glm::vec2 margin = 0.01f * (glm::vec2(hi) - glm::vec2(lo)) + 1e-3f;
  lo -= glm::vec3(margin, 0.0f);
  hi += glm::vec3(margin, 0.0f);
  // The camera looks down -Z: depths run from -hi.z to -lo.z.
  view.matrix = glm::ortho(lo.x, hi.x, lo.y, hi.y, -hi.z - 1e-3f, -lo.z + 1e-3f) * look;
  view.texel = std::max(hi.x - lo.x, hi.y - lo.y) / float(size);
  return view;
}

}  // namespace

// ---- [the GL maps] -----------------------------------------------------------------------------
ShadowMaps::ShadowMaps()
    : program_(std::make_unique<gl::Program>(std::vector<std::string>{"shadow.vert", "shadow.frag"})) {}

ShadowMaps::~ShadowMaps() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  if (texture_) glDeleteTextures(1, &texture_);
}

void ShadowMaps::allocate(int size, int layers) {
  layers = std::max(layers, 1);  // a valid texture even with no light to shadow
  if (size == size_ && layers == layers_) return;
  if (!texture_) glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D_ARRAY, texture_);
  if (!gl::allocate_array(GL_R32F, GL_RED, GL_FLOAT, size, layers)) {
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    const int largest =
        gl::largest_allocatable_square_array(GL_R32F, GL_RED, GL_FLOAT, layers, gl::power_of_two_below(size));
    throw Error(ErrorKind::usage,
                i18n::trf("--shadow-map-size {}: this OpenGL context has no memory for {} shadow-map "
                          "layers of {}x{} ({}); use --shadow-map-size {} or less", size, layers, size,
                          size, gl_version_string(), largest));
  }
  // texelFetch only: the lookup picks one texel, as the CPU twin does.
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  if (size != size_) {
    if (!depth_) glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, size, size);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
  }
  if (!framebuffer_) glGenFramebuffers(1, &framebuffer_);
  size_ = size;
  layers_ = layers;
}

void ShadowMaps::update(const Scene& scene, std::span<const AreaLight> area_lights, int max_lights,
                        const Shadows& settings, const std::vector<gl::MeshBuffers>& meshes,
                        const std::vector<bool>& emissive) {
  const int size = std::clamp(settings.map_size, 16, 8192);
  const Bounds bounds = scene.bounds();

  // Layout: each light its layers, in the order the shaders number the lights.
  light_views_.clear();
  area_views_.clear();
  int layers = 0;
  for (const Light& light : scene.lights) {
    if (!light.enabled) continue;
    if (int(light_views_.size()) == max_lights) break;
    if (light.type == LightType::directional) {
      light_views_.push_back(directional_view(light, bounds, layers, size));
      layers += 1;
    } else if (light.type == LightType::spot && light.outer_cone <= max_spot_cone) {
      light_views_.push_back(spot_view(light, bounds, layers, size));
      layers += 1;
    } else {
      light_views_.push_back(cube_view(light.position, layers, size));
      layers += 6;
    }
  }
  // Emitters: consecutive ones share a group's cube (see the header).
  const size_t n = area_lights.size();
  const size_t groups = std::min(n, size_t(max_area_shadow_groups));
  for (size_t g = 0; g < groups; ++g) {
    const size_t begin = g * n / groups, end = (g + 1) * n / groups;
    glm::vec3 centroid(0.0f);
    float weights = 0.0f;
    for (size_t i = begin; i < end; ++i) {
      const Rgb power = area_lights[i].radiance * area_lights[i].area;
      const float w = power.r + power.g + power.b;
      centroid += w * area_lights[i].centroid;
      weights += w;
    }
    centroid = weights > 0.0f ? centroid / weights : area_lights[begin].centroid;
    for (size_t i = begin; i < end; ++i) area_views_.push_back(cube_view(centroid, layers, size));
    layers += 6;
  }
  // What this context can hold, asked before allocating (a map it cannot hold would only show
  // as an incomplete framebuffer below).
  if (const int largest = gl::largest_square_array(GL_R32F, GL_RED, GL_FLOAT, layers, size); largest < size)
    throw Error(ErrorKind::usage,
                i18n::trf("--shadow-map-size {}: this OpenGL context holds {} shadow-map layers of at "
                          "most {}x{} ({}); use --shadow-map-size {} or less", size, layers, largest,
                          largest, gl_version_string(), largest));
  allocate(size, layers);

  // The passes: every layer cleared to "nothing in the way", then the scene's depth drawn in.
  const gl::KeptBinding kept;
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  glViewport(0, 0, size, size);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);  // both sides of every surface block the light
  program_->use();

  const float nothing[4] = {1e30f, 0.0f, 0.0f, 0.0f};
  const float far_depth = 1.0f;
  auto draw_layer = [&](int layer, const glm::mat4& view_projection, ShadowKind kind,
                        const glm::vec3& origin, const glm::vec3& direction, bool emitter_map) {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, texture_, 0, layer);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
      throw Error(ErrorKind::gl, i18n::trf("a {}x{} R32F shadow-map layer is incomplete (status 0x{:x}) on {}",
                                           size, size, status, gl_version_string()));
    glClearBufferfv(GL_COLOR, 0, nothing);
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    program_->set("u_view_projection", view_projection);
    program_->set("u_kind", int(kind));
    program_->set("u_origin", origin);
    program_->set("u_direction", direction);
    for (size_t m = 0; m < meshes.size(); ++m)
      if (!(emitter_map && m < emissive.size() && emissive[m])) meshes[m].draw();
  };
  auto draw_cube = [&](const ShadowView& view, bool emitter_map) {
    const Range range = depth_range(bounds, view.origin);
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, range.near, range.far);
    for (int face = 0; face < 6; ++face)
      draw_layer(view.layer + face,
                 projection * glm::lookAt(view.origin, view.origin + face_forward[face], face_up[face]),
                 ShadowKind::cube, view.origin, view.direction, emitter_map);
  };
  for (const ShadowView& view : light_views_) {
    if (view.kind == ShadowKind::cube) draw_cube(view, false);
    else draw_layer(view.layer, view.matrix, view.kind, view.origin, view.direction, false);
  }
  for (size_t i = 0; i < area_views_.size(); ++i)
    if (i == 0 || area_views_[i].layer != area_views_[i - 1].layer) draw_cube(area_views_[i], true);

  glUseProgram(0);
}

ShadowLookup ShadowMaps::lookup(const Shadows& settings) const {
  ShadowLookup lookup;
  lookup.settings = settings;
  lookup.lights = light_views_;
  lookup.area_lights = area_views_;
  lookup.size = size_;
  lookup.texel = [this](int layer, int x, int y) { return texel(layer, x, y); };
  return lookup;
}

float ShadowMaps::texel(int layer, int x, int y) const {
  if (!framebuffer_ || layer < 0 || layer >= layers_) return 1e30f;
  GLint previous = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glFramebufferTextureLayer(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, texture_, 0, layer);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  float value[4] = {};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, value);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previous));
  return value[0];
}

}  // namespace luz
