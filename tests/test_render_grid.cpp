// `luz render --model A,B[,C,D] --size WxH`: a sheet of W x H, each pane the picture
// `luz render --model A` makes at the pane's size (a column's and a row's share), but for its
// label, and the label has ink.
#include <gtest/gtest.h>

#include "app/common/i18n.h"
#include "app/cli/render_grid.h"
#include "io/image_io.h"
#include "support.h"

namespace luz {
namespace {

constexpr int kW = 160, kH = 120;

std::string scene() { return (test::scene_dir() / "phong_spheres.gltf").string(); }

Image render(const test::ScratchDir& dir, const std::string& model, const std::string& name,
             const std::vector<std::string>& extra = {}, int width = kW, int height = kH) {
  std::vector<std::string> args = {"render", scene(), "--model", model, "--size", std::to_string(width) + "x" + std::to_string(height),
                                   "--out", (dir / name).string(), "-q"};
  args.insert(args.end(), extra.begin(), extra.end());
  const test::CommandResult result = test::run_luz(args);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  return io::read_image(dir / name);
}

// Pixels inside the label's box that came out near white (the label's ink).
int ink(const Image& sheet, int left, int top, const app::LabelBox& box) {
  int n = 0;
  for (int y = box.y; y < box.y + box.height; ++y)
    for (int x = box.x; x < box.x + box.width; ++x) n += sheet.at(left + x, top + y).g > 0.6f;
  return n;
}

void expect_panes(const std::vector<std::string>& models, const std::string& lang) {
  SCOPED_TRACE(lang);
  const test::ScratchDir dir;
  std::string list;
  for (const std::string& m : models) list += (list.empty() ? "" : ",") + m;
  const app::GridLayout layout = app::grid_layout(models.size());
  const Image sheet = render(dir, list, "grid.png", {"--lang", lang}, layout.columns * kW, layout.rows * kH);
  ASSERT_EQ(sheet.width, layout.columns * kW);
  ASSERT_EQ(sheet.height, layout.rows * kH);
  const app::LabelFont font;
  i18n::set_language(*i18n::parse_language(lang));
  for (size_t i = 0; i < models.size(); ++i) {
    SCOPED_TRACE(models[i]);
    const Image single = render(dir, models[i], models[i] + ".png");
    const int left = int(i) % layout.columns * kW, top = int(i) / layout.columns * kH;
    const app::LabelBox box = app::label_box(font, app::model_label(models[i]), kH);
    ASSERT_GT(box.width, 0);
    ASSERT_LT(box.width, kW);
    int different = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        if (!box.contains(x, y)) different += sheet.at(left + x, top + y) != single.at(x, y);
    EXPECT_EQ(different, 0);
    EXPECT_GT(ink(sheet, left, top, box), 10);
  }
  i18n::set_language(i18n::Language::en);
}

TEST(RenderGrid, FourPanesAreTheFourPicturesLabelled) {
  expect_panes({"flat", "gouraud", "phong", "whitted"}, "en");
}

TEST(RenderGrid, TwoPanesSideBySideLabelledInSpanish) {
  expect_panes({"phong", "flat"}, "es");
  i18n::set_language(i18n::Language::es);
  EXPECT_EQ(app::model_label("flat"), "plano");
  i18n::set_language(i18n::Language::en);
}

TEST(RenderGrid, UsageErrors) {
  const test::ScratchDir dir;
  const std::string out = (dir / "grid.png").string();
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const Case cases[] = {
      {{"--model", "flat,gouraud,phong"}, "2 or 4 models, not 3"},
      {{"--model", "flat,goraud"}, "unknown model \"goraud\""},
      {{"--model", "flat,phong", "--depth", "2"}, "--depth: only when a pane is whitted, hybrid or path"},
      {{"--model", "flat,whitted", "--ray-tree", "3,3"}, "--ray-tree: only with a single"},
      {{"--model", "whitted,radiosity", "--shadows"}, "--shadows: only when a pane is flat, gouraud or phong"},
      {{"--model", "flat,whitted", "--spp", "5"}, "--spp 5: expected a square"},
      {{"--model", "flat,whitted", "--seed", "3"}, "--seed: only when a pane is path"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"render", scene(), "--out", out, "--lang", "en"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const test::CommandResult result = test::run_luz(args);
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find(c.message), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

}  // namespace
}  // namespace luz
