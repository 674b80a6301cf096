// Flat, Gouraud and Phong shading differ where the lecture says they should, on a coarse UV
// sphere (12 segments x 8 rings) with a tight highlight placed in the middle of a face:
//   - Phong (normals interpolated, formula per fragment) finds the highlight's full peak,
//     ks * I / (pi d^2); Gouraud only sees it at the vertices, where it is nearly gone;
//   - flat shading is one colour per triangle (the formula at its centroid with the face
//     normal), so neighbouring faces differ: facets.
// The OpenGL context comes from the GlEnvironment of test_local_formula.cpp (same binary).
#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <gtest/gtest.h>

#include "core/scene.h"
#include "distant_scene.h"
#include "local/local_renderer.h"

namespace luz {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr int size = 256;
constexpr int segments = 12;  // around the Y axis, 30 degrees each
constexpr int rings = 8;      // pole to pole, 22.5 degrees each

using dvec3 = glm::dvec3;

// The unit-sphere direction at polar angle theta (from +Y) and azimuth phi (from +Z to +X).
dvec3 sphere_direction(double theta, double phi) {
  return {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
}

// A unit UV sphere at the origin with smooth (radial) vertex normals, wound counter-clockwise
// seen from outside; the degenerate triangles at the poles are left out.
Mesh uv_sphere() {
  Mesh mesh;
  mesh.name = "sphere";
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i <= segments; ++i) {
      const glm::vec3 p(sphere_direction(pi * j / rings, 2.0 * pi * i / segments));
      mesh.positions.push_back(p);
      mesh.normals.push_back(p);
    }
  const auto index = [](int i, int j) { return uint32_t(j * (segments + 1) + i); };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1),
                     d = index(i, j + 1);
      if (j != rings - 1) mesh.indices.insert(mesh.indices.end(), {a, d, c});
      if (j != 0) mesh.indices.insert(mesh.indices.end(), {a, c, b});
    }
  return mesh;
}

const dvec3 eye(0.0, 0.0, 4.0);

// The highlight's spot: the centre of the face between rings 3 and 4 and segments 0 and 1,
// 0.3 rad from the nearest vertex. The light sits where that point mirrors the eye, so it lights
// the whole front of the sphere.
const double highlight_theta = pi * 3.5 / rings;
const double highlight_phi = 2.0 * pi * 0.5 / segments;
constexpr double light_distance = 5.0;
constexpr float shininess = 300.0f;

dvec3 highlight_point() { return sphere_direction(highlight_theta, highlight_phi); }

dvec3 light_position() {
  const dvec3 P = highlight_point(), N = P;
  const dvec3 V = glm::normalize(eye - P);
  const dvec3 L = 2.0 * glm::dot(N, V) * N - V;  // the mirror of V about N
  return P + light_distance * L;
}

Scene sphere_scene() {
  Scene scene;
  scene.path = "sphere (built in the test)";
  Material m;
  m.name = "shiny";
  m.kd = Rgb(0.3f, 0.25f, 0.2f);
  m.ka = m.kd;
  m.ks = Rgb(0.6f);
  m.shininess = shininess;
  scene.materials.push_back(m);
  scene.meshes.push_back(uv_sphere());
  Light light;
  light.name = "key";
  light.position = glm::vec3(light_position());
  light.intensity = Rgb(30.0f);
  scene.lights.push_back(light);
  scene.ambient = Rgb(0.1f);  // background black: peaks below are the sphere's
  Camera camera;
  camera.name = "front";
  camera.to_world = glm::translate(glm::mat4(1.0f), glm::vec3(eye));
  camera.yfov = 0.6f;
  camera.znear = 0.5f;  // zfar 0: the renderer picks one from the scene's bounds
  scene.cameras.push_back(camera);
  return scene;
}

Image render(const Scene& scene, Shading shading, bool ambient, bool diffuse, bool specular) {
  LocalOptions options;
  options.shading = shading;
  options.terms.ambient = ambient;
  options.terms.diffuse = diffuse;
  options.terms.specular = specular;
  LocalRenderer renderer(scene);
  return renderer.render(scene.cameras[0], size, size, options);
}

float peak_red(const Image& image) {
  float peak = 0.0f;
  for (const Rgb& p : image.pixels) peak = std::max(peak, p.r);
  return peak;
}

// Phong's specular term at P with normal N (the lecture's closed form).
double specular(const Scene& scene, const dvec3& P, const dvec3& N) {
  const dvec3 to_light = dvec3(scene.lights[0].position) - P;
  const double d = glm::length(to_light);
  const dvec3 L = to_light / d, V = glm::normalize(eye - P);
  if (glm::dot(N, L) <= 0.0) return 0.0;
  const dvec3 R = 2.0 * glm::dot(N, L) * N - L;
  const double IL = scene.lights[0].intensity.r / (pi * d * d);
  return IL * scene.materials[0].ks.r * std::pow(std::max(glm::dot(R, V), 0.0), double(shininess));
}

TEST(LocalModels, PhongFindsTheHighlightGouraudMissesIt) {
  const Scene scene = sphere_scene();
  const Image phong = render(scene, Shading::phong, false, false, true);
  const Image gouraud = render(scene, Shading::gouraud, false, false, true);

  // Phong's peak: the whole of ks * IL (cos^n(alpha) = 1 where R meets V). The mesh lies a little
  // inside the true sphere, so d and the pixel sampling shift it by a few percent at most.
  const double full = specular(scene, highlight_point(), highlight_point());
  EXPECT_NEAR(full, 0.6 * 30.0 / (pi * light_distance * light_distance), 1e-6 * full);
  EXPECT_NEAR(peak_red(phong), full, 0.05 * full);

  // Gouraud's peak is at most its brightest vertex's (colours are only interpolated), and on
  // this mesh no vertex is within 0.2 rad of the highlight: it is nearly lost.
  double brightest_vertex = 0.0;
  for (size_t v = 0; v < scene.meshes[0].positions.size(); ++v) {
    const dvec3 P(scene.meshes[0].positions[v]);
    brightest_vertex = std::max(brightest_vertex, specular(scene, P, P));
  }
  EXPECT_LT(brightest_vertex, 0.2 * full);
  EXPECT_LE(peak_red(gouraud), 1.01 * brightest_vertex + 1e-6);
  EXPECT_LT(peak_red(gouraud), 0.2f * peak_red(phong));
}

// Pixel-space projection of a world point, pixel centres at integers, row 0 at the top.
glm::dvec2 to_pixel(const Scene& scene, const glm::vec3& p) {
  const Camera& camera = scene.cameras[0];
  const glm::mat4 clip_from_world = camera.projection(1.0f, scene.bounds()) * camera.view();
  const glm::vec4 clip = clip_from_world * glm::vec4(p, 1.0f);
  const double x = clip.x / clip.w, y = clip.y / clip.w;
  return {(x + 1.0) / 2.0 * size - 0.5, (1.0 - y) / 2.0 * size - 0.5};
}

// The pixels whose centres lie well inside a triangle (all barycentrics > margin).
std::vector<glm::ivec2> interior_pixels(const glm::dvec2& a, const glm::dvec2& b,
                                        const glm::dvec2& c, double margin) {
  std::vector<glm::ivec2> pixels;
  const auto edge = [](const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& r) {
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
  };
  const double area = edge(a, b, c);
  const int x0 = int(std::floor(std::min({a.x, b.x, c.x}))),
            x1 = int(std::ceil(std::max({a.x, b.x, c.x})));
  const int y0 = int(std::floor(std::min({a.y, b.y, c.y}))),
            y1 = int(std::ceil(std::max({a.y, b.y, c.y})));
  for (int y = std::max(y0, 0); y <= std::min(y1, size - 1); ++y)
    for (int x = std::max(x0, 0); x <= std::min(x1, size - 1); ++x) {
      const glm::dvec2 p(x, y);
      const double wa = edge(b, c, p) / area, wb = edge(c, a, p) / area,
                   wc = edge(a, b, p) / area;
      if (wa > margin && wb > margin && wc > margin) pixels.emplace_back(x, y);
    }
  return pixels;
}

TEST(LocalModels, FlatShowsFacets) {
  const Scene scene = sphere_scene();
  const Image flat = render(scene, Shading::flat, true, true, true);
  const Mesh& mesh = scene.meshes[0];
  const Material& m = scene.materials[0];
  const dvec3 light(scene.lights[0].position);

  int faces_checked = 0;
  std::vector<double> face_red(mesh.triangle_count(), -1.0);
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const glm::vec3 a = mesh.positions[mesh.indices[3 * t]],
                    b = mesh.positions[mesh.indices[3 * t + 1]],
                    c = mesh.positions[mesh.indices[3 * t + 2]];
    const dvec3 centroid = dvec3(a + b + c) / 3.0;
    const dvec3 N = glm::normalize(glm::cross(dvec3(b - a), dvec3(c - a)));
    if (glm::dot(N, glm::normalize(eye - centroid)) < 0.3) continue;  // hidden or grazing
    const std::vector<glm::ivec2> pixels =
        interior_pixels(to_pixel(scene, a), to_pixel(scene, b), to_pixel(scene, c), 0.1);
    if (pixels.size() < 20) continue;

    // Within the triangle one colour...
    const Rgb first = flat.at(pixels[0].x, pixels[0].y);
    for (const glm::ivec2& p : pixels)
      ASSERT_NEAR(flat.at(p.x, p.y).r, first.r, 1e-5 * first.r)
          << "triangle " << t << " pixel " << p.x << ", " << p.y;

    // ... and it is the formula at the centroid with the face normal.
    const dvec3 to_light = light - centroid;
    const double d = glm::length(to_light);
    const dvec3 L = to_light / d, V = glm::normalize(eye - centroid);
    const double cos_theta = std::max(glm::dot(N, L), 0.0);
    const dvec3 R = 2.0 * glm::dot(N, L) * N - L;
    const double IL = scene.lights[0].intensity.r / (pi * d * d);
    double want = scene.ambient.r * m.ka.r;
    if (cos_theta > 0.0)
      want += IL * (m.kd.r * cos_theta +
                    m.ks.r * std::pow(std::max(glm::dot(R, V), 0.0), double(m.shininess)));
    EXPECT_NEAR(first.r, want, 0.01 * want) << "triangle " << t;
    face_red[t] = first.r;
    ++faces_checked;
  }
  EXPECT_GT(faces_checked, 30);

  // Neighbours differ: the two triangles of each checked quad of the UV grid (consecutive in the
  // index list, sharing the quad's diagonal) have different colours where the light reaches
  // them: each pair by far more than the 1e-5 noise inside a triangle, and by 3% on average.
  const double ambient = scene.ambient.r * m.ka.r;
  int pairs = 0;
  double sum_of_differences = 0.0;
  for (size_t t = 0; t + 1 < face_red.size(); ++t) {
    if (face_red[t] < 2.0 * ambient || face_red[t + 1] < 2.0 * ambient) continue;  // unlit
    const glm::uvec3 u(mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
    const glm::uvec3 w(mesh.indices[3 * t + 3], mesh.indices[3 * t + 4], mesh.indices[3 * t + 5]);
    if (u.x != w.x || u.z != w.y) continue;  // not the (a, d, c), (a, c, b) pair of one quad
    const double difference = std::abs(face_red[t] - face_red[t + 1]) / face_red[t];
    EXPECT_GT(difference, 1e-3) << "faces " << t << " and " << t + 1;
    sum_of_differences += difference;
    ++pairs;
  }
  ASSERT_GT(pairs, 10);
  EXPECT_GT(sum_of_differences / pairs, 0.03);
}

TEST(LocalModels, GouraudAndPhongAreSmoothFlatIsNot) {
  // Along a horizontal line across the lit sphere, away from the highlight, count jumps between
  // neighbouring pixels larger than 2% of the value: flat has one at every facet edge.
  const Scene scene = sphere_scene();
  const int y = size / 2 + 20;
  const auto jumps = [&](const Image& image) {
    int count = 0;
    for (int x = size / 2 - 60; x < size / 2 + 60; ++x) {
      const float here = image.at(x, y).r, next = image.at(x + 1, y).r;
      if (std::abs(next - here) > 0.02f * std::max(here, next)) ++count;
    }
    return count;
  };
  const Image flat = render(scene, Shading::flat, true, true, false);
  const Image gouraud = render(scene, Shading::gouraud, true, true, false);
  const Image phong = render(scene, Shading::phong, true, true, false);
  EXPECT_GE(jumps(flat), 3);
  EXPECT_EQ(jumps(gouraud), 0);
  EXPECT_EQ(jumps(phong), 0);
}

TEST(LocalModels, BackgroundWhereNothingIsDrawn) {
  Scene scene = sphere_scene();
  scene.background = Rgb(0.05f, 0.1f, 2.5f);  // radiance: above 1 must survive the float target
  for (Shading shading : {Shading::flat, Shading::gouraud, Shading::phong}) {
    const Image image = render(scene, shading, true, true, true);
    for (glm::ivec2 corner : {glm::ivec2(0, 0), glm::ivec2(size - 1, size - 1)}) {
      const Rgb p = image.at(corner.x, corner.y);
      EXPECT_EQ(p, scene.background) << to_string(shading);
    }
    // The sphere covers the centre.
    EXPECT_NE(image.at(size / 2, size / 2), scene.background) << to_string(shading);
  }
}

TEST(LocalModels, RenderKeepsTheCamerasVerticalFieldOfView) {
  // A wide picture shows the same vertical extent: the sphere's height in pixels is the same at
  // 256x256 and 512x256.
  const Scene scene = sphere_scene();
  LocalOptions options;
  LocalRenderer renderer(scene);
  const Image square = renderer.render(scene.cameras[0], size, size, options);
  const Image wide = renderer.render(scene.cameras[0], 2 * size, size, options);
  const auto covered_rows = [&](const Image& image) {
    int rows = 0;
    for (int y = 0; y < image.height; ++y)
      rows += image.at(image.width / 2, y) != scene.background;
    return rows;
  };
  // Closed form: in the plane x = 0 the mesh's outline is the polygon of its vertices there; the
  // steepest of them seen from the eye sets the half-height, tan / tan(yfov/2) of half the image.
  double steepest = 0.0;
  for (const glm::vec3& v : scene.meshes[0].positions)
    if (std::abs(v.x) < 1e-6f) steepest = std::max(steepest, std::abs(v.y) / (eye.z - v.z));
  const double expected = steepest / std::tan(0.3) * size;
  EXPECT_NEAR(covered_rows(square), expected, 2.0);
  EXPECT_NEAR(covered_rows(wide), expected, 2.0);
}

// Test::distant_faces_scene: with the file's 5 cm near plane the dark plate a metre behind the
// lit face wins pixels in depth-fighting stripes. Every local model draws every pixel of the
// face with its emission, for a far plane from the file and one chosen from the scene.
TEST(LocalModels, ADistantSceneKeepsItsDepthOrder) {
  for (float zfar : {0.0f, 1e6f}) {
    const Scene scene = test::distant_faces_scene(zfar);
    LocalRenderer renderer(scene);
    for (Shading shading : {Shading::flat, Shading::gouraud, Shading::phong}) {
      LocalOptions options;
      options.shading = shading;
      const Image image = renderer.render(scene.cameras[0], 64, 64, options);
      int wrong = 0;
      for (const Rgb& p : image.pixels) wrong += std::abs(p.g - 1.0f) > 1e-3f;
      EXPECT_EQ(wrong, 0) << "pixels of 64 x 64 showing the plate behind the face, " << to_string(shading)
                          << ", zfar " << zfar;
    }
  }
}

}  // namespace
}  // namespace luz
