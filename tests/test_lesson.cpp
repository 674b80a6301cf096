// Lessons: the shipped walk through the lecture, the commands a step becomes, and the
// FILE:LINE messages of a malformed lesson.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "app/classroom/lesson.h"
#include "app/common/options_tables.h"
#include "app/common/radiosity_drive.h"
#include "core/error.h"
#include "local/local_options.h"
#include "radiosity/radiosity_options.h"
#include "raytracing/whitted_options.h"
#include "support.h"

namespace luz {
namespace {

using app::Lesson;
using app::LessonPlayer;
using app::ScriptCommand;

std::filesystem::path shipped() { return std::filesystem::path(LUZ_LESSON_DIR) / "sintesis.json"; }

std::string line_of(const ScriptCommand& c) {
  std::string text = c.verb;
  for (const std::string& a : c.args) text += " " + a;
  return text;
}

bool has(const std::vector<ScriptCommand>& commands, const std::string& line) {
  for (const ScriptCommand& c : commands)
    if (line_of(c) == line) return true;
  return false;
}

std::vector<const app::LessonStep*> on_slide(const Lesson& lesson, int slide) {
  std::vector<const app::LessonStep*> out;
  for (const app::LessonStep& s : lesson.steps)
    if (s.slide == slide) out.push_back(&s);
  return out;
}

TEST(ShippedLesson, WalksTheSlidesTheClassroomNeeds) {
  const Lesson lesson = app::parse_lesson(shipped());
  std::set<int> slides;
  for (const app::LessonStep& s : lesson.steps) slides.insert(s.slide);
  // Lit vs unlit, the local terms, slide 19, the ray tree, Whitted's formula and algorithm, its
  // problems, radiosity's steps, the solvers, meshing, the hybrid and the conclusions.
  for (int slide : {2, 3, 4, 15, 16, 17, 18, 19, 24, 25, 26, 27, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44})
    EXPECT_TRUE(slides.count(slide)) << "slide " << slide;
  EXPECT_EQ(*slides.begin(), 2);
  EXPECT_EQ(*slides.rbegin(), 44);
  int previous = 0;
  for (const app::LessonStep& s : lesson.steps) {  // in the lecture's order
    EXPECT_GE(s.slide, previous) << "line " << s.line;
    previous = s.slide;
    EXPECT_NE(s.title.es, s.title.en) << "line " << s.line;  // really in two languages
    EXPECT_NE(s.text.es, s.text.en) << "line " << s.line;
  }
}

// Slides 16-18: each term alone; slide 4: the scene without its light.
TEST(ShippedLesson, ShowsEachLocalTermAlone) {
  const Lesson lesson = app::parse_lesson(shipped());
  const std::map<int, std::string> alone = {{16, "ambient"}, {17, "diffuse"}, {18, "specular"}};
  for (const auto& [slide, term] : alone) {
    const app::LessonStep& s = *on_slide(lesson, slide).at(0);
    for (const char* t : {"ambient", "diffuse", "specular"})
      EXPECT_TRUE(has(s.commands, std::string("set ") + t + (t == term ? " on" : " off"))) << slide << " " << t;
  }
  const app::LessonStep& unlit = *on_slide(lesson, 4).at(0);
  EXPECT_TRUE(has(unlit.commands, "set diffuse off"));
  EXPECT_TRUE(has(unlit.commands, "set specular off"));
}

TEST(ShippedLesson, ShowsEachEffectOfSlide19) {
  const Lesson lesson = app::parse_lesson(shipped());
  for (const char* effect : {"set fog linear", "set shadows on", "set transparency on", "set reflection-map on"}) {
    bool alone = false;  // some step of slide 19 shows this effect and no other
    for (const app::LessonStep* s : on_slide(lesson, 19)) {
      int on = has(s->commands, "set shadows on") + has(s->commands, "set transparency on") +
               has(s->commands, "set reflection-map on") + !has(s->commands, "set fog off");
      alone = alone || (has(s->commands, effect) && on == 1);
    }
    EXPECT_TRUE(alone) << effect;
  }
}

TEST(ShippedLesson, RunsTheActionsOfTheirSlides) {
  const Lesson lesson = app::parse_lesson(shipped());
  auto any = [&](int slide, auto predicate) {
    for (const app::LessonStep* s : on_slide(lesson, slide))
      for (const ScriptCommand& c : s->commands)
        if (predicate(c)) return true;
    return false;
  };
  auto verb = [](const char* v, const char* first = nullptr) {
    return [=](const ScriptCommand& c) { return c.verb == v && (!first || (!c.args.empty() && c.args[0] == first)); };
  };
  EXPECT_TRUE(any(24, verb("click-picture")));         // the ray tree of a pixel
  EXPECT_TRUE(any(24, verb("trace")));
  EXPECT_TRUE(any(27, verb("set", "brute-force")));
  EXPECT_TRUE(any(27, [](const ScriptCommand& c) { return line_of(c) == "set spp 16"; }));
  EXPECT_TRUE(any(27, [](const ScriptCommand& c) { return line_of(c) == "set adaptive on"; }));
  EXPECT_TRUE(any(29, [](const ScriptCommand& c) { return line_of(c) == "radiosity reset"; }));  // shot 0
  EXPECT_TRUE(any(31, verb("wait-shots")));            // the first shots
  EXPECT_TRUE(any(35, [](const ScriptCommand& c) { return line_of(c) == "radiosity heat-map on"; }));
  EXPECT_TRUE(any(36, [](const ScriptCommand& c) { return line_of(c) == "solvers open"; }));
  EXPECT_TRUE(any(37, [](const ScriptCommand& c) { return line_of(c) == "radiosity item-buffer on"; }));
  EXPECT_TRUE(any(39, [](const ScriptCommand& c) { return line_of(c) == "radiosity step 1"; }));
  EXPECT_TRUE(any(40, verb("radiosity", "patch-size")));
  EXPECT_TRUE(any(37, [](const ScriptCommand& c) { return line_of(c) == "radiosity form-factors hemicube"; }));
  EXPECT_TRUE(any(40, [](const ScriptCommand& c) { return line_of(c) == "radiosity meshing uniform"; }));
  EXPECT_TRUE(any(40, [](const ScriptCommand& c) { return line_of(c) == "radiosity meshing adaptive"; }));
  for (int slide : {41, 42, 43}) EXPECT_TRUE(any(slide, [](const ScriptCommand& c) { return line_of(c) == "model hybrid"; }));
  EXPECT_TRUE(any(44, [](const ScriptCommand& c) { return line_of(c) == "panes flat,gouraud,phong,whitted"; }));
  EXPECT_TRUE(any(44, [](const ScriptCommand& c) { return line_of(c) == "panes radiosity,hybrid"; }));
}

// What the player sends, walking forward, back and jumping, is today's script language (the
// viewer's own parser accepts it) but for `panes`, the verb side by side adds.
TEST(ShippedLesson, EveryCommandIsAScriptCommand) {
  LessonPlayer player(app::parse_lesson(shipped()));
  std::string script;
  auto add = [&](const std::vector<ScriptCommand>& commands) {
    for (const ScriptCommand& c : commands)
      if (c.verb != "panes") script += line_of(c) + "\n";
  };
  add(player.go_to(0));
  for (size_t i = 1; i < player.size(); ++i) add(player.next());
  for (size_t i = 1; i < player.size(); ++i) add(player.previous());
  for (size_t i = player.size(); i-- > 0;) add(player.go_to(i));
  EXPECT_NO_THROW(app::parse_script_text(script, "lesson-commands.txt"));
}

// A step that does not name a switch sets the options' own default (never a copy of it).
TEST(Lesson, UnnamedSwitchesGoBackToTheOptionsDefaults) {
  const Lesson lesson = app::parse_lesson_text(
      R"({"title": {"es": "t", "en": "t"}, "steps": [
           {"slide": 17, "title": {"es": "a", "en": "a"}, "text": {"es": "b", "en": "b"},
            "scene": ")" + (test::scene_dir() / "phong_spheres.gltf").string() + R"(", "model": "phong"}]})",
      "defaults.json");
  const LocalOptions local;
  const rt::WhittedOptions whitted;
  const RadiosityOptions radiosity;
  const auto& c = lesson.steps[0].commands;
  auto on = [](bool b) { return std::string(b ? "on" : "off"); };
  EXPECT_TRUE(has(c, "set ambient " + on(local.terms.ambient)));
  EXPECT_TRUE(has(c, "set blinn " + on(local.terms.blinn)));
  EXPECT_TRUE(has(c, "set shadows " + on(local.shadows.on)));
  EXPECT_TRUE(has(c, "set depth " + std::to_string(whitted.max_depth)));
  EXPECT_TRUE(has(c, "set spp " + std::to_string(whitted.spp)));
  EXPECT_TRUE(has(c, "set fresnel " + on(whitted.fresnel)));
  EXPECT_TRUE(has(c, "radiosity hemicube " + std::to_string(radiosity.hemicube_res)));
  EXPECT_TRUE(has(c, "radiosity outlines " + on(radiosity.outlines)));
  EXPECT_TRUE(has(c, "radiosity rotation " + on(radiosity.random_rotation)));
  EXPECT_TRUE(has(c, std::string("radiosity meshing ") + to_string(radiosity.meshing)));
  EXPECT_TRUE(has(c, std::string("radiosity form-factors ") + to_string(radiosity.form_factors)));
}

// The lesson's switch groups are the options tables' rows: every switch and choice of the local
// table (the terms, slide 19's effects), every flag of the Whitted tracer's and every switch and
// mesh setting of the `radiosity` verb is set to its default when a step does not name it, and
// taken by its name when it does.
TEST(Lesson, TheSwitchGroupsAreTheOptionsTablesRows) {
  const std::string head = R"({"title": {"es": "t", "en": "t"}, "steps": [
           {"slide": 17, "title": {"es": "a", "en": "a"}, "text": {"es": "b", "en": "b"},
            "scene": ")" + (test::scene_dir() / "whitted.gltf").string() + R"(", "model": "whitted")";
  const Lesson defaults = app::parse_lesson_text(head + "}]}", "defaults.json");
  const auto& c = defaults.steps[0].commands;
  int rows = 0;
  for (const app::OptionRow& row : app::local_table().rows)
    if (row.kind == app::OptionKind::on_off || row.kind == app::OptionKind::choice) {
      EXPECT_TRUE(has(c, std::string("set ") + row.name + " " + app::default_text(app::local_table(), row))) << row.name;
      ++rows;
    }
  for (const app::OptionRow& row : app::whitted_table().rows)
    if (row.flag) {
      EXPECT_TRUE(has(c, std::string("set ") + row.name + " " + app::default_text(app::whitted_table(), row))) << row.name;
      ++rows;
    }
  EXPECT_EQ(rows, 18);  // 10 local switches and choices, 8 of the tracer's flags
  // Radiosity's: the `radiosity` verb's switches and mesh settings.
  const RadiosityOptions options;
  const app::RadiosityDrive drive;
  for (const app::RadiositySwitch& sw : app::radiosity_switches()) {
    const bool on = sw.drive ? drive.*sw.drive : options.*sw.option;
    EXPECT_TRUE(has(c, std::string("radiosity ") + sw.name + (on ? " on" : " off"))) << sw.name;
  }
  for (const char* name : app::radiosity_mesh_settings())
    EXPECT_TRUE(has(c, std::string("radiosity ") + name + " " +
                           app::default_text(app::radiosity_table(), *app::find_row(app::radiosity_table(), name))))
        << name;
  EXPECT_EQ(app::radiosity_switches().size() + app::radiosity_mesh_settings().size(), 11u);  // 3 + 4 switches, 4 settings
  const Lesson named = app::parse_lesson_text(head + R"(, "whitted": {"renderer": "recursive"}, "effects": {"fog": "linear"},
                                                  "radiosity": {"shooter": false, "hemicube": 128}}]})",
                                              "given.json");
  const auto& given = named.steps[0].commands;
  EXPECT_TRUE(has(given, "set renderer recursive"));
  EXPECT_TRUE(has(given, "set fog linear"));
  EXPECT_TRUE(has(given, "radiosity shooter off"));
  EXPECT_TRUE(has(given, "radiosity hemicube 128"));
}

// A scene is loaded and a mesh rebuilt only when the step needs another one; panes end when a
// step shows one picture again.
TEST(LessonPlayer, RebuildsOnlyWhatChanges) {
  const std::string spheres = (test::scene_dir() / "phong_spheres.gltf").string();
  const std::string box = (test::scene_dir() / "cornell_box.gltf").string();
  const std::string t = R"("title": {"es": "t", "en": "t"}, "text": {"es": "x", "en": "x"})";
  LessonPlayer player(app::parse_lesson_text(
      R"({"title": {"es": "t", "en": "t"}, "steps": [
        {"slide": 2, )" + t + R"(, "scene": ")" + spheres + R"(", "model": "phong"},
        {"slide": 3, )" + t + R"(, "terms": {"ambient": false}},
        {"slide": 4, )" + t + R"(, "scene": ")" + box + R"(", "model": "radiosity", "radiosity": {"patch-size": 0.2}},
        {"slide": 5, )" + t + R"(, "radiosity": {"patch-size": 0.2}, "panes": ["radiosity", "phong"]},
        {"slide": 6, )" + t + R"(}]})",
      "moves.json"));
  auto count = [](const std::vector<ScriptCommand>& c, const std::string& verb, const std::string& first = "") {
    return std::count_if(c.begin(), c.end(), [&](const ScriptCommand& x) {
      return x.verb == verb && (first.empty() || x.args[0] == first);
    });
  };
  auto first = player.go_to(0);
  EXPECT_TRUE(has(first, "load " + spheres));
  EXPECT_EQ(count(first, "radiosity", "patch-size"), 0);  // the viewer starts on the defaults
  EXPECT_EQ(count(first, "panes"), 0);
  auto second = player.next();
  EXPECT_EQ(count(second, "load"), 0);
  EXPECT_TRUE(has(second, "set ambient off"));
  EXPECT_TRUE(has(second, "model phong"));  // carried over
  auto third = player.next();
  EXPECT_TRUE(has(third, "load " + box));
  EXPECT_TRUE(has(third, "radiosity patch-size 0.2"));
  EXPECT_TRUE(has(third, "set ambient on"));  // back to the default
  auto fourth = player.next();
  EXPECT_EQ(count(fourth, "radiosity", "patch-size"), 0);
  EXPECT_TRUE(has(fourth, "panes radiosity,phong"));
  auto fifth = player.next();
  EXPECT_TRUE(has(fifth, "panes radiosity"));  // one picture again
  EXPECT_TRUE(has(fifth, "radiosity patch-size 0"));
  // The end: stays; no load, mesh (patch size, hemicube, meshing, form factors) or panes.
  EXPECT_EQ(player.next().size(), player.step().commands.size() - 6);
  auto back = player.go_to(0);
  EXPECT_TRUE(has(back, "load " + spheres));
}

TEST(LessonPlayer, VerbsMoveSwitchLanguageAndDump) {
  LessonPlayer player(app::parse_lesson(shipped()));
  player.go_to(0);
  EXPECT_EQ(app::lesson_verb_problem({1, "lesson", {"next"}}), "");
  EXPECT_NE(app::lesson_verb_problem({1, "lesson", {"goto", "0"}}), "");
  EXPECT_NE(app::lesson_verb_problem({1, "lesson", {"forward"}}), "");
  EXPECT_EQ(app::lesson_verb_problem({1, "lang", {"es"}}), "");
  EXPECT_NE(app::lesson_verb_problem({1, "lang", {"de"}}), "");
  EXPECT_NE(app::lesson_verb_problem({1, "dump-lesson", {"x.txt"}}), "");
  EXPECT_FALSE(app::lesson_verb_problem({1, "model", {"phong"}}).has_value());

  const test::ScratchDir dir;
  std::vector<ScriptCommand> to_run;
  std::string error;
  ASSERT_TRUE(player.run({1, "lesson", {"goto", "5"}}, to_run, error)) << error;
  EXPECT_FALSE(to_run.empty());
  ASSERT_TRUE(player.run({2, "lang", {"es"}}, to_run, error));
  ASSERT_TRUE(player.run({3, "dump-lesson", {(dir / "es.json").string()}}, to_run, error)) << error;
  ASSERT_TRUE(player.run({4, "lang", {"en"}}, to_run, error));
  ASSERT_TRUE(player.run({5, "lesson", {"prev"}}, to_run, error));
  ASSERT_TRUE(player.run({6, "lesson", {"next"}}, to_run, error));
  ASSERT_TRUE(player.run({7, "dump-lesson", {(dir / "en.json").string()}}, to_run, error)) << error;
  EXPECT_FALSE(player.run({8, "lesson", {"goto", "999"}}, to_run, error));
  EXPECT_NE(error.find("1 .. " + std::to_string(player.size())), std::string::npos) << error;

  const nlohmann::json es = nlohmann::json::parse(std::ifstream(dir / "es.json"));
  const nlohmann::json en = nlohmann::json::parse(std::ifstream(dir / "en.json"));
  const app::LessonStep& fifth = player.lesson().steps[4];
  EXPECT_EQ(es["step"], 5);
  EXPECT_EQ(es["slide"], fifth.slide);
  EXPECT_EQ(es["title"], fifth.title.es);
  EXPECT_EQ(es["text"], fifth.text.es);
  EXPECT_EQ(es["language"], "es");
  EXPECT_EQ(es["model"], fifth.model);
  EXPECT_EQ(en["step"], 5);
  EXPECT_EQ(en["title"], fifth.title.en);
  EXPECT_EQ(en["language"], "en");
}

// Each malformed lesson names the line of what is wrong.
TEST(Lesson, MalformedFilesNameTheLine) {
  const std::string scene = (test::scene_dir() / "phong_spheres.gltf").string();
  const std::string head = "{\n\"title\": {\"es\": \"t\", \"en\": \"t\"},\n\"steps\": [\n{\n";  // the step opens on line 4
  const std::string text = "\"title\": {\"es\": \"a\", \"en\": \"a\"}, \"text\": {\"es\": \"b\", \"en\": \"b\"},\n";
  const std::string where = "\"scene\": \"" + scene + "\", \"model\": \"phong\",\n";
  struct Case {
    std::string json;
    int line;
    std::string message;
  };
  const Case cases[] = {
      {"{\n\"title\": {\"es\": \"t\", \"en\": \"t\"},\n\"steps\": [\n{ \"slide\": 3,, }\n]}", 4, "not JSON"},
      {head + text + where + "\"slide\": 3,\n\"colour\": 1\n}]}", 8, "unknown key \"colour\""},
      {head + "\"title\": {\"es\": \"a\"}, \"text\": {\"es\": \"b\", \"en\": \"b\"},\n" + where + "\"slide\": 3\n}]}", 5,
       "the \"en\" text is missing"},
      {head + text + "\"scene\": \"" + scene + "\",\n\"model\": \"gooraud\",\n\"slide\": 3\n}]}", 7, "model must be one of"},
      {head + text + where + "\"slide\": 3,\n\"radiosity\": {\n\"hemicube\": 2048\n}\n}]}", 9, "hemicube must be a whole number in 64 .. 1024"},
      {head + text + where + "\"slide\": 3,\n\"whitted\": {\"spp\": 5}\n}]}", 8, "spp must be a square"},
      {head + text + where + "\"slide\": 3,\n\"radiosity\": {\n\"meshing\": \"fine\"\n}\n}]}", 9,
       "radiosity: meshing must be one of uniform, adaptive"},
      {head + text + where + "\"slide\": 45\n}]}", 7, "slide must be a whole number in 1 .. 44"},
      {head + text + "\"model\": \"phong\", \"slide\": 3\n}]}", 4, "the first step must name a \"scene\""},
      {head + text + where + "\"slide\": 3,\n\"actions\": [\"trace\"]\n}]}", 8, "action \"trace\" needs the model whitted or hybrid"},
      {head + text + "\"scene\": \"missing.gltf\", \"model\": \"phong\",\n\"slide\": 3\n}]}", 6, "does not exist"},
      {head + text + where + "\"slide\": 3,\n\"terms\": {\"ambient\": \"no\"}\n}]}", 8, "terms: ambient must be true or false"},
  };
  for (const Case& c : cases) {
    try {
      app::parse_lesson_text(c.json, "bad.json");
      ADD_FAILURE() << "accepted:\n" << c.json;
    } catch (const Error& error) {
      EXPECT_EQ(error.kind, ErrorKind::usage);
      const std::string expected = "bad.json:" + std::to_string(c.line) + ": ";
      EXPECT_EQ(std::string(error.what()).rfind(expected, 0), 0u) << error.what() << "\nexpected " << expected;
      EXPECT_NE(std::string(error.what()).find(c.message), std::string::npos) << error.what();
    }
  }
}

TEST(LessonCommand, AMalformedLessonIsAUsageErrorBeforeAnyWindow) {
  const test::ScratchDir dir;
  std::ofstream(dir / "bad.json") << "{\n\"title\": {\"es\": \"t\", \"en\": \"t\"},\n\"steps\": 3\n}\n";
  const test::CommandResult result = test::run_luz({"--lesson", (dir / "bad.json").string()}, {.cwd = {}, .no_display = true});
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("bad.json:3: the lesson needs \"steps\""), std::string::npos) << result.output;
  // The shipped lesson is fine: only the missing display stops it.
  const test::CommandResult good = test::run_luz({"--lesson"}, {.cwd = {}, .no_display = true});
  EXPECT_EQ(good.exit_code, 1) << good.output;
  EXPECT_NE(good.output.find("no display"), std::string::npos) << good.output;
}

}  // namespace
}  // namespace luz
