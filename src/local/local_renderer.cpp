// The local models of slides 15-19 through OpenGL 3.3 core. The formula itself is in
// shaders/lighting.glsl; this file uploads the scene, chooses the program of the shading model
// and hands the lights, the material and the switches to it as uniforms.
//
// A frame, with every switch of slide 19 on:
//   1. shadow maps, one set for all lights (shadow_maps.cpp);
//   2. a reflection cube map from the centre of each object with kr > 0, the object left out;
//   3. the picture: opaque meshes first with depth writes, then the transparent ones (kt > 0)
//      back to front by the distance of their centre from the eye, blended without depth writes
//      (pixel = I + kt * pixel behind: dual-source blending, or two draws where GLSL ES has
//      none); within a mesh its back faces first, then its front faces, so a sphere's far side
//      shows through its near side. The fog is in the shaders (lighting.glsl write_fragment).
//
// Sections: [light limits] [textures] [the renderer] [uniforms] [the scene pass]
//           [reflection maps] [draw and render] [for the CPU twin]
#include "local/local_renderer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/i18n.h"
#include "gl/framebuffer.h"
#include "io/image_io.h"
#include "gl/face_buffers.h"
#include "gl/functions.h"
#include "gl/glsl_dialect.h"
#include "gl/mesh_buffers.h"
#include "gl/scene_texture.h"
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
// Reflection maps: one cube per reflective mesh, for the first 8 (a warning names the cap).
constexpr size_t max_reflection_maps = 8;

// Texture units, one per sampler type (GL refuses a draw where two sampler types share a unit).
constexpr int kd_unit = 0;
constexpr int shadow_unit = 1;
constexpr int reflection_unit = 2;
constexpr int environment_unit = 3;
constexpr int emission_unit = 4;

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

bool any(const Rgb& c) { return c.r > 0.0f || c.g > 0.0f || c.b > 0.0f; }

// The six faces of a cube map in GL's order, with the up vectors GL's cube-map rule implies (the
// same as shadow_maps.cpp's).
const glm::vec3 face_forward[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const glm::vec3 face_up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};

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
// One view of the scene to draw: the picture, or a face of a reflection cube map.
struct ScenePass {
  glm::mat4 view_projection{1.0f};
  glm::vec3 eye{0.0f};
  bool fog = true;          // the picture has the fog; the cube maps see the surfaces unfogged
  bool reflections = true;  // a cube map shows objects without their own reflections
  bool display = false;     // the opaque meshes also write the displayed value (attachment 1)
  int skip_mesh = -1;       // the object a cube map is rendered from
};

struct ReflectionCube {
  GLuint texture = 0;
  int size = 0;
};

// The switches a program is compiled with: lighting.glsl's constants (LUZ_*), so that a term that
// is off costs nothing per fragment. The options give most; the mesh gives its texture, its
// reflection map and whether it is drawn as transparent.
struct Switches {
  Shading shading = Shading::phong;
  bool ambient = true, diffuse = true, specular = true, emission = true, blinn = false;
  bool kd_texture = false, emission_texture = false;
  bool shadows = false, reflection = false, environment = false, transparent = false;
  bool display = false;  // lighting.glsl's second output, the displayed value
  FogMode fog = FogMode::off;
  int lights = 0, area_lights = 0;  // how many the shaders' loops run over
  std::vector<int> light_types;     // per light (lighting.glsl POINT, SPOT, DIRECTIONAL)
  std::vector<int> shadow_kinds;    // per light, its map's ShadowKind
  ShadowKind area_shadow_kind = ShadowKind::none;

  std::string defines() const {
    const auto line = [](const char* name, bool on) { return fmt::format("#define {} {}\n", name, on ? "true" : "false"); };
    return line("LUZ_AMBIENT_ON", ambient) + line("LUZ_DIFFUSE_ON", diffuse) +
           line("LUZ_SPECULAR_ON", specular) + line("LUZ_EMISSION_ON", emission) +
           line("LUZ_BLINN", blinn) + line("LUZ_KD_TEXTURE", kd_texture) +
           line("LUZ_EMISSION_TEXTURE", emission_texture) +
           line("LUZ_SHADOWS_ON", shadows) + line("LUZ_REFLECTION_ON", reflection) +
           line("LUZ_ENVIRONMENT", environment) + line("LUZ_TRANSPARENT", transparent) +
           fmt::format("#define LUZ_FOG_MODE {}\n", int(fog)) +  // lighting.glsl's FOG_*
           fmt::format("#define LUZ_LIGHT_COUNT {}\n#define LUZ_AREA_LIGHT_COUNT {}\n", lights, area_lights) +
           fmt::format("#define LUZ_LIGHT_TYPES {}\n", list(light_types)) +
           fmt::format("#define LUZ_LIGHT_SHADOW_KINDS {}\n", list(shadow_kinds)) +
           fmt::format("#define LUZ_AREA_SHADOW_KIND {}\n", int(area_shadow_kind)) +
           fmt::format("#define LUZ_DISPLAY_OUTPUT {}\n", int(display));  // for #if
  }

  // lighting.glsl's per-light arrays, max_lights long: "1, 2, -1, ..., -1" for {1, 2}.
  static std::string list(const std::vector<int>& values) {
    std::string text;
    for (int i = 0; i < max_lights; ++i)
      text += fmt::format("{}{}", i ? ", " : "", size_t(i) < values.size() ? values[size_t(i)] : -1);
    return text;
  }
};

// A compiled program and the draw_scene() call whose uniforms it holds: a pass sets the lights,
// the camera and the switches' parameters once per program it uses, not once per mesh.
struct Variant {
  gl::Program program;
  int pass = -1;
};

// What the maps of slide 19 were last drawn from. Shadow and reflection maps do not depend on the
// camera, so an orbiting class redraws neither: they are drawn again only when what they show
// changes (a light moved or switched, a material edited, a switch thrown). The geometry is fixed
// for a renderer's life (see local_renderer.h).
struct ShadowInputs {
  std::vector<Light> lights;
  std::vector<bool> emissive;  // per mesh: left out of the emitters' maps
  Shadows settings;
  bool operator==(const ShadowInputs&) const = default;
};

struct ReflectionInputs {
  std::vector<Light> lights;
  std::vector<Material> materials;
  Rgb ambient{0.0f}, background{0.0f};
  LocalOptions options;
  int shadow_revision = 0;  // the shadow maps the cube faces were lit with
  bool operator==(const ReflectionInputs&) const = default;
};

struct LocalRenderer::Impl {
  const Scene& scene;
  std::vector<gl::MeshBuffers> meshes;  // one per Scene::meshes entry
  std::vector<gl::FaceBuffers> faces;   // the same for flat.vert (GLSL ES): made when first drawn flat
  std::vector<Bounds> bounds;           // each mesh's bounding box (sorting, cube maps)
  std::vector<glm::vec3> centres;       // their centres
  std::vector<GLuint> textures;         // one per Scene::textures entry
  std::vector<AreaLight> area_lights;   // at most max_area_lights
  std::unique_ptr<ShadowMaps> shadow_maps;  // made when shadows are first switched on
  bool drew_shadows = false;                // the last draw() used them
  std::optional<ShadowInputs> shadows_drawn_for;
  int shadow_revision = 0;                  // counts the shadow maps' updates
  std::optional<ReflectionInputs> reflections_drawn_for;
  Shadows drawn_shadow_settings;
  std::vector<ReflectionCube> cubes;        // per mesh (texture 0: none)
  GLuint cube_framebuffer = 0, cube_depth = 0;
  int cube_depth_size = 0;
  bool drew_reflections = false;
  float display_scale = 1.0f;               // 2^exposure for the displayed value
  bool drew_display = false;                // the last draw() left it whole (drew_display())
  std::string environment_path;             // the image in environment_texture
  Image environment;
  GLuint environment_texture = 0;
  bool warned_reflections = false;
  std::map<std::string, Variant> programs;   // by Switches::defines(), compiled when first drawn
  int pass_number = 0;                       // counts draw_scene() calls (see Variant::pass)
  std::unique_ptr<gl::Framebuffer> target;  // render()'s, reused while the size stays
  std::vector<std::string> warnings;
  bool warned_lights = false;

  explicit Impl(const Scene& s) : scene(s) {}
  ~Impl() {
    if (!textures.empty()) glDeleteTextures(GLsizei(textures.size()), textures.data());
    for (const ReflectionCube& cube : cubes)
      if (cube.texture) glDeleteTextures(1, &cube.texture);
    if (cube_framebuffer) glDeleteFramebuffers(1, &cube_framebuffer);
    if (cube_depth) glDeleteRenderbuffers(1, &cube_depth);
    if (environment_texture) glDeleteTextures(1, &environment_texture);
  }

  Variant& program_for(const Switches& switches);

  const Material& material_of(size_t mesh) const {
    static const Material fallback;
    const int m = scene.meshes[mesh].material;
    return m >= 0 && size_t(m) < scene.materials.size() ? scene.materials[size_t(m)] : fallback;
  }

  void set_pass(gl::Program& p, const ScenePass& pass, const LocalOptions& options, bool shadows);
  void set_lights(gl::Program& p, bool shadows);
  // `textured`: is_textured() of the mesh drawn with it.
  void set_material(gl::Program& p, const Material& material, bool textured, bool emission_textured);
  bool is_textured(size_t mesh, const LocalOptions& options) const {
    return options.terms.textures && scene.shown_texture(scene.meshes[mesh], material_of(mesh)) >= 0;
  }
  void set_shadow_view(gl::Program& p, const std::string& at, const ShadowView* view);
  float far_plane(const glm::vec3& eye) const;
  void draw_scene(const ScenePass& pass, const LocalOptions& options);
  // LocalRenderer::draw and draw_display: the maps, then the picture into the rectangle.
  void draw(const Camera& camera, glm::ivec2 origin, glm::ivec2 size, const LocalOptions& options,
            std::optional<float> scale, bool clear_everywhere = false);
  void update_environment(const ReflectionMap& settings);
  void render_reflection_maps(const LocalOptions& options);
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
  for (const Mesh& mesh : scene.meshes) {
    impl_->meshes.emplace_back(mesh);
    Bounds bounds;
    for (const glm::vec3& p : mesh.positions) bounds.grow(p);
    impl_->bounds.push_back(bounds);
    impl_->centres.push_back(bounds.empty() ? glm::vec3(0.0f) : bounds.centre());
  }
  impl_->cubes.resize(scene.meshes.size());
  for (const Texture& texture : scene.textures) impl_->textures.push_back(gl::upload_texture(texture));

  if (scene.area_lights.size() > size_t(max_area_lights)) {
    impl_->area_lights = merge_area_lights(scene.area_lights, max_area_lights);
    impl_->warnings.push_back(i18n::trf(
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
// A light's shadow map for lighting.glsl's ShadowView (kind none without one).
void LocalRenderer::Impl::set_shadow_view(gl::Program& p, const std::string& at, const ShadowView* view) {
  const ShadowView none;
  const ShadowView& v = view ? *view : none;
  p.set(at + "kind", int(v.kind));
  p.set(at + "layer", v.layer);
  p.set(at + "origin", v.origin);
  p.set(at + "direction", v.direction);
  p.set(at + "matrix", v.matrix);
  p.set(at + "texel", v.texel);
}

void LocalRenderer::Impl::set_lights(gl::Program& p, bool shadows) {
  const std::vector<ShadowView>* light_views = shadows ? &shadow_maps->light_views() : nullptr;
  const std::vector<ShadowView>* area_views = shadows ? &shadow_maps->area_views() : nullptr;
  auto view = [](const std::vector<ShadowView>* views, size_t i) -> const ShadowView* {
    return views && i < views->size() ? &(*views)[i] : nullptr;
  };
  int count = 0, enabled = 0;
  for (const Light& light : scene.lights) {
    if (!light.enabled) continue;
    ++enabled;
    if (count == max_lights) continue;
    set_shadow_view(p, fmt::format("u_lights[{}].shadow.", count), view(light_views, size_t(count)));
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
  if (enabled > max_lights && !warned_lights) {
    warned_lights = true;
    warnings.push_back(i18n::trf("local models: {} lights are on; only the first {} light "
                                 "the picture (the shaders' limit)", enabled, max_lights));
  }

  for (size_t i = 0; i < area_lights.size(); ++i) {
    const std::string at = fmt::format("u_area_lights[{}].", i);
    p.set(at + "position", area_lights[i].centroid);
    p.set(at + "normal", area_lights[i].normal);
    p.set(at + "power", glm::vec3(area_lights[i].radiance * area_lights[i].area));  // Le * A
    set_shadow_view(p, at + "shadow.", view(area_views, i));
  }
}

// What every mesh of a pass shares: the camera, the ambient term, the lights and the parameters
// of slide 19's switches.
void LocalRenderer::Impl::set_pass(gl::Program& p, const ScenePass& pass, const LocalOptions& options,
                                   bool shadows) {
  p.set("u_view_projection", pass.view_projection);
  p.set("u_eye", pass.eye);
  p.set("u_ambient", glm::vec3(scene.ambient));
  p.set("u_kd_texture", kd_unit);
  p.set("u_emission_texture", emission_unit);
  // Slide 19. S_i: the shadow maps (already rendered for this frame).
  p.set("u_shadow_maps", shadow_unit);
  p.set("u_shadow_constant_bias", options.shadows.constant_bias);
  p.set("u_shadow_slope_bias", options.shadows.slope_bias);
  p.set("u_shadow_normal_offset", options.shadows.normal_offset);
  set_lights(p, shadows);
  // kr Ir: the environment behind the cube maps.
  p.set("u_reflection_map", reflection_unit);
  p.set("u_environment", environment_unit);
  p.set("u_background", glm::vec3(scene.background));
  // The fog.
  p.set("u_fog_colour", glm::vec3(options.fog.colour));
  p.set("u_fog_near", options.fog.near);
  p.set("u_fog_far", options.fog.far);
  p.set("u_fog_density", options.fog.density);
  if (pass.display) p.set("u_display_scale", display_scale);
}

Variant& LocalRenderer::Impl::program_for(const Switches& switches) {
  // The shading model picks the stages, so it is part of the key (with the defines alone, the
  // viewer's flat and Gouraud would reuse the Phong program compiled first).
  std::string key = fmt::format("// shading {}\n", int(switches.shading)) + switches.defines();
  auto found = programs.find(key);
  if (found != programs.end()) return found->second;
  std::vector<std::string> stages;
  const bool es = gl::current_glsl_dialect() == gl::GlslDialect::es_300;
  switch (switches.shading) {
    case Shading::flat:  // GLSL ES has no geometry stage: every vertex carries its triangle
      stages = es ? std::vector<std::string>{"flat.vert", "flat.frag"}
                  : std::vector<std::string>{"local.vert", "flat.geom", "flat.frag"};
      break;
    case Shading::gouraud: stages = {"gouraud.vert", "gouraud.frag"}; break;
    case Shading::phong: stages = {"local.vert", "phong.frag"}; break;
  }
  Variant variant{gl::Program(stages, {"srgb.glsl", "lighting.glsl"}, key)};
  return programs.emplace(std::move(key), std::move(variant)).first->second;
}

void LocalRenderer::Impl::set_material(gl::Program& p, const Material& material, bool textured,
                                       bool emission_textured) {
  p.set("u_ka", glm::vec3(material.ka));
  p.set("u_kd", glm::vec3(material.kd));
  p.set("u_ks", glm::vec3(material.ks));
  p.set("u_shininess", material.shininess);
  p.set("u_emission", glm::vec3(material.emission));
  glActiveTexture(GL_TEXTURE0 + kd_unit);
  glBindTexture(GL_TEXTURE_2D, textured ? textures[size_t(material.kd_texture)] : 0);
  glActiveTexture(GL_TEXTURE0 + emission_unit);
  glBindTexture(GL_TEXTURE_2D, emission_textured ? textures[size_t(material.emission_texture)] : 0);
  p.set("u_kr", glm::vec3(material.kr));
  p.set("u_kt", glm::vec3(material.kt));
}

// The distance from the eye to the farthest corner of a (non-empty) box.
static float farthest_corner(const Bounds& bounds, const glm::vec3& eye) {
  float farthest = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p(corner & 1 ? bounds.max.x : bounds.min.x,
                      corner & 2 ? bounds.max.y : bounds.min.y,
                      corner & 4 ? bounds.max.z : bounds.min.z);
    farthest = std::max(farthest, glm::length(p - eye));
  }
  return farthest;
}

// A finite far plane for a reflection map's cube around `eye`: just past the farthest corner of the scene.
float LocalRenderer::Impl::far_plane(const glm::vec3& eye) const {
  const Bounds box = scene.bounds();
  if (box.empty()) return 1000.0f;
  return std::max(1.1f * farthest_corner(box, eye), 1e-3f);
}

// ---- [the scene pass] --------------------------------------------------------------------------
// Draws every mesh (but pass.skip_mesh) into the bound framebuffer, already cleared.
void LocalRenderer::Impl::draw_scene(const ScenePass& pass, const LocalOptions& options) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);  // two-sided: back faces are lit too (lighting.glsl)
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);

  const bool shadows = options.shadows.on && shadow_maps;
  Switches common;
  common.shading = options.shading;
  common.ambient = options.terms.ambient;
  common.diffuse = options.terms.diffuse;
  common.specular = options.terms.specular;
  common.emission = options.terms.emission;
  common.blinn = options.terms.blinn;
  common.shadows = shadows;
  common.environment = environment_texture != 0 && !environment_path.empty();
  common.fog = pass.fog ? options.fog.mode : FogMode::off;
  common.area_lights = int(area_lights.size());
  for (const Light& light : scene.lights) {
    if (!light.enabled) continue;
    if (common.lights == max_lights) break;
    const size_t i = size_t(common.lights++);
    common.light_types.push_back(light_type_code(light.type));
    common.shadow_kinds.push_back(int(shadows && i < shadow_maps->light_views().size()
                                          ? shadow_maps->light_views()[i].kind : ShadowKind::none));
  }
  if (shadows && !shadow_maps->area_views().empty()) common.area_shadow_kind = ShadowKind::cube;
  ++pass_number;
  // Flat shading in GLSL ES (flat.vert) draws every triangle with its own three vertices.
  const bool dual_source = gl::current_glsl_dialect() == gl::GlslDialect::desktop_330;
  const bool face_vertices = options.shading == Shading::flat && !dual_source;
  if (face_vertices && faces.empty())
    for (const Mesh& mesh : scene.meshes) faces.emplace_back(mesh);

  // The textures every mesh of the pass shares: S_i's maps and the surroundings of kr Ir.
  glActiveTexture(GL_TEXTURE0 + shadow_unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, shadows ? shadow_maps->texture() : 0);
  glActiveTexture(GL_TEXTURE0 + environment_unit);
  glBindTexture(GL_TEXTURE_2D, environment_texture);

  auto draw_mesh = [&](size_t m, bool transparent, bool transmittance_pass = false) {
    const Material& material = material_of(m);
    Switches switches = common;
    switches.kd_texture = is_textured(m, options);
    switches.emission_texture = options.terms.emission && material.is_emissive() &&
                                scene.shown_emission_texture(scene.meshes[m], material) >= 0;
    switches.reflection = pass.reflections && options.reflection.on && any(material.kr) && cubes[m].texture;
    switches.transparent = transparent;
    switches.display = pass.display && !transparent;
    Variant& variant = program_for(switches);
    gl::Program& p = variant.program;
    p.use();
    if (variant.pass != pass_number) {
      set_pass(p, pass, options, shadows);
      variant.pass = pass_number;
    }
    set_material(p, material, switches.kd_texture, switches.emission_texture);
    if (transparent && !dual_source) p.set("u_transmittance_pass", transmittance_pass);
    glActiveTexture(GL_TEXTURE0 + reflection_unit);
    glBindTexture(GL_TEXTURE_CUBE_MAP, switches.reflection ? cubes[m].texture : 0);
    if (face_vertices) faces[m].draw();
    else meshes[m].draw();
  };

  // pixel = I + kt * pixel behind. The desktop blends both in one draw with dual-source blending
  // (SRC1 = lighting.glsl's frag_transmittance); GLSL ES has none, so the page draws twice:
  // pixel behind x kt, then + I. The same sum wherever one side of a mesh does not cover itself
  // (the two draws would filter a farther triangle of that side by a nearer one's kt too).
  auto draw_transparent = [&](size_t m) {
    if (dual_source) {
      glBlendFunc(GL_ONE, GL_SRC1_COLOR);
      draw_mesh(m, true);
      return;
    }
    glBlendFunc(GL_ZERO, GL_SRC_COLOR);
    draw_mesh(m, true, true);
    glBlendFunc(GL_ONE, GL_ONE);
    draw_mesh(m, true, false);
  };

  // Opaque first, with depth writes; the transparent ones wait. The opaque ones go nearest far
  // side first, so that what stands on a floor or before a wall is drawn before it: the depth
  // test before the fragment shader then skips the hidden part of the large surfaces, which is
  // most of what a software rasteriser would shade twice. The picture is the same in any order.
  std::vector<size_t> opaque, transparent;
  for (size_t m = 0; m < meshes.size(); ++m) {
    if (int(m) == pass.skip_mesh || bounds[m].empty()) continue;
    if (options.transparency.on && any(material_of(m).kt)) transparent.push_back(m);
    else opaque.push_back(m);
  }
  std::vector<float> far_side(meshes.size());
  for (size_t m : opaque) far_side[m] = farthest_corner(bounds[m], pass.eye);
  std::stable_sort(opaque.begin(), opaque.end(),
                   [&](size_t a, size_t b) { return far_side[a] < far_side[b]; });
  for (size_t m : opaque) draw_mesh(m, false);

  // Then back to front, blended: pixel = (this surface's radiance) + kt * (pixel behind).
  if (!transparent.empty()) {
    if (pass.display) {  // the blend acts on radiance only, and dual-source blending takes one draw buffer
      drew_display = false;
      const GLenum radiance = GL_COLOR_ATTACHMENT0;
      glDrawBuffers(1, &radiance);
    }
    std::stable_sort(transparent.begin(), transparent.end(), [&](size_t a, size_t b) {
      return glm::length(centres[a] - pass.eye) > glm::length(centres[b] - pass.eye);
    });
    glEnable(GL_BLEND);
    glDepthMask(GL_FALSE);               // what is behind stays visible to the next ones
    glEnable(GL_CULL_FACE);
    for (size_t m : transparent) {
      glCullFace(GL_FRONT);  // its far side first...
      draw_transparent(m);
      glCullFace(GL_BACK);   // ...then its near side over it
      draw_transparent(m);
    }
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    // GL's default again: a blend function that reads SRC1 forbids a second draw buffer even
    // with blending off (Mesa then refuses the draws that also write the displayed values).
    glBlendFunc(GL_ONE, GL_ZERO);
  }

  for (int unit : {kd_unit, shadow_unit, reflection_unit, environment_unit}) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  }
  glActiveTexture(GL_TEXTURE0);
  glUseProgram(0);
}

// ---- [reflection maps] -------------------------------------------------------------------------
// The environment image named by the options, read when the name changes (linear RGB float,
// repeating around, clamped at the poles; no mipmaps: the lookup is at level 0).
void LocalRenderer::Impl::update_environment(const ReflectionMap& settings) {
  if (settings.environment == environment_path) return;
  environment_path.clear();
  environment = Image();
  if (settings.environment.empty()) return;
  environment = io::read_image(settings.environment);  // throws: the caller reports it
  if (!environment_texture) glGenTextures(1, &environment_texture);
  glBindTexture(GL_TEXTURE_2D, environment_texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, environment.width, environment.height, 0, GL_RGB, GL_FLOAT,
               environment.pixels.data());  // row 0 = the top = t 0: the sky up
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  environment_path = settings.environment;
}

// A cube map around the centre of every mesh with kr > 0, the mesh itself left out: the world as
// a mirror there would see it, with one bounce (the other mirrors appear without their own
// reflections) and no fog. Cleared to alpha 0, so the lookup knows where nothing was seen.
void LocalRenderer::Impl::render_reflection_maps(const LocalOptions& options) {
  const int size = std::clamp(options.reflection.resolution, 8, 4096);
  std::vector<size_t> reflective;
  for (size_t m = 0; m < meshes.size(); ++m)
    if (any(material_of(m).kr)) reflective.push_back(m);
  if (reflective.size() > max_reflection_maps) {
    if (!warned_reflections)
      warnings.push_back(i18n::trf("local models: {} objects have kr > 0; the first {} get a "
                                   "reflection map", reflective.size(), max_reflection_maps));
    warned_reflections = true;
    reflective.resize(max_reflection_maps);
  }
  if (reflective.empty()) return;

  if (!cube_framebuffer) glGenFramebuffers(1, &cube_framebuffer);
  if (cube_depth_size != size) {
    if (!cube_depth) glGenRenderbuffers(1, &cube_depth);
    glBindRenderbuffer(GL_RENDERBUFFER, cube_depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, size, size);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    cube_depth_size = size;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, cube_framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, cube_depth);
  glViewport(0, 0, size, size);

  for (size_t m : reflective) {
    ReflectionCube& cube = cubes[m];
    if (!cube.texture) glGenTextures(1, &cube.texture);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube.texture);
    if (cube.size != size) {
      for (int face = 0; face < 6; ++face)
        glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_RGBA32F, size, size, 0, GL_RGBA,
                     GL_FLOAT, nullptr);
      glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
      cube.size = size;
    }
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);

    const glm::vec3 centre = centres[m];
    const float far = far_plane(centre);
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, 1e-4f * far, far);
    for (int face = 0; face < 6; ++face) {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face),
                             cube.texture, 0);
      const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
      if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error(ErrorKind::gl, i18n::trf("a {}x{} RGBA32F reflection-map face is incomplete (status "
                                             "0x{:x}) on {}", size, size, status, gl_version_string()));
      const float nothing[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      const float far_depth = 1.0f;
      glClearBufferfv(GL_COLOR, 0, nothing);
      glClearBufferfv(GL_DEPTH, 0, &far_depth);
      ScenePass pass;
      pass.view_projection = projection * glm::lookAt(centre, centre + face_forward[face], face_up[face]);
      pass.eye = centre;
      pass.fog = false;
      pass.reflections = false;
      pass.skip_mesh = int(m);
      draw_scene(pass, options);
    }
  }
}

// ---- [draw and render] -------------------------------------------------------------------------
void LocalRenderer::draw(const Camera& camera, int width, int height,
                         const LocalOptions& options, std::optional<float> display_scale) {
  impl_->draw(camera, glm::ivec2(0), glm::ivec2(width, height), options, display_scale);
}

void LocalRenderer::draw_display(const Camera& camera, glm::ivec2 origin, glm::ivec2 size,
                                 const LocalOptions& options, float display_scale, bool clear_everywhere) {
  impl_->draw(camera, origin, size, options, display_scale, clear_everywhere);
}

bool LocalRenderer::blends(const LocalOptions& options) const {
  if (!options.transparency.on) return false;
  for (size_t m = 0; m < impl_->meshes.size(); ++m)
    if (any(impl_->material_of(m).kt)) return true;
  return false;
}

void LocalRenderer::Impl::draw(const Camera& camera, glm::ivec2 origin, glm::ivec2 size,
                               const LocalOptions& options, std::optional<float> scale, bool clear_everywhere) {
  Impl& s = *this;
  glDisable(GL_SCISSOR_TEST);  // the maps are drawn whole
  GLint drawn_into = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &drawn_into);

  // 1. The shadow maps (S_i).
  s.drew_shadows = options.shadows.on;
  s.drawn_shadow_settings = options.shadows;
  if (options.shadows.on) {
    ShadowInputs inputs{s.scene.lights, {}, options.shadows};
    for (size_t m = 0; m < s.meshes.size(); ++m) inputs.emissive.push_back(s.material_of(m).is_emissive());
    if (!s.shadow_maps || s.shadows_drawn_for != inputs) {
      if (!s.shadow_maps) s.shadow_maps = std::make_unique<ShadowMaps>();
      s.shadow_maps->update(s.scene, s.area_lights, max_lights, options.shadows, s.meshes, inputs.emissive);
      s.shadows_drawn_for = std::move(inputs);
      ++s.shadow_revision;
    }
  }
  // 2. The reflection maps (kr Ir).
  s.update_environment(options.reflection);
  s.drew_reflections = options.reflection.on;
  if (options.reflection.on) {
    ReflectionInputs inputs{s.scene.lights, s.scene.materials, s.scene.ambient, s.scene.background,
                            options, options.shadows.on ? s.shadow_revision : 0};
    if (s.reflections_drawn_for != inputs) {
      s.render_reflection_maps(options);
      s.reflections_drawn_for = std::move(inputs);
    }
  }

  // 3. The picture.
  // The depth buffer is cleared whole: between draws it holds nothing anyone reads, and Mesa's
  // software rasteriser fills a whole buffer at memory speed but clears a rectangle of it by
  // drawing a quad (in a 1720x752 window, 0.25 ms for all of it against 0.9 ms for a 1280x720
  // pane; the colour 0.26 against 1.28 ms). The stencil goes with it, since depth alone in a
  // packed depth-stencil buffer is a masked write, as slow as the quad.
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(drawn_into));
  glDepthMask(GL_TRUE);
  glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
  // The scissor keeps the colour clears inside the rectangle (all of an FBO, a pane of the window).
  glViewport(origin.x, origin.y, size.x, size.y);
  glScissor(origin.x, origin.y, size.x, size.y);
  glEnable(GL_SCISSOR_TEST);
  // Rays that hit nothing see the background, or through fog the fog colour (f = 0 at infinity).
  // glClearBuffer does not clamp, so a background radiance above 1 survives in a float target.
  const Rgb clear = options.fog.mode != FogMode::off ? options.fog.colour : s.scene.background;
  const float background[4] = {clear.r, clear.g, clear.b, 1.0f};
  glClearBufferfv(GL_COLOR, 0, background);

  ScenePass pass;
  pass.display = s.drew_display = scale.has_value();
  if (scale) {
    s.display_scale = *scale;
    const float shown[4] = {srgb_encode(clear.r * *scale), srgb_encode(clear.g * *scale),
                            srgb_encode(clear.b * *scale), 1.0f};
    if (clear_everywhere) glDisable(GL_SCISSOR_TEST);
    glClearBufferfv(GL_COLOR, 1, shown);
    glEnable(GL_SCISSOR_TEST);
  }
  // Vertical field of view is the camera's yfov whatever the output's aspect.
  pass.view_projection = camera.projection(float(size.x) / float(size.y), s.scene.bounds()) * camera.view();
  pass.eye = camera.position();
  s.draw_scene(pass, options);
  glDisable(GL_SCISSOR_TEST);
}

bool LocalRenderer::drew_display() const { return impl_->drew_display; }

Image LocalRenderer::render(const Camera& camera, int width, int height,
                            const LocalOptions& options) {
  Impl& s = *impl_;
  if (!s.target || s.target->width() != width || s.target->height() != height)
    s.target = std::make_unique<gl::Framebuffer>(width, height);
  const gl::KeptBinding kept;
  s.target->bind();
  draw(camera, width, height, options);
  return s.target->read();
}

}  // namespace luz

namespace luz {

// ---- [for the CPU twin] ------------------------------------------------------------------------
std::optional<ShadowLookup> LocalRenderer::shadow_lookup() const {
  if (!impl_->drew_shadows || !impl_->shadow_maps) return std::nullopt;
  return impl_->shadow_maps->lookup(impl_->drawn_shadow_settings);
}

ReflectionLookup LocalRenderer::reflection_lookup(int mesh) const {
  const Impl& s = *impl_;
  ReflectionLookup lookup;
  lookup.background = s.scene.background;
  if (!s.environment_path.empty()) lookup.environment = &s.environment;
  if (!s.drew_reflections || mesh < 0 || size_t(mesh) >= s.cubes.size() || !s.cubes[size_t(mesh)].texture)
    return lookup;
  CubeMapData& cube = lookup.cube;
  cube.size = s.cubes[size_t(mesh)].size;
  const GLuint texture = s.cubes[size_t(mesh)].texture;
  GLuint framebuffer = s.cube_framebuffer;
  cube.texel = [texture, framebuffer](int face, int x, int y) {
    GLint previous = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face),
                           texture, 0);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glm::vec4 value(0.0f);
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, &value.x);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previous));
    return value;
  };
  return lookup;
}

}  // namespace luz
