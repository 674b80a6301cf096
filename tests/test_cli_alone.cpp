// The command line without the window: this program links the cli library and two headless
// models (their renders, no views) and nothing of the viewer, ImGui or GLFW; its registry table
// is its own, as a program that joins the models' renders only would write it. Its pictures must
// be those `luz render` writes.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include "app/cli/render_command.h"
#include "app/common/model_registry.h"
#include "app/common/options_tables.h"
#include "app/models/local/render_local.h"
#include "app/models/whitted/render_whitted.h"
#include "support.h"

namespace luz::app {
namespace {

constexpr const char* local_flags[] = {"terms", "ambient-emission", "textures", "local"};
constexpr const char* whitted_flags[] = {"terms", "ambient-emission", "textures", "whitted", "sampling"};

Rendered render_flat(const Scene& scene, const Camera& camera, int width, int height, const RenderSettings& settings) {
  return render_local(Shading::flat, scene, camera, width, height, settings);
}

Rendered render_traced(const Scene& scene, const Camera& camera, int width, int height, const RenderSettings& settings) {
  return render_whitted(scene, camera, width, height, settings);
}

constexpr OptionTableOf local_options[] = {local_table};
constexpr OptionTableOf whitted_options[] = {local_table, whitted_table};

const ModelEntry table[] = {
    {"flat", "flat", 1, "flat shading", local_flags, local_options, render_flat, nullptr, {}, nullptr},
    {"whitted", "Whitted", 4, "Whitted ray tracing", whitted_flags, whitted_options, render_traced, nullptr, {}, nullptr},
};

}  // namespace

std::span<const ModelEntry> catalogue() { return table; }

}  // namespace luz::app

namespace {

std::string bytes_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The same picture through this program's run_render and through `luz render`.
void expect_as_luz_renders(const std::string& model) {
  luz::test::ScratchDir scratch;
  luz::app::RenderSettings settings;
  settings.scene = (luz::test::scene_dir() / "cornell_box.gltf").string();
  settings.model = model;
  settings.out = (scratch / "alone.png").string();
  settings.width = 64;
  settings.height = 48;
  settings.quiet = true;
  ASSERT_EQ(luz::app::run_render(settings), 0);
  const auto luz = luz::test::run_luz({"render", settings.scene, "--model", model, "--size", "64x48",
                                       "--out", (scratch / "luz.png").string()});
  ASSERT_EQ(luz.exit_code, 0) << luz.output;
  const std::string alone = bytes_of(scratch / "alone.png");
  EXPECT_FALSE(alone.empty());
  EXPECT_EQ(alone, bytes_of(scratch / "luz.png")) << model << ": the picture differs from luz render's";
}

TEST(CliAlone, FlatAsLuzRendersIt) { expect_as_luz_renders("flat"); }
TEST(CliAlone, WhittedAsLuzRendersIt) { expect_as_luz_renders("whitted"); }

}  // namespace
