// The path tracer against converged radiosity on the Cornell box that ships: every surface is
// diffuse (ks = 0) and there is no mirror or glass, so both solve the same equation (SCENES.md),
// radiosity up to its meshing (constant patches, Gouraud-interpolated, hemicube form factors).
//
// Compared: each mesh's mean radiance over the pixels that see only that mesh (3x3), per channel,
// the path tracer's mean (with its standard error) against radiosity's B/pi at the same pixel
// centres (read through the hybrid's RadianceField, so no rasteriser is involved).
//
// The discretisation error, measured on this scene (path tracer minus radiosity, per mesh and
// channel): with 10 cm patches and a 64-pixel hemicube (this test) -0.9% to +5.6%, the short
// block's green +7.6% with a standard error of 2%; with 5 cm patches and 128 pixels, +0.1% to
// +1.6%, the short block +3.5%. Radiosity is darker everywhere, and less so on the finer mesh:
// its constant patches and hemicube lose light that the path tracer keeps. The test allows 6% +
// 3 standard errors per mesh and channel (the 5 cm solve takes minutes, too long for a test).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "hybrid/radiosity_diffuse.h"
#include "io/gltf_loader.h"
#include "radiosity/patch_mesh.h"
#include "radiosity/shooting.h"
#include "raytracing/path_tracer.h"
#include "raytracing/renderer.h"
#include "support.h"

namespace luz {
namespace {

constexpr int kSize = 48;

TEST(PathVsRadiosity, CornellBoxMeshMeansAgreeWithinTheDiscretisationError) {
  const Scene scene = io::load_gltf(test::scene_dir() / "cornell_box.gltf").scene;
  const Camera& camera = scene.cameras.front();

  RadiosityOptions radiosity;
  radiosity.patch_size = 0.1f;
  radiosity.hemicube_res = 64;
  radiosity.converge = 0.002f;  // converged: 0.2% of the power left unshot
  PatchMesh mesh = PatchMesh::build(scene, radiosity);
  ProgressiveSolver solver(scene, mesh, radiosity);
  while (solver.step()) {}
  const hybrid::RadiosityDiffuse diffuse(mesh, RadianceField::of(solver));
  rt::WhittedRenderer tracer(scene);
  tracer.set_diffuse_source(&diffuse);
  rt::WhittedOptions hybrid_options;
  hybrid_options.max_depth = 1;  // B/pi at the primary hit, nothing else
  const Image reference = tracer.render(camera, kSize, kSize, hybrid_options);

  rt::PathRenderer path(scene);
  rt::PathOptions options;
  options.max_depth = 64;
  rt::PathFilm film(kSize, kSize);
  path.add_samples(film, camera, options, 128);
  const Image mean = film.mean(), error = film.standard_error();

  std::vector<int> mesh_at;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      mesh_at.push_back(tracer.primary_hit(camera, kSize, kSize, {float(x) + 0.5f, float(y) + 0.5f}, {}).mesh);
  struct Sums { glm::dvec3 path{0.0}, variance{0.0}, radiosity{0.0}; int pixels = 0; };
  std::map<int, Sums> sums;
  for (int y = 1; y + 1 < kSize; ++y)
    for (int x = 1; x + 1 < kSize; ++x) {
      const int m = mesh_at[size_t(y * kSize + x)];
      bool one = m >= 0;
      for (int dy = -1; dy <= 1 && one; ++dy)
        for (int dx = -1; dx <= 1 && one; ++dx) one = mesh_at[size_t((y + dy) * kSize + x + dx)] == m;
      if (!one || scene.materials[size_t(scene.meshes[size_t(m)].material)].is_emissive()) continue;
      Sums& s = sums[m];
      s.path += glm::dvec3(mean.at(x, y));
      s.variance += glm::dvec3(error.at(x, y)) * glm::dvec3(error.at(x, y));
      s.radiosity += glm::dvec3(reference.at(x, y));
      ++s.pixels;
    }
  ASSERT_GE(sums.size(), size_t(7));  // floor, ceiling, three walls, two blocks
  for (const auto& [m, s] : sums) {
    const glm::dvec3 p = s.path / double(s.pixels), r = s.radiosity / double(s.pixels);
    const glm::dvec3 e = glm::sqrt(s.variance) / double(s.pixels);
    for (int c = 0; c < 3; ++c) {
      std::printf("%-18s channel %d: path %.5f +- %.5f, radiosity %.5f (%+.2f%%)\n",
                  scene.meshes[size_t(m)].name.c_str(), c, p[c], e[c], r[c], 100.0 * (p[c] / r[c] - 1.0));
      EXPECT_LT(std::abs(p[c] - r[c]), 0.06 * r[c] + 3.0 * e[c]) << scene.meshes[size_t(m)].name << " channel " << c;
    }
  }
}

}  // namespace
}  // namespace luz
