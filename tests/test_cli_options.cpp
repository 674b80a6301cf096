// `luz render`'s flags come from the options tables (src/app/common/option_row.h): every float flag
// refuses nan and inf as a usage error naming the flag; the help quotes each option's default
// as its struct has it; a range without an upper end is said in words.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/common/options_tables.h"
#include "support.h"

namespace luz::app {
namespace {

using test::run_luz;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The model whose flag group takes a row's flag.
const char* model_for(const char* group) {
  const std::string g = group;
  if (g == "whitted") return "whitted";
  if (g == "radiosity" || g == "radiosity-display") return "radiosity";
  return "phong";
}

std::vector<std::pair<std::string, std::string>> real_flags(const OptionTable& table) {
  std::vector<std::pair<std::string, std::string>> flags;
  for (const OptionRow& row : table.rows)
    if (row.flag && row.kind == OptionKind::real) flags.emplace_back(row.flag, model_for(row.group));
  return flags;
}

TEST(CliOptions, EveryFloatFlagRefusesNanAndInfinity) {
  test::ScratchDir dir;
  const std::string scene = (test::scene_dir() / "cornell_box.gltf").string(), out = (dir / "a.png").string();
  std::vector<std::pair<std::string, std::string>> flags = {{"--exposure", "phong"}};
  for (const OptionTable* table : {&local_table(), &whitted_table(), &radiosity_table()})
    for (const auto& f : real_flags(*table)) flags.push_back(f);
  EXPECT_GE(flags.size(), 9u);  // exposure, fog x3, shadow biases x3, converge, patch size, ...
  for (const auto& [flag, model] : flags)
    for (const char* value : {"nan", "inf", "-inf", "NaN"}) {
      const auto result = run_luz({"render", scene, "--model", model, "--out", out, flag, value});
      EXPECT_EQ(result.exit_code, 2) << flag << " " << value << ": " << result.output;
      EXPECT_TRUE(contains(result.output, flag)) << result.output;
      EXPECT_TRUE(contains(result.output, "finite")) << result.output;
    }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path));
}

TEST(CliOptions, TheHelpQuotesTheStructsDefaults) {
  const auto help = run_luz({"render", "--help"});
  ASSERT_EQ(help.exit_code, 0);
  for (const OptionTable* table : {&local_table(), &whitted_table(), &radiosity_table()})
    for (const OptionRow& row : table->rows)
      if (row.flag && row.kind != OptionKind::on_off) {
        EXPECT_TRUE(contains(help.output, "default " + default_text(*table, row))) << row.flag;
      }
  EXPECT_TRUE(contains(help.output, "default " + std::to_string(RadiosityOptions{}.hemicube_res)));
  EXPECT_TRUE(contains(help.output, "default " + std::to_string(rt::WhittedOptions{}.max_depth)));
}

TEST(CliOptions, AShotsRangeWithoutAnEndIsSaidInWords) {
  const auto result = run_luz({"render", (test::scene_dir() / "cornell_box.gltf").string(), "--model", "radiosity",
                               "--out", "x.png", "--shots", "0"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(contains(result.output, "--shots: 0: expected a whole number >= 1")) << result.output;
  EXPECT_LT(result.output.size(), 200u) << result.output;  // no 309-digit upper end
}

}  // namespace
}  // namespace luz::app
