// Real glTF files from elsewhere: the glTF 2.0 models of Debian's assimp-testmodels package
// (/usr/share/assimp/models/glTF2, installed by setup.sh). Each model either renders in every
// illumination model with a sensible picture, or is refused with the documented message; the
// refusals are listed below with the reason for each. Pictures are tiny and radiosity coarse:
// the property checked is "something is lit and nothing is NaN", not the look.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/common/model_registry.h"
#include "app/cli/render_command.h"
#include "core/error.h"
#include "core/scene.h"
#include "io/gltf_loader.h"
#include "io/image_io.h"
#include "support.h"

namespace luz::test {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models/glTF2";

// Files refused on purpose: the path under kModels, a part of the message, and why.
struct Refusal {
  const char* message;
  const char* reason;
};
const std::map<std::string, Refusal> kRefused = {
    {"BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf",
     {"requires the glTF extension KHR_technique_webgl", "shaders in the file (a glTF 1.0 idea)"}},
    {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
     {"POSITION: element 0 is infinite", "infinite vertex positions"}},
    {"IncorrectVertexArrays/Cube.gltf",
     {"35 indices are not a whole number of triangles", "a truncated index list"}},
    {"IndexOutOfRange/AllIndicesOutOfRange.gltf",
     {"index 65535 (element 0) is past the 24 vertices", "indices past the vertex array"}},
    {"IndexOutOfRange/IndexOutOfRange.gltf",
     {"index 255 (element 0) is past the 24 vertices", "an index past the vertex array"}},
    {"MissingBin/BoxTextured.gltf",
     {"\"BoxTextured0.bin\" does not exist", "its buffer file is not in the package"}},
    {"RecursiveNodes/RecursiveNodes.gltf",
     {"reached twice; the node hierarchy must be a tree", "a node that is its own ancestor"}},
    {"SchemaFailures/sceneWrongType.gltf",
     {"\"BoxTextured0.bin\" does not exist", "its buffer file is not in the package"}},
    {"TestNoRootNode/NoScene.gltf",
     {"no triangles to draw in the default scene", "no meshes at all"}},
    {"TestNoRootNode/SceneWithoutNodes.gltf",
     {"no triangles to draw in the default scene", "a scene without nodes"}},
    {"draco/2CylinderEngine.gltf",
     {"requires the glTF extension KHR_draco_mesh_compression", "Draco-compressed geometry"}},
    {"wrongTypes/badArray.gltf",
     {"no triangles to draw in the default scene", "its mesh's primitives are not an array, so it has none"}},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf",
     {"no triangles to draw in the default scene; mesh 0: skipped its points (mode 0); only triangles are drawn",
      "only points: Luz draws triangles (SCENES.md)"}},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_01.gltf",
     {"no triangles to draw in the default scene; mesh 0: skipped its lines (mode 1); only triangles are drawn",
      "only lines: Luz draws triangles (SCENES.md)"}},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_02.gltf",
     {"no triangles to draw in the default scene; mesh 0: skipped its line loops (mode 2); only triangles are drawn",
      "only line loops: Luz draws triangles (SCENES.md)"}},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_03.gltf",
     {"no triangles to draw in the default scene; mesh 0: skipped its line strips (mode 3); only triangles are drawn",
      "only line strips: Luz draws triangles (SCENES.md)"}},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_07.gltf",
     {"no triangles to draw in the default scene; mesh 0: skipped its points (mode 0); only triangles are drawn",
      "only points: Luz draws triangles (SCENES.md)"}},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_08.gltf",
     {"no triangles to draw in the default scene; mesh 0: skipped its lines (mode 1); only triangles are drawn",
      "only lines: Luz draws triangles (SCENES.md)"}},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_09.gltf",
     {"no triangles to draw in the default scene; mesh 0: skipped its line loops (mode 2); only triangles are drawn",
      "only line loops: Luz draws triangles (SCENES.md)"}},
    {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_10.gltf",
     {"no triangles to draw in the default scene; mesh 0: skipped its line strips (mode 3); only triangles are drawn",
      "only line strips: Luz draws triangles (SCENES.md)"}},
};

std::vector<std::string> model_files() {
  std::vector<std::string> files;
  std::error_code ec;
  if (!fs::is_directory(kModels, ec)) return files;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kModels, ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb"))
      files.push_back(entry.path().lexically_relative(kModels).string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

// A sensible picture: every pixel finite and at least 1% of them lit (radiance above 1e-3 in
// some channel; the models fill a good part of the frame from the default framing camera).
// Radiosity shows diffuse light only: a scene whose every material has kd = 0 (all metal) is
// black there, by the model, and that is the sensible picture.
void expect_lit(const fs::path& exr, const std::string& what, bool expect_black = false) {
  const Image image = io::read_image(exr);
  size_t lit = 0;
  for (const Rgb& c : image.pixels) {
    ASSERT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b)) << what;
    if (std::max({c.r, c.g, c.b}) > 1e-3f) ++lit;
  }
  if (expect_black) {
    EXPECT_EQ(lit, 0u) << what << ": all metal, yet lit in a diffuse-only model";
    return;
  }
  EXPECT_GE(lit, image.pixels.size() / 100) << what << ": " << lit << " of " << image.pixels.size()
                                            << " pixels lit";
}

bool has_diffuse(const Scene& scene) {
  for (const Mesh& mesh : scene.meshes) {
    const Rgb& kd = scene.materials.at(size_t(mesh.material)).kd;
    if (std::max({kd.r, kd.g, kd.b}) > 0.0f) return true;
  }
  return false;
}

class SampleModel : public ::testing::TestWithParam<std::string> {};

TEST_P(SampleModel, RendersInEveryModelOrIsRefusedAsDocumented) {
  const fs::path file = kModels / GetParam();
  auto refused = kRefused.find(GetParam());
  if (refused != kRefused.end()) {
    try {
      io::load_gltf(file);
      ADD_FAILURE() << GetParam() << " loads, but is listed as refused: " << refused->second.reason;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(refused->second.message), std::string::npos)
          << e.what() << "\nexpected: " << refused->second.message;
    }
    return;
  }
  bool diffuse = false;
  try {
    diffuse = has_diffuse(io::load_gltf(file).scene);
  } catch (const Error& e) {
    FAIL() << "refused: " << e.what();
  }
  ScratchDir dir;
  for (const app::ModelEntry& entry : app::models()) {
    const std::string model = entry.name;
    app::RenderSettings settings;
    settings.scene = file.string();
    settings.model = model;
    settings.out = (dir / (model + ".exr")).string();
    settings.width = 40;
    settings.height = 30;
    settings.quiet = true;
    settings.radiosity.target_patches = 150;
    settings.radiosity.hemicube_res = 64;
    settings.radiosity.max_shots = 40;
    ASSERT_EQ(app::run_render(settings), 0) << GetParam() << " --model " << model;
    expect_lit(settings.out, GetParam() + " --model " + model, !diffuse && settings.model == "radiosity");
  }
}

INSTANTIATE_TEST_SUITE_P(AssimpTestModels, SampleModel, ::testing::ValuesIn(model_files()), test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(SampleModel);

TEST(SampleModels, PackageInstalled) {
  if (model_files().empty()) GTEST_SKIP() << kModels << " is absent (Debian package assimp-testmodels)";
  // Every refusal names a file that exists, so the list cannot silently go stale.
  for (const auto& [path, refusal] : kRefused) EXPECT_TRUE(fs::exists(kModels / path)) << path;
}

}  // namespace
}  // namespace luz::test
