// The radiosity item buffer (shaders/item_buffer.*) compiled as GLSL ES 3.00, the page's dialect,
// on the desktop's Mesa (a 4.3+ core context takes both, gl/glsl_dialect.h): it names the same
// patch in every pixel as the desktop's program: two ways of naming patch i, gl_PrimitiveID over
// the indexed list on the desktop and gl_VertexID / 3 over an unindexed one in GLSL ES (which has
// no gl_PrimitiveID). The radiosity tests hold the desktop's names to the form factors they give.
// The OpenGL context comes from the GlEnvironment of gl_environment.cpp (same binary).
#include <cstdint>
#include <set>
#include <vector>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/scene.h"
#include "gl/glsl_dialect.h"
#include "gl/item_framebuffer.h"
#include "io/gltf_loader.h"
#include "radiosity/item_buffer.h"
#include "radiosity/patch_mesh.h"
#include "glsl_dialect_scope.h"
#include "support.h"

namespace luz {
namespace {

// The item buffer of `mesh` seen from `eye` towards `centre` (a 90-degree square view), with the
// programs compiled in `dialect`.
std::vector<uint32_t> item_buffer(const PatchMesh& mesh, gl::GlslDialect dialect, const glm::vec3& eye,
                                  const glm::vec3& centre) {
  const DialectScope scope(dialect);
  const PatchItems items(mesh);
  constexpr int side = 96;
  const gl::ItemFramebuffer target(side, side);
  target.bind_and_clear();
  glViewport(0, 0, side, side);
  items.begin();
  items.draw(glm::perspective(glm::radians(90.0f), 1.0f, 0.01f, 20.0f) * glm::lookAt(eye, centre, {0, 1, 0}));
  items.end();
  std::vector<uint32_t> ids;
  target.read(ids);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return ids;
}

TEST(ItemBufferGlslEs, NamesTheSamePatchesAsTheDesktop) {
  const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "cornell_box.gltf");
  const PatchMesh mesh = PatchMesh::build(loaded.scene, 0.1f);
  Bounds box;
  for (const glm::vec3& v : mesh.vertices) box.grow(v);
  const glm::vec3 middle = box.centre();
  // Inside the box towards a wall, and from behind the far wall (its back: ID 0, depth kept).
  const glm::vec3 views[][2] = {{middle, middle + glm::vec3(0, 0, -1)},
                                {middle + glm::vec3(0.1f, 0.2f, 0), middle + glm::vec3(1, -0.5f, 0)},
                                {middle + glm::vec3(0, 0, -2.0f * (box.max.z - box.min.z)), middle}};
  for (const auto& view : views) {
    const std::vector<uint32_t> desktop = item_buffer(mesh, gl::GlslDialect::desktop_330, view[0], view[1]);
    const std::vector<uint32_t> es = item_buffer(mesh, gl::GlslDialect::es_300, view[0], view[1]);
    ASSERT_EQ(desktop.size(), es.size());
    size_t different = 0;
    std::set<uint32_t> seen;
    for (size_t i = 0; i < desktop.size(); ++i) {
      different += desktop[i] != es[i];
      ASSERT_LE(desktop[i], mesh.size()) << "pixel " << i << ": ID + 1 past the last patch";
      if (desktop[i]) seen.insert(desktop[i]);
    }
    EXPECT_EQ(different, 0u);
    EXPECT_GT(seen.size(), 20u) << "the view sees many patches";
  }
}

// The one-pass atlas needs clip distances, which GLSL ES 3.00 lacks: refused with the driver's
// message when it is asked for, while the five-pass items above draw.
TEST(ItemBufferGlslEs, TheAtlasIsRefusedInGlslEs) {
  const io::LoadedScene loaded = io::load_gltf(test::scene_dir() / "cornell_box.gltf");
  const PatchMesh mesh = PatchMesh::build(loaded.scene, 0.5f);
  const DialectScope scope(gl::GlslDialect::es_300);
  const PatchItems items(mesh);
  const AtlasFace face{glm::mat4(1.0f), 0, 0, 8, 8};
  items.begin();
  EXPECT_THROW(items.draw_atlas({&face, 1}, 8, 8), Error);
  items.end();
}

}  // namespace
}  // namespace luz
