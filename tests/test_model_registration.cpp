// A model added from outside the catalogue (toy_model/, registered as docs/adding-a-model.md
// says) is a model like the shipped ones: `luz render` takes its flags within its rows' ranges and
// refuses them with another model, the script's `set` and dump-state reach its options, the panel
// finds its ranges through the registry and a lesson's step sets it by its table's key. And every
// row of every table is checked once: the flag, `set` and a lesson accept and refuse the same
// values.
#include <algorithm>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "app/classroom/lesson.h"
#include "app/cli/render_command.h"
#include "app/cli/render_flags.h"
#include "app/common/model_registry.h"
#include "app/viewer/viewer_settings.h"
#include "core/error.h"
#include "support.h"
#include "toy_model/toy_model.h"

namespace luz::app {
namespace {

using test::ToyOptions;
using test::toy_table;

const std::string box = (test::scene_dir() / "cornell_box.gltf").string();

// `luz render` parsed as main parses it: the settings its flags leave, or the flag's refusal.
struct Parsed {
  RenderSettings settings;
  std::string error;  // empty: parsed
};

Parsed parse_render(std::vector<std::string> flags) {
  Parsed parsed;
  CLI::App render;
  const RenderFlags declared = add_render_flags(render, parsed.settings);
  flags.insert(flags.begin(), {box, "--out", "x.png"});
  std::reverse(flags.begin(), flags.end());  // CLI11 takes the arguments last first
  try {
    render.parse(flags);
    note_given_flags(declared, parsed.settings);
  } catch (const CLI::ParseError& e) {
    parsed.error = e.what();
  }
  return parsed;
}

Lesson lesson_with(const std::string& step_json) {
  const std::string text = R"({"title": {"es": "t", "en": "t"}, "steps": [{"slide": 3, "title": {"es": "t", "en": "t"},
    "text": {"es": "t", "en": "t"}, "scene": ")" + box + R"(", "model": "toy", )" + step_json + "}]}";
  return parse_lesson_text(text, "toy.json");
}

TEST(ModelRegistration, TheToyModelIsInTheRegistry) {
  const ModelEntry* toy = find_model("toy");
  ASSERT_NE(toy, nullptr);
  EXPECT_EQ(model_on_key(8), toy);
  EXPECT_EQ(std::string(models().back().name), "toy");  // after the catalogue's
  EXPECT_NE(find_model("phong"), nullptr);
}

TEST(ModelRegistration, ItsFlagsReachItsRender) {
  const Parsed parsed = parse_render({"--model", "toy", "--toy-bounces", "5", "--toy-gain", "2", "--toy-glow"});
  ASSERT_EQ(parsed.error, "");
  const ToyOptions& o = parsed.settings.model_options.get<ToyOptions>(toy_table());
  EXPECT_EQ(o.bounces, 5);
  EXPECT_EQ(o.gain, 2.0f);
  EXPECT_TRUE(o.glow);
  const Rendered picture = find_model("toy")->render(Scene{}, Camera{}, 4, 3, parsed.settings);
  EXPECT_EQ(picture.image.at(2, 1).r, 10.0f);  // bounces x gain
}

TEST(ModelRegistration, ItsFlagsAreCheckedByItsRows) {
  EXPECT_NE(parse_render({"--model", "toy", "--toy-bounces", "9"}).error.find("a whole number in 1 .. 8"),
            std::string::npos);
  EXPECT_NE(parse_render({"--model", "toy", "--toy-gain", "nan"}).error, "");
  EXPECT_EQ(parse_render({"--model", "toy", "--toy-bounces", "8"}).error, "");
  // Its flag group is its own: with another model, a usage error that names it.
  test::ScratchDir dir;
  RenderSettings settings = parse_render({"--model", "phong", "--toy-bounces", "4"}).settings;
  settings.out = (dir / "x.png").string();
  testing::internal::CaptureStderr();
  EXPECT_EQ(run_render(settings), 2);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("--toy-bounces: only with --model toy"), std::string::npos);
}

TEST(ModelRegistration, ItsHelpQuotesItsRows) {
  CLI::App render;
  RenderSettings settings;
  add_render_flags(render, settings);
  const std::string help = render.help();
  EXPECT_NE(help.find("--toy-bounces"), std::string::npos);
  EXPECT_NE(help.find("toy: how many times (a whole number in 1 .. 8; default 3)"), std::string::npos) << help;
}

TEST(ModelRegistration, SetAndDumpStateReachItsOptions) {
  ViewerState state;
  std::string error;
  EXPECT_EQ(check_setting("bounces", "6"), "");
  EXPECT_NE(check_setting("bounces", "0"), "");
  ASSERT_TRUE(apply_setting(state, "bounces", "6", error)) << error;
  ASSERT_TRUE(apply_setting(state, "toy.gain", "1.5", error)) << error;
  EXPECT_EQ(state.model_options.get<ToyOptions>(toy_table()).bounces, 6);
  EXPECT_EQ(state.model_options.get<ToyOptions>(toy_table()).gain, 1.5f);
  const nlohmann::json dump = settings_json(state);
  EXPECT_EQ(dump["toy"]["bounces"], 6);
  EXPECT_EQ(dump["toy"]["glow"], false);
  EXPECT_FALSE(apply_setting(state, "bounces", "12", error));
  EXPECT_EQ(error, "`set bounces` takes a whole number in 1 .. 8");
}

// A file row (the path tracer's --error-out) is a flag of `luz render` with its help; the viewer
// writes no file, so `set`, dump-state and the lessons leave it out, each saying so.
TEST(ModelRegistration, AFileRowIsAFlagOfTheCommandLineOnly) {
  const Parsed parsed = parse_render({"--model", "toy", "--toy-log", "run.txt"});
  ASSERT_EQ(parsed.error, "");
  EXPECT_EQ(parsed.settings.model_options.get<ToyOptions>(toy_table()).log, "run.txt");
  EXPECT_NE(parse_render({"--model", "toy", "--toy-log"}).error, "");  // a file name is needed
  CLI::App render;
  RenderSettings settings;
  add_render_flags(render, settings);
  EXPECT_NE(render.help().find("--toy-log FILE"), std::string::npos) << render.help();
  EXPECT_NE(render.help().find("toy: write a log to this file"), std::string::npos);
  ViewerState state;
  std::string error;
  EXPECT_FALSE(apply_setting(state, "toy.log", "run.txt", error));
  EXPECT_EQ(error, "\"toy.log\" is a file `luz render --toy-log` writes; the viewer writes none");
  EXPECT_FALSE(settings_json(state)["toy"].contains("log"));
  EXPECT_THROW(lesson_with(R"("toy": {"log": "run.txt"})"), Error);
  // The path tracer's --error-out is such a row of its table.
  const std::optional<FoundOption> error_out = find_option("path.error-out");
  ASSERT_TRUE(error_out);
  EXPECT_EQ(error_out->row->kind, OptionKind::file);
  EXPECT_EQ(std::string(error_out->row->flag), "--error-out");
}

TEST(ModelRegistration, ThePanelFindsItsRangesInTheRegistry) {
  const std::optional<FoundOption> bounces = find_option("bounces");
  ASSERT_TRUE(bounces);
  EXPECT_EQ(bounces->table, &toy_table());
  const SliderRange range = slider_range(*bounces->row);
  EXPECT_EQ(range.low, 1.0f);
  EXPECT_EQ(range.high, 8.0f);
}

TEST(ModelRegistration, ALessonSetsItByItsTablesKey) {
  const Lesson lesson = lesson_with(R"("toy": {"bounces": 7, "glow": true})");
  ViewerState state;
  int sets = 0;
  for (const ScriptCommand& c : lesson.steps[0].commands)
    if (c.verb == "set" && c.args[0].starts_with("toy.")) {
      std::string error;
      ASSERT_TRUE(apply_setting(state, c.args[0], c.args[1], error)) << error;
      ++sets;
    }
  EXPECT_EQ(sets, 2);
  EXPECT_EQ(state.model_options.get<ToyOptions>(toy_table()).bounces, 7);
  EXPECT_TRUE(state.model_options.get<ToyOptions>(toy_table()).glow);
  try {
    lesson_with(R"("toy": {"bounces": 9})");
    ADD_FAILURE() << "bounces 9 was taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("toy: bounces must be a whole number in 1 .. 8"), std::string::npos) << e.what();
  }
}

// The one check: for every row with a flag, of every model's tables, the values just inside and
// just outside its range are taken or refused alike by the flag and by `set TABLE.NAME`.
TEST(ModelRegistration, EveryRowIsCheckedOnceForFlagAndSet) {
  for (const OptionTable* table : option_tables())
    for (const OptionRow& row : table->rows) {
      if (row.kind != OptionKind::integer && row.kind != OptionKind::real) continue;
      const std::string name = std::string(table->name) + "." + row.name;
      std::vector<double> values = {row.low, row.low - 1.0};
      if (row.high != kUnbounded) values.insert(values.end(), {row.high, row.high + 1.0});
      for (double v : values) {
        const std::string text = row.kind == OptionKind::integer ? std::to_string((long long)(v)) : fmt::format("{}", v);
        const bool taken = check_setting(name, text).empty();
        EXPECT_EQ(taken, parse_value(row, text).has_value()) << name << " " << text;
        if (!row.flag || row.rule) continue;  // a rule (a square) may be the render's to check
        const ModelEntry* owner = nullptr;
        for (const ModelEntry& m : models())
          for (const char* g : m.flag_groups)
            if (!owner && std::string_view(g) == row.group) owner = &m;
        ASSERT_NE(owner, nullptr) << row.flag;
        EXPECT_EQ(parse_render({"--model", owner->name, row.flag, text}).error.empty(), taken) << row.flag << " " << text;
      }
    }
}

}  // namespace
}  // namespace luz::app
