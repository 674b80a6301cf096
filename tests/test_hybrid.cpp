// The hybrid model (slides 41-43): the Whitted tracer whose diffuse part is the radiosity
// solution (hybrid/radiosity_diffuse.h).
//
// - Where there is no mirror, glass or highlight (the Cornell box) the hybrid picture is the
//   radiosity picture: two implementations of "B/pi, interpolated across the patches" (the GL
//   Gouraud rasteriser and RadianceField::at at the ray's hit) agree within 0.5% + 1e-4 of the
//   picture's largest value at every pixel whose 3x3 neighbourhood sees one mesh (silhouettes
//   are sampled differently by a rasteriser and by rays through pixel centres).
// - On cornell_spheres the floor keeps its radiosity shading (same comparison, floor pixels),
//   and the mirror shows the room as radiosity lit it: where it reflects the red wall it is red,
//   and the ceiling it reflects is the ceiling radiosity lit, within the range of the ceiling
//   patches' B/pi: Whitted lights the ceiling by the ambient term alone, exactly Ia ka (the lamp
//   faces down), radiosity by the light the room sends back up.
// - The mirror sphere's highlight is Whitted's, pixel for pixel, and slide 15's closed form.
//
// - A textured floor shows its texture in radiosity and in the hybrid alike: the solution, made
//   with the texture's mean texel, times texel / mean (radiosity/texture_detail.h).
//
// One OSMesa context for the whole binary: the radiosity solves draw hemicubes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/scene.h"
#include "hybrid/radiosity_diffuse.h"
#include "io/gltf_loader.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/radiosity_renderer.h"
#include "radiosity/shooting.h"
#include "raytracing/renderer.h"
#include "support.h"

namespace luz {
namespace {

constexpr int kSize = 120;

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// A scene solved by radiosity, pictured by radiosity (GL), by the hybrid and by Whitted.
struct Pictures {
  Scene scene;
  PatchMesh mesh;
  RadianceField field;  // the converged solution's
  Image radiosity, hybrid, whitted;
  std::vector<int> mesh_at;  // the mesh each pixel centre's primary ray hits (-1: none)
  std::unique_ptr<hybrid::RadiosityDiffuse> diffuse;
  std::unique_ptr<rt::WhittedRenderer> tracer, hybrid_tracer;  // Whitted's; with the diffuse source

  Pictures(const std::string& name, const RadiosityOptions& options)
      : Pictures(io::load_gltf(test::scene_dir() / (name + ".gltf")).scene, options) {}

  Pictures(Scene loaded, const RadiosityOptions& options) : scene(std::move(loaded)) {
    mesh = PatchMesh::build(scene, options);
    ProgressiveSolver solver(scene, mesh, options);
    while (solver.step()) {}
    const Camera& camera = scene.cameras.front();
    field = RadianceField::of(solver);
    RadiosityRenderer renderer(scene, mesh);
    renderer.update(field, options);
    radiosity = renderer.render(camera, kSize, kSize, options);

    diffuse = std::make_unique<hybrid::RadiosityDiffuse>(mesh, RadianceField::of(solver));
    tracer = std::make_unique<rt::WhittedRenderer>(scene);
    hybrid_tracer = std::make_unique<rt::WhittedRenderer>(scene);
    hybrid_tracer->set_diffuse_source(diffuse.get());
    hybrid = hybrid_tracer->render(camera, kSize, kSize, rt::WhittedOptions{});
    whitted = tracer->render(camera, kSize, kSize, rt::WhittedOptions{});
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        mesh_at.push_back(tracer->primary_hit(camera, kSize, kSize, {float(x) + 0.5f, float(y) + 0.5f}, {}).mesh);
  }

  int mesh_index(const std::string& name) const {
    for (size_t i = 0; i < scene.meshes.size(); ++i)
      if (scene.meshes[i].name == name) return int(i);
    return -2;
  }

  // Pixels whose 3x3 neighbourhood sees one mesh, and that one is `only` (any, when -1).
  std::vector<std::pair<int, int>> interior_pixels(int only = -1) const {
    std::vector<std::pair<int, int>> pixels;
    for (int y = 1; y + 1 < kSize; ++y)
      for (int x = 1; x + 1 < kSize; ++x) {
        const int m = mesh_at[size_t(y * kSize + x)];
        bool one = m >= 0 && (only < 0 || m == only);
        for (int dy = -1; dy <= 1 && one; ++dy)
          for (int dx = -1; dx <= 1 && one; ++dx) one = mesh_at[size_t((y + dy) * kSize + x + dx)] == m;
        if (one) pixels.emplace_back(x, y);
      }
    return pixels;
  }
};

// Within 0.5% + 1e-4 of the radiosity picture's largest value, per channel.
void expect_radiosity_shading(const Pictures& p, const std::vector<std::pair<int, int>>& pixels) {
  float largest = 0.0f;
  for (const Rgb& c : p.radiosity.pixels) largest = std::max({largest, c.r, c.g, c.b});
  int failures = 0;
  float worst = 0.0f;
  for (const auto& [x, y] : pixels) {
    const Rgb a = p.hybrid.at(x, y), b = p.radiosity.at(x, y);
    for (int c = 0; c < 3; ++c) {
      const float difference = std::abs(a[c] - b[c]);
      worst = std::max(worst, difference / largest);
      if (difference > 0.005f * std::abs(b[c]) + 1e-4f * largest) ++failures;
    }
  }
  EXPECT_EQ(failures, 0) << "of " << pixels.size() << " pixels; worst difference " << worst
                         << " of the largest value";
}

RadiosityOptions coarse(float patch_size, float converge) {
  RadiosityOptions options;
  options.patch_size = patch_size;
  options.hemicube_res = 64;
  options.converge = converge;
  // The hybrid's primary rays go through pixel centres: the radiosity picture is sampled there too.
  options.pixel_samples = 1;
  return options;
}

TEST(Hybrid, WithoutMirrorGlassOrHighlightItIsTheRadiosityPicture) {
  const Pictures p("cornell_box", coarse(0.1f, 0.01f));
  const auto pixels = p.interior_pixels();
  ASSERT_GT(pixels.size(), size_t(kSize * kSize / 2));
  expect_radiosity_shading(p, pixels);
}

class CornellSpheres : public testing::Test {
protected:
  static void SetUpTestSuite() { pictures_ = new Pictures("cornell_spheres", coarse(0.12f, 0.02f)); }
  static void TearDownTestSuite() { delete pictures_; }
  static Pictures* pictures_;
};
Pictures* CornellSpheres::pictures_ = nullptr;

TEST_F(CornellSpheres, TheFloorKeepsItsRadiosityShading) {
  const Pictures& p = *pictures_;
  const auto pixels = p.interior_pixels(p.mesh_index("floor"));
  ASSERT_GT(pixels.size(), size_t(500));
  expect_radiosity_shading(p, pixels);
}

TEST_F(CornellSpheres, TheMirrorShowsTheColourBledRoom) {
  const Pictures& p = *pictures_;
  const Camera& camera = p.scene.cameras.front();
  const int mirror = p.mesh_index("mirror_sphere");
  // What the mirror's reflected ray hits and brings back (its radiance, before kr), from the
  // pixel's ray tree in each model.
  const auto reflected = [&](int x, int y, rt::WhittedRenderer& tracer) {
    const rt::RayTree tree = tracer.trace_pixel(camera, kSize, kSize, x, y, rt::WhittedOptions{});
    for (const rt::RayTreeNode& node : tree.nodes)
      if (node.parent == 0 && node.kind == rt::RayKind::reflected && node.hit) return node;
    return rt::RayTreeNode{};
  };
  // The ceiling as each model lights it. Whitted: the ambient term alone, Ia ka (the lamp
  // faces down and the ceiling has no mirror or highlight). Radiosity: B/pi interpolated
  // between the ceiling patches' vertex values, so within their range (a convex combination).
  const int ceiling = p.mesh_index("ceiling");
  const Material& white = p.scene.materials[size_t(p.scene.meshes[size_t(ceiling)].material)];
  const float ambient = luminance(p.scene.ambient * white.ka);
  // The ceiling straight above the lamp sees only the lamp's dark back: the mirror reflects the
  // rest, so the range is taken outside the lamp's footprint (grown by its own half size).
  const Mesh& lamp = p.scene.meshes[size_t(p.mesh_index("light"))];
  glm::vec3 lamp_low(1e30f), lamp_high(-1e30f);
  for (const glm::vec3& q : lamp.positions) {
    lamp_low = glm::min(lamp_low, q);
    lamp_high = glm::max(lamp_high, q);
  }
  const glm::vec3 margin = 0.5f * (lamp_high - lamp_low);
  const auto above_lamp = [&](const glm::vec3& q) {
    return q.x > lamp_low.x - margin.x && q.x < lamp_high.x + margin.x && q.z > lamp_low.z - margin.z &&
           q.z < lamp_high.z + margin.z;
  };
  float lowest = 1e30f, highest = 0.0f;
  for (size_t e = 0; e < p.mesh.size(); ++e)
    if (p.mesh.patches[e].mesh == ceiling)
      for (size_t k = 0; k < 3; ++k) {
        if (above_lamp(p.mesh.vertices[p.mesh.patches[e].vertices[k]])) continue;
        lowest = std::min(lowest, luminance(p.diffuse->field().corner[3 * e + k]));
        highest = std::max(highest, luminance(p.diffuse->field().corner[3 * e + k]));
      }
  // Radiosity's ceiling is darkest at its rim, in the corners with the walls; its range reaches
  // down about to Whitted's ambient value there, so the two models are told apart by the mean
  // below as well as by the range.
  int red_seen = 0, ceiling_seen = 0;
  double ceiling_hybrid = 0.0;
  for (const auto& [x, y] : p.interior_pixels(mirror)) {
    const rt::RayTreeNode hybrid = reflected(x, y, *p.hybrid_tracer);
    if (hybrid.mesh == "left_wall_red") {
      ++red_seen;
      EXPECT_GT(p.hybrid.at(x, y).r, 3.0f * p.hybrid.at(x, y).g)
          << "pixel " << x << "," << y << " mirrors the red wall";
    } else if (hybrid.mesh == "ceiling") {
      ++ceiling_seen;
      const float seen = luminance(hybrid.radiance);
      ceiling_hybrid += double(seen);
      EXPECT_GE(seen, lowest * (1.0f - 1e-5f)) << "pixel " << x << "," << y;
      EXPECT_LE(seen, highest * (1.0f + 1e-5f)) << "pixel " << x << "," << y;
      EXPECT_NEAR(luminance(reflected(x, y, *p.tracer).radiance), ambient, 1e-6f)
          << "pixel " << x << "," << y;
    }
  }
  EXPECT_GT(red_seen, 10);
  ASSERT_GT(ceiling_seen, 10);
  EXPECT_GT(ceiling_hybrid / ceiling_seen, 1.5 * ambient) << "radiosity lights the ceiling above Whitted's ambient term";
  printf("the ceiling in the mirror, mean luminance: hybrid %.4f (radiosity's ceiling %.4f .. %.4f), "
         "Whitted %.4f (%d pixels)\n", ceiling_hybrid / ceiling_seen, lowest, highest, ambient,
         ceiling_seen);
}

// The highlights come from rays in both models: IL ks cos^n(alpha), the same at every pixel of
// the hybrid as of Whitted. A pixel's highlight is its picture with highlights minus without;
// at the mirror sphere's brightest highlight the two models agree (to float rounding, 1e-5 of
// the pixel), and both equal slide 15's closed form summed over the lamp's triangles, each a
// point of intensity Le A cos(theta_e) at its centroid, that reach the hit unblocked.
TEST_F(CornellSpheres, TheHighlightsAreWhittedsHighlights) {
  const Pictures& p = *pictures_;
  const Camera& camera = p.scene.cameras.front();
  rt::WhittedOptions no_highlight;
  no_highlight.terms.specular = false;
  const Image whitted_dull = p.tracer->render(camera, kSize, kSize, no_highlight);
  const Image hybrid_dull = p.hybrid_tracer->render(camera, kSize, kSize, no_highlight);
  const auto highlight = [](const Image& shiny, const Image& dull, int x, int y) {
    return luminance(shiny.at(x, y)) - luminance(dull.at(x, y));
  };
  int hx = -1, hy = -1;
  float brightest = 0.0f;
  for (const auto& [x, y] : p.interior_pixels(p.mesh_index("mirror_sphere")))
    if (highlight(p.whitted, whitted_dull, x, y) > brightest) {
      brightest = highlight(p.whitted, whitted_dull, x, y);
      hx = x;
      hy = y;
    }
  ASSERT_GE(hx, 0) << "the mirror sphere shows a highlight";
  printf("the mirror sphere's highlight at %d,%d: %.4f\n", hx, hy, brightest);
  const float rounding = 1e-5f * luminance(p.hybrid.at(hx, hy));
  EXPECT_GT(brightest, 100.0f * rounding) << "a highlight far above the comparison's tolerance";
  EXPECT_NEAR(highlight(p.hybrid, hybrid_dull, hx, hy), brightest, rounding);

  // The closed form at the primary hit, from the ray tree's hit point, normal and shadow rays.
  const rt::RayTree tree = p.hybrid_tracer->trace_pixel(camera, kSize, kSize, hx, hy, rt::WhittedOptions{});
  const rt::RayTreeNode& primary = tree.nodes[0];
  ASSERT_EQ(primary.mesh, "mirror_sphere");
  const Material& mirror = p.scene.materials[size_t(p.scene.meshes[size_t(p.mesh_index("mirror_sphere"))].material)];
  const glm::dvec3 P(primary.hit_point), N(primary.normal), V = -glm::dvec3(primary.direction);
  double expected = 0.0;
  for (const rt::RayTreeNode& shadow : tree.nodes) {
    if (shadow.parent != 0 || shadow.kind != rt::RayKind::shadow || shadow.hit) continue;
    ASSERT_GE(size_t(shadow.light), p.scene.lights.size()) << "the scene's only light is its lamp";
    const AreaLight& lamp = p.scene.area_lights[size_t(shadow.light) - p.scene.lights.size()];
    const glm::dvec3 to_lamp = glm::dvec3(lamp.centroid) - P;
    const double d = glm::length(to_lamp);
    const glm::dvec3 L = to_lamp / d;
    const double cos_e = std::max(glm::dot(glm::dvec3(lamp.normal), -L), 0.0);
    const double IL = luminance(lamp.radiance) * lamp.area * cos_e / (d * d) / std::numbers::pi;
    const glm::dvec3 R = 2.0 * glm::dot(N, L) * N - L;  // the light's mirror direction
    expected += IL * luminance(mirror.ks) * std::pow(std::max(glm::dot(R, V), 0.0), mirror.shininess);
  }
  // n = 300 turns a float rounding of cos(alpha) (1e-7) into 3e-5 of the highlight.
  EXPECT_NEAR(brightest, expected, 1e-3 * expected);
}

// A 2 m floor seen from above under a lamp. Textured: kd 1 and an 8 x 8 texture in four 4 x 4
// blocks of 0.2 and 0.8 (mean 0.5), mapped once; plain: kd 0.5. The two have the same patches'
// reflectance, so the same solution.
Scene lamp_over_floor(bool textured) {
  Scene scene;
  Mesh floor;
  floor.name = "floor";
  floor.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  floor.normals.assign(4, glm::vec3(0, 1, 0));
  floor.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  floor.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from above
  scene.meshes.push_back(floor);
  Material material;
  material.kd = Rgb(textured ? 1.0f : 0.5f);
  if (textured) {
    Texture blocks;
    blocks.width = blocks.height = 8;
    blocks.texels.assign(64, Rgb(0.0f));
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) blocks.texels[size_t(y * 8 + x)] = Rgb((x < 4) == (y < 4) ? 0.2f : 0.8f);
    scene.textures.push_back(blocks);
    material.kd_texture = 0;
  }
  scene.materials.push_back(material);
  Light lamp;
  lamp.position = {0.2f, 1.5f, 0.1f};
  lamp.intensity = Rgb(3.0f);
  scene.lights.push_back(lamp);
  Camera camera;
  camera.to_world = glm::translate(glm::mat4(1.0f), glm::vec3(0, 2.2f, 0)) *
                    glm::rotate(glm::mat4(1.0f), -0.5f * std::numbers::pi_v<float>, glm::vec3(1, 0, 0));
  camera.yfov = 0.8f;
  scene.cameras.push_back(camera);
  return scene;
}

TEST(Hybrid, ATexturedFloorShowsItsTextureInRadiosityAndTheHybridAlike) {
  const RadiosityOptions options = coarse(0.25f, 0.01f);
  const Pictures textured(lamp_over_floor(true), options), plain(lamp_over_floor(false), options);
  // Radiosity: texel / mean = 0.4 or 1.6 times the plain picture, exactly inside the blocks and
  // in between across their edges (where GL's linear filter blends a block with the next).
  const auto pixels = textured.interior_pixels();
  ASSERT_GT(pixels.size(), size_t(kSize * kSize / 2));
  int dark = 0, light = 0, outside = 0;
  for (const auto& [x, y] : pixels) {
    const float ratio = luminance(textured.radiosity.at(x, y)) / luminance(plain.radiosity.at(x, y));
    dark += std::abs(ratio - 0.4f) < 0.004f;
    light += std::abs(ratio - 1.6f) < 0.016f;
    outside += ratio < 0.4f * 0.99f || ratio > 1.6f * 1.01f;
  }
  EXPECT_GT(dark, int(pixels.size() / 5));
  EXPECT_GT(light, int(pixels.size() / 5));
  EXPECT_EQ(outside, 0);
  // The hybrid's diffuse part is that picture, pixel for pixel.
  expect_radiosity_shading(textured, pixels);
  // The heat map's colours are no radiance: a renderer told so leaves the texture out.
  RadiosityRenderer renderer(textured.scene, textured.mesh);
  renderer.update(textured.field, options, false);
  const Image untextured = renderer.render(textured.scene.cameras.front(), kSize, kSize, options);
  for (const auto& [x, y] : pixels)
    ASSERT_NEAR(luminance(untextured.at(x, y)), luminance(plain.radiosity.at(x, y)),
                1e-4f + 1e-3f * luminance(plain.radiosity.at(x, y)));
}

// Without textures (`--no-textures`, the viewer's T) the floor is its kd alone, in the solution
// and in the picture: the same as the floor with the texture taken out of the scene.
TEST(Hybrid, WithoutTexturesATexturedFloorIsItsKdAlone) {
  RadiosityOptions options = coarse(0.25f, 0.01f);
  Scene untextured = lamp_over_floor(true);
  untextured.materials.front().kd_texture = -1;
  untextured.textures.clear();
  const Pictures expected(untextured, options);
  options.textures = false;
  const Pictures switched_off(lamp_over_floor(true), options);
  EXPECT_FALSE(switched_off.mesh.detail.textures());
  for (const Patch& p : switched_off.mesh.patches) ASSERT_EQ(p.rho, Rgb(1.0f));
  const auto pixels = switched_off.interior_pixels();
  ASSERT_GT(pixels.size(), size_t(kSize * kSize / 2));
  for (const auto& [x, y] : pixels) {
    ASSERT_EQ(switched_off.radiosity.at(x, y), expected.radiosity.at(x, y)) << x << "," << y;
    ASSERT_EQ(switched_off.hybrid.at(x, y), expected.hybrid.at(x, y)) << x << "," << y;
  }
}

// The patches' reflectance is kd times the mean texel of the texture the mesh shows; a mesh
// without TEXCOORD_0 shows none (as in Whitted's model), so its patches take kd alone.
TEST(Hybrid, APatchTakesTheMeanTexelOfTheTextureItsMeshShows) {
  const RadiosityOptions options = coarse(0.5f, 0.01f);
  const Scene textured = lamp_over_floor(true);
  for (const Patch& p : PatchMesh::build(textured, options).patches) ASSERT_EQ(p.rho, Rgb(0.5f));
  Scene unmapped = lamp_over_floor(true);
  unmapped.meshes.front().uvs.clear();
  for (const Patch& p : PatchMesh::build(unmapped, options).patches) ASSERT_EQ(p.rho, Rgb(1.0f));
}

// The picture draws a textured mesh apart from the untextured ones; the shooter's highlight
// still falls on the shooter's elements. A small untextured tile comes first, so the floor's
// elements are drawn by a second call: its highlight must be where the plain scene, drawn in one
// call, has it.
TEST(Hybrid, TheShootersHighlightFindsItsPatchOnATexturedMesh) {
  const auto with_tile = [](bool textured) {
    Scene scene = lamp_over_floor(textured);
    Mesh tile = scene.meshes.front();
    tile.name = "tile";
    tile.uvs.clear();
    for (glm::vec3& p : tile.positions) p = 0.2f * p + glm::vec3(-0.7f, 0.01f, -0.7f);
    scene.meshes.insert(scene.meshes.begin(), tile);
    return scene;
  };
  const RadiosityOptions options = coarse(0.25f, 0.01f);
  const auto highlighted = [&](const Scene& scene, std::vector<bool>& magenta) {
    PatchMesh mesh = PatchMesh::build(scene, options);
    RadiosityRenderer renderer(scene, mesh);
    ProgressiveSolver solver(scene, mesh, options);
    renderer.update(RadianceField::of(solver), options);
    const int shooter = int(mesh.shooters.size()) - 3;  // on the floor, whose patches come last
    ASSERT_EQ(mesh.patches[mesh.members[mesh.shooters[size_t(shooter)].first]].mesh, 1);
    const Image image = renderer.render(scene.cameras.front(), kSize, kSize, options, shooter);
    for (const Rgb& c : image.pixels) magenta.push_back(c.r > 3.0f && c.g < 0.5f && c.b > 3.0f);
  };
  std::vector<bool> textured, plain;
  highlighted(with_tile(true), textured);
  highlighted(with_tile(false), plain);
  EXPECT_GT(std::count(plain.begin(), plain.end(), true), 20);
  EXPECT_EQ(textured, plain);
}

// The highlight falls where the shooter is: every magenta pixel of the floor seen from straight
// above (x right, z up the picture, half-width tan(yfov / 2) x 2.2 at the floor) lies inside the
// bounding box of the shooter's elements, within two pixels, and it covers a good share of it
// (a triangle fills half its box).
TEST(Hybrid, TheShootersHighlightIsOnTheShootersElements) {
  const Scene scene = lamp_over_floor(false);
  const RadiosityOptions options = coarse(0.25f, 0.01f);
  PatchMesh mesh = PatchMesh::build(scene, options);
  RadiosityRenderer renderer(scene, mesh);
  ProgressiveSolver solver(scene, mesh, options);
  renderer.update(RadianceField::of(solver), options);
  const float half = std::tan(0.5f * scene.cameras.front().yfov) * 2.2f, pixel = 2.0f * half / kSize;
  int checked = 0;
  for (size_t shooter = 0; shooter < mesh.shooters.size(); shooter += 7) {
    Bounds box;
    for (uint32_t k = 0; k < mesh.shooters[shooter].count; ++k)
      for (const uint32_t v : mesh.patches[mesh.members[mesh.shooters[shooter].first + k]].vertices)
        box.grow(mesh.vertices[v]);
    if (std::max({-box.min.x, box.max.x, -box.min.z, box.max.z}) > 0.9f * half) continue;  // not all in view
    ++checked;
    const Image image = renderer.render(scene.cameras.front(), kSize, kSize, options, int(shooter));
    int magenta = 0, outside = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const Rgb c = image.at(x, y);
        if (!(c.r > 3.0f && c.g < 0.5f && c.b > 3.0f)) continue;
        ++magenta;
        const float wx = (float(x) + 0.5f) * pixel - half, wz = (float(y) + 0.5f) * pixel - half;
        outside += wx < box.min.x - 2.0f * pixel || wx > box.max.x + 2.0f * pixel ||
                   wz < box.min.z - 2.0f * pixel || wz > box.max.z + 2.0f * pixel;
      }
    const float box_pixels = (box.max.x - box.min.x) * (box.max.z - box.min.z) / (pixel * pixel);
    EXPECT_EQ(outside, 0) << "shooter " << shooter;
    EXPECT_GT(float(magenta), 0.25f * box_pixels) << "shooter " << shooter;
  }
  EXPECT_GT(checked, 10);
}

}  // namespace
}  // namespace luz
