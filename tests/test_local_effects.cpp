// Slide 19's "other possibilities" against closed forms, rendered headless through OSMesa into
// float pixels (the GL context is test_local_formula.cpp's GlEnvironment, one per binary).
//
// The setup of test_local_formula.cpp: a camera at (0, 0, 2) looks straight down -Z at the plane
// z = 0, so every pixel is a known floor point. Phong shading, so every pixel is checked.
//   - fog: fogged pixel = f * plain pixel + (1 - f) * C_fog, f from the distance to the eye;
//   - shadows: an occluding square over the floor under a point light (cube map), a spot
//     (perspective map) and a directional light (orthographic map): inside the shadow's closed-form
//     rectangle the floor has only its ambient term, outside it is exactly the unshadowed floor
//     (no acne, no light leaking, no peter panning beyond a margin of 2 pixels);
//   - transparency: pixel = I_pane + kt * I_behind, whatever order the meshes come in;
//   - reflection map: a mirror ball in a uniformly glowing box shows exactly kr * Le (the furnace
//     test of the cube maps), and an environment image's colours where nothing surrounds it.
// Tolerance: 1e-4 relative plus 1e-6 absolute (float rounding; the same formula on both sides).
#include <algorithm>
#include <cmath>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include "core/scene.h"
#include "io/gltf_loader.h"
#include "io/image_io.h"
#include "local/local_renderer.h"
#include "support.h"

namespace luz {
namespace {

constexpr int size = 96;                            // image width and height, pixels
constexpr double pixel = 2.0 / size;                // world size of a pixel on the floor
const float yfov = float(2.0 * std::atan(0.5));     // the view covers [-1, 1]^2 of z = 0
const glm::vec3 eye(0.0f, 0.0f, 2.0f);

glm::vec3 floor_point(int x, int y) {
  return {float(-1.0 + (x + 0.5) * pixel), float(1.0 - (y + 0.5) * pixel), 0.0f};
}

Camera top_camera() {
  Camera camera;
  camera.to_world = glm::translate(glm::mat4(1.0f), eye);
  camera.yfov = yfov;
  camera.znear = 0.05f;
  camera.zfar = 10.0f;
  return camera;
}

// An axis-aligned square in the plane z = `z`, facing +Z (counter-clockwise seen from above).
Mesh square(const std::string& name, float half, float z, int material, glm::vec2 centre = {0, 0}) {
  Mesh mesh;
  mesh.name = name;
  mesh.material = material;
  for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
    mesh.positions.emplace_back(centre.x + half * c.x, centre.y + half * c.y, z);
    mesh.normals.emplace_back(0.0f, 0.0f, 1.0f);
  }
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

Material matte(Rgb kd) {
  Material m;
  m.name = "matte";
  m.kd = m.ka = kd;
  return m;
}

// The floor (material 0) filling the view, lit by `light`, a little ambient.
Scene floor_scene(const Light& light) {
  Scene scene;
  scene.path = "floor (built in the test)";
  scene.materials.push_back(matte(Rgb(0.6f, 0.5f, 0.4f)));
  scene.meshes.push_back(square("floor", 1.5f, 0.0f, 0));
  scene.lights.push_back(light);
  scene.ambient = Rgb(0.05f);
  scene.cameras.push_back(top_camera());
  return scene;
}

Light point_light(glm::vec3 position, float intensity) {
  Light light;
  light.name = "lamp";
  light.position = position;
  light.intensity = Rgb(intensity);
  return light;
}

Image render(const Scene& scene, const LocalOptions& options) {
  LocalRenderer renderer(scene);
  return renderer.render(scene.cameras.front(), size, size, options);
}

// |a - b| within 1e-4 of the larger plus 1e-6, channel by channel.
bool close(const Rgb& a, const Rgb& b) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(a[c] - b[c]) > 1e-4f * std::max(std::abs(a[c]), std::abs(b[c])) + 1e-6f) return false;
  return true;
}

std::string rgb(const Rgb& c) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", c.r, c.g, c.b); }

// ---- Atmospheric attenuation --------------------------------------------------------------------
void expect_fog(const Fog& fog, const std::function<float(float)>& f_of_d) {
  Scene scene = floor_scene(point_light({0.2f, -0.1f, 1.0f}, 2.0f));
  scene.meshes[0] = square("floor", 0.7f, 0.0f, 0);  // leaves the image's border to the background
  LocalOptions plain;
  LocalOptions fogged;
  fogged.fog = fog;
  const Image without = render(scene, plain), with = render(scene, fogged);
  int floor = 0, background = 0, failed = 0;
  std::string first;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec3 P = floor_point(x, y);
      Rgb expected = fog.colour;  // rays that miss: infinitely far, all fog
      if (std::max(std::abs(P.x), std::abs(P.y)) < 0.7f - 1e-3f) {
        const float f = f_of_d(glm::length(P - eye));
        expected = f * without.at(x, y) + (1.0f - f) * fog.colour;
        ++floor;
      } else if (std::max(std::abs(P.x), std::abs(P.y)) > 0.7f + 1e-3f) {
        ++background;
      } else {
        continue;  // the floor's edge runs through this pixel
      }
      if (!close(with.at(x, y), expected) && failed++ < 5)
        first += fmt::format("  ({}, {}): {} expected {}\n", x, y, rgb(with.at(x, y)), rgb(expected));
    }
  EXPECT_GT(floor, 4000);
  EXPECT_GT(background, 2000);
  EXPECT_EQ(failed, 0) << first;
}

TEST(LocalEffects, LinearFogIsTheClosedFormBlendTowardTheFogColour) {
  Fog fog;
  fog.mode = FogMode::linear;
  fog.colour = Rgb(0.3f, 0.35f, 0.5f);
  fog.near = 2.05f;  // the floor spans d = 2 (below the eye) to 2.24 (its corners)
  fog.far = 2.3f;
  expect_fog(fog, [&](float d) { return std::clamp((fog.far - d) / (fog.far - fog.near), 0.0f, 1.0f); });
}

TEST(LocalEffects, ExponentialFogIsTheClosedFormBlendTowardTheFogColour) {
  Fog fog;
  fog.mode = FogMode::exponential;
  fog.colour = Rgb(0.4f, 0.2f, 0.1f);
  fog.density = 0.6f;
  expect_fog(fog, [&](float d) { return std::exp(-fog.density * d); });
}

// ---- Blocking of the sources by occlusion --------------------------------------------------------
// Three occluders over the floor: a square floating at z = 0.5, a wall standing on the floor
// (where peter panning would show: its shadow must start at its foot), and a small low square
// whose shadow falls near the picture's edge (a map that covered only the middle of the scene
// would miss it). A floor point is in shadow when the segment from it to the light (or
// toward a directional light) crosses an occluder.
struct Quad {
  glm::vec3 centre, u, v;  // half-axes, orthogonal
  bool hit(const glm::vec3& a, const glm::vec3& b) const {
    const glm::vec3 n = glm::cross(u, v);
    const float along = glm::dot(b - a, n);
    if (std::abs(along) < 1e-9f) return false;
    const float t = glm::dot(centre - a, n) / along;
    if (t <= 1e-5f || t >= 1.0f) return false;
    const glm::vec3 h = a + t * (b - a) - centre;
    return std::abs(glm::dot(h, u)) <= glm::dot(u, u) && std::abs(glm::dot(h, v)) <= glm::dot(v, v);
  }
};

Mesh quad_mesh(const std::string& name, const Quad& q, int material) {
  Mesh mesh;
  mesh.name = name;
  mesh.material = material;
  const glm::vec3 n = glm::normalize(glm::cross(q.u, q.v));
  for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
    mesh.positions.push_back(q.centre + c.x * q.u + c.y * q.v);
    mesh.normals.push_back(n);
  }
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

struct ShadowCase {
  const char* name;
  Light light;
};

void PrintTo(const ShadowCase& c, std::ostream* os) { *os << c.name; }

class Shadow : public ::testing::TestWithParam<ShadowCase> {};

TEST_P(Shadow, FloorIsAmbientOnlyInTheShadowAndUntouchedOutside) {
  const Light& light = GetParam().light;
  Scene scene = floor_scene(light);
  scene.materials.push_back(matte(Rgb(0.2f, 0.7f, 0.3f)));
  const Quad occluders[] = {
      {{0.3f, 0.4f, 0.5f}, {0.2f, 0.0f, 0.0f}, {0.0f, 0.2f, 0.0f}},    // floating, facing up
      {{0.3f, -0.35f, 0.3f}, {0.0f, 0.3f, 0.0f}, {0.0f, 0.0f, 0.3f}},   // a wall on the floor, between
                                                                        // the light and the camera
      {{0.65f, 0.82f, 0.25f}, {0.1f, 0.0f, 0.0f}, {0.0f, 0.1f, 0.0f}},  // low, near an edge
  };
  scene.meshes.push_back(quad_mesh("floating square", occluders[0], 1));
  scene.meshes.push_back(quad_mesh("standing wall", occluders[1], 1));
  scene.meshes.push_back(quad_mesh("low square", occluders[2], 1));

  auto blocked = [&](const glm::vec3& P, const glm::vec3& towards) {
    return std::any_of(std::begin(occluders), std::end(occluders), [&](const Quad& q) { return q.hit(P, towards); });
  };
  const glm::vec3 to_light_end = light.type == LightType::directional ? glm::vec3(0.0f) : light.position;
  auto in_shadow = [&](const glm::vec3& P) {
    return blocked(P, light.type == LightType::directional ? P - 10.0f * light.direction : to_light_end);
  };

  LocalOptions off;
  LocalOptions on;
  on.shadows.on = true;
  LocalOptions ambient_only;
  ambient_only.terms.diffuse = ambient_only.terms.specular = false;
  const Image unshadowed = render(scene, off), shadowed = render(scene, on), ambient = render(scene, ambient_only);

  // A pixel counts when the floor around it, 2 pixels every way, is all in shadow or all lit
  // (the shadow's edge is the map's to draw), and the camera sees the floor there.
  const float m = float(2.0 * pixel);
  const glm::vec3 offsets[] = {{0, 0, 0}, {m, 0, 0}, {-m, 0, 0}, {0, m, 0}, {0, -m, 0}, {m, m, 0}, {-m, -m, 0}, {m, -m, 0}, {-m, m, 0}};
  int dark = 0, lit = 0, foot = 0, failed = 0;
  std::string first;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec3 P = floor_point(x, y);
      int shaded = 0, hidden = 0;
      for (const glm::vec3& o : offsets) {
        shaded += in_shadow(P + o);
        hidden += blocked(P + o, eye);
      }
      if (hidden > 0 || (shaded > 0 && shaded < 9)) continue;
      const bool inside = shaded == 9;
      const Rgb expected = inside ? ambient.at(x, y) : unshadowed.at(x, y);
      (inside ? dark : lit)++;
      // The floor just behind the wall's foot, within 3 pixels of it: peter panning would light it.
      if (inside && P.x < 0.3f && P.x > 0.3f - 3.0f * float(pixel)) ++foot;
      if (!close(shadowed.at(x, y), expected) && failed++ < 5)
        first += fmt::format("  ({}, {}) {}: {} expected {}\n", x, y, inside ? "in shadow" : "lit",
                             rgb(shadowed.at(x, y)), rgb(expected));
    }
  EXPECT_GT(dark, 300);
  EXPECT_GT(lit, 4000);
  EXPECT_GT(foot, 10) << "the wall's shadow must start at its foot";
  EXPECT_EQ(failed, 0) << failed << " pixels wrong:\n" << first;
}

Light spot_light() {
  Light light = point_light({0.7f, 0.1f, 1.5f}, 3.0f);
  light.type = LightType::spot;
  light.direction = glm::normalize(glm::vec3(-0.3f, 0.0f, -1.0f));
  light.inner_cone = 0.9f;
  light.outer_cone = 1.0f;  // about 57 degrees: the floor in view is inside the inner cone
  return light;
}

Light directional_light() {
  Light light;
  light.name = "sun";
  light.type = LightType::directional;
  light.direction = glm::normalize(glm::vec3(-1.0f, 0.2f, -1.0f));
  light.intensity = Rgb(2.0f);
  return light;
}

INSTANTIATE_TEST_SUITE_P(EveryMapKind, Shadow,
                         ::testing::Values(ShadowCase{"point_cube_map", point_light({0.6f, 0.0f, 1.5f}, 3.0f)},
                                           ShadowCase{"spot_perspective_map", spot_light()},
                                           ShadowCase{"directional_orthographic_map", directional_light()}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// ---- Non-refractive transparency ----------------------------------------------------------------
// Two panes over the floor: near (z 0.6, kt 0.6) and far (z 0.3, kt 0.5), overlapping in the
// middle. Where both are, I = I_near + kt_near (I_far + kt_far I_floor).
// Each of the two defences against acne holds on its own: with the normal offset at 0, the
// depth bias alone (constant + slope * texel * tan(theta)) keeps a bare floor lit at 60 degrees
// by a point light, a spot and a directional light exactly as lit as without shadows (nothing
// occludes it); with no bias either, the map's own depth quantisation shadows it in speckles.
TEST(LocalEffects, TheDepthBiasAloneKeepsAFloorFreeOfAcne) {
  const float t = 60.0f * 3.14159265f / 180.0f;
  const glm::vec3 toward(std::sin(t), 0.0f, std::cos(t));  // from the floor's centre
  Light spot = point_light(2.0f * toward, 6.0f);
  spot.type = LightType::spot;
  spot.direction = -toward;
  spot.inner_cone = 0.6f;
  spot.outer_cone = 0.8f;
  Light sun;
  sun.type = LightType::directional;
  sun.direction = -toward;
  sun.intensity = Rgb(2.0f);
  for (const Light& light : {point_light(2.0f * toward, 6.0f), spot, sun}) {
    SCOPED_TRACE(to_string(light.type));
    const Scene scene = floor_scene(light);
    LocalOptions off, on;
    on.shadows.on = true;
    on.shadows.normal_offset = 0.0f;
    const Image lit = render(scene, off), shadowed = render(scene, on);
    int acne = 0;
    for (size_t i = 0; i < lit.pixels.size(); ++i) acne += !close(lit.pixels[i], shadowed.pixels[i]);
    EXPECT_EQ(acne, 0) << "of " << lit.pixels.size() << " pixels";
  }
}

TEST(LocalEffects, TransparencyAddsKtTimesWhatLiesBehindInAnyDrawOrder) {
  Scene scene = floor_scene(point_light({0.0f, 0.0f, 1.5f}, 3.0f));
  Material near_pane = matte(Rgb(0.1f, 0.1f, 0.3f));
  near_pane.kt = Rgb(0.6f);
  near_pane.ks = Rgb(0.2f);
  near_pane.shininess = 20;
  Material far_pane = matte(Rgb(0.3f, 0.1f, 0.05f));
  far_pane.kt = Rgb(0.5f, 0.4f, 0.3f);
  scene.materials.push_back(near_pane);
  scene.materials.push_back(far_pane);
  const Mesh floor = scene.meshes[0];
  const Mesh near_mesh = square("near pane", 0.3f, 0.6f, 1, {-0.1f, 0.0f});
  const Mesh far_mesh = square("far pane", 0.3f, 0.3f, 2, {0.15f, 0.05f});

  LocalOptions on;
  on.transparency.on = true;
  LocalOptions off;
  auto with = [&](std::vector<Mesh> meshes, const LocalOptions& options, Rgb background = Rgb(0.0f)) {
    Scene s = scene;
    s.meshes = std::move(meshes);
    s.background = background;
    return render(s, options);
  };
  const Image forward = with({floor, near_mesh, far_mesh}, on);
  const Image backward = with({far_mesh, near_mesh, floor}, on);
  const Image shuffled = with({near_mesh, floor, far_mesh}, on);
  // The parts, each alone over black with transparency off: its own local radiance.
  const Image floor_alone = with({floor}, off), near_alone = with({near_mesh}, off), far_alone = with({far_mesh}, off);

  int both = 0, failed = 0;
  std::string first;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      EXPECT_TRUE(close(forward.at(x, y), backward.at(x, y)) && close(forward.at(x, y), shuffled.at(x, y)))
          << "draw order changed pixel (" << x << ", " << y << ")";
      // Pixels well inside both panes (the ray to the floor point crosses them at z/2 of the way).
      const glm::vec3 P = floor_point(x, y);
      const glm::vec2 at_near = glm::vec2(P) * (1.4f / 2.0f), at_far = glm::vec2(P) * (1.7f / 2.0f);
      const float m = float(2.0 * pixel);
      const bool in_near = std::abs(at_near.x + 0.1f) < 0.3f - m && std::abs(at_near.y) < 0.3f - m;
      const bool in_far = std::abs(at_far.x - 0.15f) < 0.3f - m && std::abs(at_far.y - 0.05f) < 0.3f - m;
      if (!in_near || !in_far) continue;
      ++both;
      const Rgb expected = near_alone.at(x, y) + near_pane.kt * (far_alone.at(x, y) + far_pane.kt * floor_alone.at(x, y));
      if (!close(forward.at(x, y), expected) && failed++ < 5)
        first += fmt::format("  ({}, {}): {} expected {}\n", x, y, rgb(forward.at(x, y)), rgb(expected));
    }
  EXPECT_GT(both, 300);
  EXPECT_EQ(failed, 0) << first;
}

// ---- Reflection maps ----------------------------------------------------------------------------
Mesh sphere(float radius, int segments, int rings, int material) {
  Mesh mesh;
  mesh.name = "ball";
  mesh.material = material;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const float theta = 3.14159265f * float(i) / float(rings), phi = 6.2831853f * float(j) / float(segments);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      mesh.positions.push_back(radius * n);
      mesh.normals.push_back(n);
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = uint32_t(i * (segments + 1) + j), b = a + 1, c = a + uint32_t(segments + 1), d = c + 1;
      if (i > 0) mesh.indices.insert(mesh.indices.end(), {a, c, b});
      if (i < rings - 1) mesh.indices.insert(mesh.indices.end(), {b, c, d});
    }
  return mesh;
}

Material mirror() {
  Material m;
  m.name = "mirror";
  m.kd = m.ka = Rgb(0.0f);
  m.kr = Rgb(0.5f, 0.6f, 0.7f);
  return m;
}

// The ball's pixels: those whose ray meets the sphere of radius 0.5 well inside its silhouette.
template <typename Check>
int for_ball_pixels(Check check) {
  int n = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec3 P = floor_point(x, y);
      const glm::vec3 ray = glm::normalize(P - eye);
      // Distance of the ray from the centre: inside the ball by 2 pixels' worth.
      const float miss = glm::length(glm::cross(ray, -eye));
      if (miss < 0.5f - 0.05f) {
        check(x, y, ray);
        ++n;
      }
    }
  return n;
}

TEST(LocalEffects, MirrorBallInAGlowingBoxShowsKrTimesLe) {
  Scene scene;
  scene.path = "furnace (built in the test)";
  scene.materials.push_back(mirror());
  Material glow = matte(Rgb(0.0f));
  glow.emission = Rgb(0.3f, 0.5f, 0.7f);
  scene.materials.push_back(glow);
  scene.meshes.push_back(sphere(0.5f, 48, 32, 0));
  // A closed box around the ball and the eye, its faces wound to face inward (toward the eye).
  const float h = 3.0f;
  const glm::vec3 corners[8] = {{-h, -h, -h}, {h, -h, -h}, {h, h, -h}, {-h, h, -h},
                                {-h, -h, h},  {h, -h, h},  {h, h, h},  {-h, h, h}};
  const int faces[6][4] = {{0, 1, 2, 3}, {5, 4, 7, 6}, {4, 0, 3, 7}, {1, 5, 6, 2}, {4, 5, 1, 0}, {3, 2, 6, 7}};
  for (const auto& face : faces) {
    Mesh quad;
    quad.name = "wall";
    quad.material = 1;
    const glm::vec3 n = glm::normalize(glm::cross(corners[face[1]] - corners[face[0]], corners[face[2]] - corners[face[0]]));
    for (int k : face) {
      quad.positions.push_back(corners[k]);
      quad.normals.push_back(n);
    }
    quad.indices = {0, 1, 2, 0, 2, 3};
    scene.meshes.push_back(quad);
  }
  scene.find_area_lights();
  scene.cameras.push_back(top_camera());

  LocalOptions on;
  on.reflection.on = true;
  on.reflection.resolution = 64;
  LocalOptions off;
  const Image with = render(scene, on), without = render(scene, off);
  const Rgb expected = scene.materials[0].kr * glow.emission;
  int failed = 0;
  std::string first;
  const int n = for_ball_pixels([&](int x, int y, const glm::vec3&) {
    EXPECT_EQ(without.at(x, y), Rgb(0.0f)) << "kd = ks = 0: without the map the ball is black";
    if (!close(with.at(x, y), expected) && failed++ < 5)
      first += fmt::format("  ({}, {}): {} expected {}\n", x, y, rgb(with.at(x, y)), rgb(expected));
  });
  EXPECT_GT(n, 1000);
  EXPECT_EQ(failed, 0) << first;
}

TEST(LocalEffects, MirrorBallAloneReflectsTheEnvironmentImage) {
  // An equirectangular sky: blue above the horizon, red below.
  test::ScratchDir dir;
  Image sky(64, 32);
  for (int y = 0; y < sky.height; ++y)
    for (int x = 0; x < sky.width; ++x) sky.at(x, y) = y < sky.height / 2 ? Rgb(0.0f, 0.0f, 1.0f) : Rgb(1.0f, 0.0f, 0.0f);
  io::write_image(sky, dir / "sky.exr", 0.0f);

  Scene scene;
  scene.path = "ball (built in the test)";
  scene.materials.push_back(mirror());
  scene.meshes.push_back(sphere(0.5f, 48, 32, 0));
  scene.cameras.push_back(top_camera());
  LocalOptions options;
  options.reflection.on = true;
  options.reflection.environment = (dir / "sky.exr").string();
  const Image image = render(scene, options);
  // The camera looks down -Z; R's y decides between sky and ground (the image's horizon is y = 0).
  int checked = 0;
  for_ball_pixels([&](int x, int y, const glm::vec3& ray) {
    const glm::vec3 P = eye + ray * (-glm::dot(ray, eye) - std::sqrt(std::max(glm::dot(ray, eye) * glm::dot(ray, eye) - glm::dot(eye, eye) + 0.25f, 0.0f)));
    const glm::vec3 R = glm::reflect(ray, glm::normalize(P));
    if (std::abs(R.y) < 0.1f) return;  // near the horizon the filter blends the two
    ++checked;
    const Rgb expected = R.y > 0.0f ? Rgb(0.0f, 0.0f, 0.7f) : Rgb(0.5f, 0.0f, 0.0f);  // kr * sky
    EXPECT_TRUE(close(image.at(x, y), expected)) << "(" << x << ", " << y << "): " << rgb(image.at(x, y))
                                                 << " expected " << rgb(expected);
  });
  EXPECT_GT(checked, 800);
}

}  // namespace
}  // namespace luz

namespace luz {
namespace {

// ---- The plate: distance attenuation and non-uniform lights at floor points ----------------------
// scenes/local_effects.gltf with one light on at a time: every floor pixel of the front row is the
// closed form Ia ka + kd/pi * I * f_att(d) * spot * cos(theta) (the floor has ks = 0), at the floor
// point the pixel's central ray meets (nothing stands between the camera and the front row).
class Plate : public ::testing::Test {
protected:
  void SetUp() override { loaded_ = io::load_gltf(test::scene_dir() / "local_effects.gltf"); }

  // Renders with only `light_name` on and checks every floor pixel within `radius` of its foot.
  // Returns the radiance at the foot and at `probe` metres from it, for comparisons.
  std::pair<float, float> check(const std::string& light_name, float radius, float probe) {
    Scene& scene = loaded_.scene;
    const Light* only = nullptr;
    for (Light& light : scene.lights) {
      light.enabled = light.name == light_name;
      if (light.enabled) only = &light;
    }
    EXPECT_NE(only, nullptr) << light_name;
    if (!only) return {0, 0};
    const Camera& camera = scene.cameras.front();
    constexpr int width = 320, height = 240;
    LocalRenderer renderer(scene);
    const Image image = renderer.render(camera, width, height, LocalOptions{});
    const Material& floor = scene.materials[size_t(scene.meshes[0].material)];
    const glm::mat4 to_world = glm::inverse(camera.projection(float(width) / float(height), scene.bounds()) * camera.view());
    const glm::vec3 foot(only->position.x, 0.0f, only->position.z);
    int checked = 0, failed = 0;
    std::string first;
    float at_foot = 0.0f, at_probe = 0.0f, best_foot = 1e9f, best_probe = 1e9f;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        // The pixel centre's ray, from the near to the far plane, meets the floor y = 0 at P.
        const float nx = 2.0f * (float(x) + 0.5f) / float(width) - 1.0f, ny = 1.0f - 2.0f * (float(y) + 0.5f) / float(height);
        const glm::vec4 a = to_world * glm::vec4(nx, ny, -1.0f, 1.0f), b = to_world * glm::vec4(nx, ny, 1.0f, 1.0f);
        const glm::vec3 near_point = glm::vec3(a) / a.w, far_point = glm::vec3(b) / b.w;
        const float t = near_point.y / (near_point.y - far_point.y);
        const glm::vec3 P = near_point + t * (far_point - near_point);
        const float from_foot = glm::length(P - foot);
        if (from_foot > radius) continue;
        const glm::vec3 to_light = only->position - P;
        const float d = glm::length(to_light);
        const float cos_theta = to_light.y / d;
        const double f_att = only->attenuation.classroom
                                 ? 1.0 / (only->attenuation.c.x + only->attenuation.c.y * d + only->attenuation.c.z * d * d)
                                 : 1.0 / (double(d) * d);
        // The spot's distributions written out here, not taken from core::Light.
        double spot = 1.0;
        if (only->type == LightType::spot) {
          const double cos_angle = glm::dot(glm::normalize(only->direction), -to_light / d);
          const double cos_outer = std::cos(only->outer_cone), cos_inner = std::cos(only->inner_cone);
          if (only->warn_exponent > 0) spot = cos_angle >= cos_outer ? std::pow(cos_angle, only->warn_exponent) : 0.0;
          else spot = std::pow(std::clamp((cos_angle - cos_outer) / (cos_inner - cos_outer), 0.0, 1.0), 2.0);
        }
        const Rgb expected = scene.ambient * floor.ka +
                             floor.kd * float(only->intensity.r / 3.14159265358979 * f_att * spot * cos_theta);
        ++checked;
        const Rgb got = image.at(x, y);
        for (int c = 0; c < 3; ++c)
          if (std::abs(got[c] - expected[c]) > 0.01f * expected[c] + 1e-5f) {
            if (failed++ < 5)
              first += fmt::format("  ({}, {}) at {:.3f} m from the foot: {} expected {}\n", x, y, from_foot, rgb(got), rgb(expected));
            break;
          }
        if (from_foot < best_foot) best_foot = from_foot, at_foot = got.r;
        if (std::abs(from_foot - probe) < best_probe) best_probe = std::abs(from_foot - probe), at_probe = got.r;
      }
    EXPECT_GT(checked, 200) << light_name;
    EXPECT_EQ(failed, 0) << light_name << ": " << failed << " of " << checked << " floor pixels:\n" << first;
    return {at_foot, at_probe};
  }

  io::LoadedScene loaded_;
};

TEST_F(Plate, PhysicalAndClassroomAttenuationAreTheirClosedForms) {
  const auto physical = check("lamp_physical", 1.2f, 0.8f);
  const auto classroom = check("lamp_classroom", 1.2f, 0.8f);
  // Equal below the lamps (1/d^2 = 1/(0.35 d) at d = 0.35 m); 0.8 m away the classroom lamp,
  // falling as 1/d, keeps more of its light: the wider pool the plate shows.
  EXPECT_NEAR(physical.first, classroom.first, 0.02f * physical.first);
  EXPECT_GT(classroom.second / classroom.first, 2.0f * physical.second / physical.first);
}

TEST_F(Plate, SmoothConeAndWarnSpotAreTheirClosedForms) {
  const auto smooth = check("spot_smooth", 1.0f, 0.5f);
  const auto warn = check("spot_warn", 1.0f, 0.5f);
  EXPECT_NEAR(smooth.first, warn.first, 0.02f * smooth.first) << "the same spot on its axis";
  EXPECT_GT(smooth.second, 0.0f);
}

}  // namespace
}  // namespace luz
