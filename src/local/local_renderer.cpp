// The local models of slides 15-19 through OpenGL 3.3 core. The formula itself is in
// shaders/lighting.glsl; this file uploads the scene, chooses the program of the shading model
// and hands the lights, the material and the switches to it as uniforms.
//
// Sections: [light limits] [textures] [the renderer] [uniforms] [draw and render]
#include "local/local_renderer.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "gl/framebuffer.h"
#include "gl/functions.h"
#include "gl/mesh_buffers.h"
#include "gl/shader.h"

namespace luz {

// ---- [light limits] ----------------------------------------------------------------------------
// The lights go to the shaders as fixed-size uniform arrays (MAX_LIGHTS and MAX_AREA_LIGHTS in
// lighting.glsl; keep them equal). 16 punctual + 64 emissive triangles take about 340 vec4
// uniforms per stage, well inside what desktop drivers give (llvmpipe, NVIDIA, AMD, Intel all
// offer >= 1024 vec4). Beyond the limits:
// - punctual lights: the first 16 enabled ones in scene order are used, the rest ignored with a
//   warning (predictable: toggling a light never reshuffles the others);
// - emissive triangles: consecutive triangles (neighbours in their mesh, so usually close and
//   alike) are merged into 64 groups. A group is one point light at the power-weighted centroid
//   with the summed power Le*A and the power-weighted mean normal. Total power is kept exactly,
//   and a flat emitter (a tessellated ceiling lamp) keeps its normal; only the position of the
//   light within the group is approximated. A warning says so.
constexpr int max_lights = 16;
constexpr int max_area_lights = 64;

namespace {

float weight_of(const Rgb& power) { return power.r + power.g + power.b; }

std::vector<AreaLight> merge_area_lights(const std::vector<AreaLight>& lights, size_t groups) {
  std::vector<AreaLight> merged;
  const size_t n = lights.size();
  for (size_t g = 0; g < groups; ++g) {
    const size_t begin = g * n / groups, end = (g + 1) * n / groups;
    if (begin == end) continue;
    AreaLight group = lights[begin];
    Rgb power(0.0f);
    glm::vec3 centroid(0.0f), normal(0.0f);
    float weights = 0.0f;
    for (size_t i = begin; i < end; ++i) {
      const Rgb p = lights[i].radiance * lights[i].area;
      const float w = weight_of(p);
      power += p;
      centroid += w * lights[i].centroid;
      normal += w * lights[i].normal;
      weights += w;
    }
    // The group's light carries its power in `radiance` with a unit area.
    group.radiance = power;
    group.area = 1.0f;
    if (weights > 0.0f) group.centroid = centroid / weights;
    if (glm::length(normal) > 0.0f) group.normal = glm::normalize(normal);
    merged.push_back(group);
  }
  return merged;
}

// ---- [textures] --------------------------------------------------------------------------------
// A baseColorTexture: texels are already linear (sRGB-decoded by the loader), so they go up as
// float RGB, not as an sRGB format that GL would decode a second time. Trilinear, repeating.
GLuint upload_texture(const Texture& texture) {
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, texture.width, texture.height, 0, GL_RGB, GL_FLOAT,
               texture.texels.data());  // row 0 = the top = glTF's v = 0, as GL's t = 0
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, 0);
  return id;
}

int light_type_code(LightType type) {  // POINT, SPOT, DIRECTIONAL in lighting.glsl
  switch (type) {
    case LightType::point: return 0;
    case LightType::spot: return 1;
    case LightType::directional: return 2;
  }
  return 0;
}

}  // namespace

// ---- [the renderer] ----------------------------------------------------------------------------
struct LocalRenderer::Impl {
  const Scene& scene;
  std::vector<gl::MeshBuffers> meshes;  // one per Scene::meshes entry
  std::vector<GLuint> textures;         // one per Scene::textures entry
  std::vector<AreaLight> area_lights;   // at most max_area_lights
  gl::Program flat{{"local.vert", "flat.geom", "flat.frag"}, {"lighting.glsl"}};
  gl::Program gouraud{{"gouraud.vert", "gouraud.frag"}, {"lighting.glsl"}};
  gl::Program phong{{"local.vert", "phong.frag"}, {"lighting.glsl"}};
  std::unique_ptr<gl::Framebuffer> target;  // render()'s, reused while the size stays
  std::vector<std::string> warnings;
  bool warned_lights = false;

  explicit Impl(const Scene& s) : scene(s) {}
  ~Impl() {
    if (!textures.empty()) glDeleteTextures(GLsizei(textures.size()), textures.data());
  }

  gl::Program& program(Shading shading) {
    switch (shading) {
      case Shading::flat: return flat;
      case Shading::gouraud: return gouraud;
      case Shading::phong: return phong;
    }
    return phong;
  }

  void set_lights(gl::Program& p);
  void set_material(gl::Program& p, const Material& material, const LocalOptions& options);
  float far_plane(const Camera& camera) const;
};

// Checks before any GL call: with no context ever made current the table is all null pointers.
static const Scene& with_gl_loaded(const Scene& scene) {
  if (!glCreateProgram)
    throw Error(ErrorKind::gl, "the local renderer needs a current OpenGL context (an "
                               "OffscreenContext or a WindowContext) made before it");
  return scene;
}

LocalRenderer::LocalRenderer(const Scene& scene)
    : impl_(std::make_unique<Impl>(with_gl_loaded(scene))) {
  for (const Mesh& mesh : scene.meshes) impl_->meshes.emplace_back(mesh);
  for (const Texture& texture : scene.textures) impl_->textures.push_back(upload_texture(texture));

  if (scene.area_lights.size() > size_t(max_area_lights)) {
    impl_->area_lights = merge_area_lights(scene.area_lights, max_area_lights);
    impl_->warnings.push_back(fmt::format(
        "local models: {} emissive triangles light the scene as {} merged point lights "
        "(the shaders' limit)", scene.area_lights.size(), impl_->area_lights.size()));
  } else {
    impl_->area_lights = scene.area_lights;
  }
}

LocalRenderer::~LocalRenderer() = default;

const std::vector<std::string>& LocalRenderer::warnings() const { return impl_->warnings; }

const std::vector<AreaLight>& LocalRenderer::area_lights() const { return impl_->area_lights; }

// ---- [uniforms] --------------------------------------------------------------------------------
void LocalRenderer::Impl::set_lights(gl::Program& p) {
  int count = 0, enabled = 0;
  for (const Light& light : scene.lights) {
    if (!light.enabled) continue;
    ++enabled;
    if (count == max_lights) continue;
    const std::string at = fmt::format("u_lights[{}].", count++);
    p.set(at + "type", light_type_code(light.type));
    p.set(at + "intensity", glm::vec3(light.intensity));
    p.set(at + "position", light.position);
    p.set(at + "direction", glm::normalize(light.direction));
    p.set(at + "classroom", light.attenuation.classroom);
    p.set(at + "attenuation", light.attenuation.c);
    p.set(at + "cos_inner", std::cos(light.inner_cone));
    p.set(at + "cos_outer", std::cos(light.outer_cone));
    p.set(at + "warn_exponent", light.warn_exponent);
  }
  p.set("u_light_count", count);
  if (enabled > max_lights && !warned_lights) {
    warned_lights = true;
    warnings.push_back(fmt::format("local models: {} lights are on; only the first {} light "
                                   "the picture (the shaders' limit)", enabled, max_lights));
  }

  for (size_t i = 0; i < area_lights.size(); ++i) {
    const std::string at = fmt::format("u_area_lights[{}].", i);
    p.set(at + "position", area_lights[i].centroid);
    p.set(at + "normal", area_lights[i].normal);
    p.set(at + "power", glm::vec3(area_lights[i].radiance * area_lights[i].area));  // Le * A
  }
  p.set("u_area_light_count", int(area_lights.size()));
}

void LocalRenderer::Impl::set_material(gl::Program& p, const Material& material,
                                       const LocalOptions& options) {
  p.set("u_ka", glm::vec3(material.ka));
  p.set("u_kd", glm::vec3(material.kd));
  p.set("u_ks", glm::vec3(material.ks));
  p.set("u_shininess", material.shininess);
  p.set("u_emission", glm::vec3(material.emission));
  const bool textured = options.textures && material.kd_texture >= 0 &&
                        size_t(material.kd_texture) < textures.size();
  p.set("u_has_kd_texture", textured);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, textured ? textures[size_t(material.kd_texture)] : 0);
}

// A finite far plane for cameras with zfar = 0: just past the farthest corner of the scene.
float LocalRenderer::Impl::far_plane(const Camera& camera) const {
  const Bounds bounds = scene.bounds();
  if (bounds.empty()) return 1000.0f;
  float farthest = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p(corner & 1 ? bounds.max.x : bounds.min.x,
                      corner & 2 ? bounds.max.y : bounds.min.y,
                      corner & 4 ? bounds.max.z : bounds.min.z);
    farthest = std::max(farthest, glm::length(p - camera.position()));
  }
  return std::max(1.1f * farthest, 2.0f * camera.znear);
}

// ---- [draw and render] -------------------------------------------------------------------------
void LocalRenderer::draw(const Camera& camera, int width, int height,
                         const LocalOptions& options) {
  Impl& s = *impl_;
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);  // two-sided: back faces are lit too (lighting.glsl)
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);

  // glClearBuffer does not clamp, so a background radiance above 1 survives in a float target.
  const float background[4] = {s.scene.background.r, s.scene.background.g,
                               s.scene.background.b, 1.0f};
  const float far_depth = 1.0f;
  glClearBufferfv(GL_COLOR, 0, background);
  glClearBufferfv(GL_DEPTH, 0, &far_depth);

  gl::Program& p = s.program(options.shading);
  p.use();
  // Vertical field of view is the camera's yfov whatever the output's aspect.
  const glm::mat4 projection = camera.projection(float(width) / float(height),
                                                 s.far_plane(camera));
  p.set("u_view_projection", projection * camera.view());
  p.set("u_eye", camera.position());
  p.set("u_ambient", glm::vec3(s.scene.ambient));
  p.set("u_ambient_on", options.ambient);
  p.set("u_diffuse_on", options.diffuse);
  p.set("u_specular_on", options.specular);
  p.set("u_emission_on", options.emission);
  p.set("u_blinn", options.blinn);
  p.set("u_kd_texture", 0);  // texture unit 0
  s.set_lights(p);

  for (size_t m = 0; m < s.meshes.size(); ++m) {
    const int material = s.scene.meshes[m].material;
    const bool known = material >= 0 && size_t(material) < s.scene.materials.size();
    s.set_material(p, known ? s.scene.materials[size_t(material)] : Material{}, options);
    s.meshes[m].draw();
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
}

Image LocalRenderer::render(const Camera& camera, int width, int height,
                            const LocalOptions& options) {
  Impl& s = *impl_;
  if (!s.target || s.target->width() != width || s.target->height() != height)
    s.target = std::make_unique<gl::Framebuffer>(width, height);
  GLint previous = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  s.target->bind();
  draw(camera, width, height, options);
  Image image = s.target->read();
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
  return image;
}

}  // namespace luz
