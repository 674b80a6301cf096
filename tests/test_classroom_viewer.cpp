// The classroom in a real window (Xvfb): tests/lesson/walk.txt plays tests/lesson/walk.json,
// switches the language live, walks the lesson by the verbs and by F8 / F7, and dumps what the
// window shows. The expectations come from elsewhere than the viewer: the catalogues for the
// words, the lesson file and the options structs' defaults for each step's state.
#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "app/common/i18n.h"
#include "app/classroom/lesson.h"
#include "app/viewer/viewer_settings.h"
#include "io/default_lights.h"
#include "viewer_support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::json_of;

const fs::path run_dir = LUZ_VIEWER_RUN_DIR;
const fs::path lesson_file = fs::path(LUZ_TEST_LESSON_DIR) / "walk.json";

class ClassroomViewer : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
};

bool has_window(const json& dump, const std::string& name) {
  for (const json& w : dump["windows"])
    if (w["name"] == name) return true;
  return false;
}

// The translation the catalogue holds, read from the .mo the build compiled.
std::string spanish(const char* id) {
  const std::string* found = i18n::catalogue(i18n::Language::es).find(id);
  return found ? *found : std::string();
}

// What a step must leave in the viewer: every row at its options struct's default, but for the
// ones the step names in its "terms", "effects", "whitted" and "radiosity", which take the file's
// values.
json expected_settings(size_t step) {
  std::ifstream in(lesson_file);
  const json lesson = json::parse(in);
  const json& s = lesson["steps"][step];
  json expected = app::settings_json(app::ViewerState{});
  for (const char* group : {"terms", "effects"})
    if (s.contains(group))
      for (const auto& [name, value] : s[group].items()) expected["local"][name] = value;
  for (const char* group : {"whitted", "radiosity"})
    if (s.contains(group))
      for (const auto& [name, value] : s[group].items())
        if (expected[group].contains(name)) expected[group][name] = value;
  return expected;
}

void expect_step(const json& state, size_t step) {
  std::ifstream in(lesson_file);
  const json lesson = json::parse(in);
  std::string model;
  for (size_t i = 0; i <= step; ++i)
    if (lesson["steps"][i].contains("model")) model = lesson["steps"][i]["model"];
  EXPECT_EQ(state["model"], model) << "step " << step + 1;
  const json expected = expected_settings(step);
  for (const char* group : {"local", "whitted", "radiosity"})
    for (const auto& [name, value] : expected[group].items())
      EXPECT_EQ(state["settings"][group][name], value) << "step " << step + 1 << ": " << group << " " << name;
}

TEST_F(ClassroomViewer, TheLanguageSwitchesLive) {
  ASSERT_FALSE(spanish("Keys (F1)").empty());
  EXPECT_TRUE(has_window(json_of(run_dir / "en_windows.json"), "Keys (F1)"));
  EXPECT_TRUE(has_window(json_of(run_dir / "es_windows.json"), spanish("Keys (F1)")));
  EXPECT_FALSE(has_window(json_of(run_dir / "es_windows.json"), "Keys (F1)"));
  EXPECT_TRUE(has_window(json_of(run_dir / "en_again_windows.json"), "Keys (F1)"));
  // The status line's message after A, in Spanish.
  const json note = json_of(run_dir / "es_note.json");
  EXPECT_EQ(note["language"], "es");
  EXPECT_EQ(note["note"], spanish("ambient I_A") + " " + spanish("off"));
  EXPECT_NE(spanish("ambient I_A"), "ambient I_A");
}

// ImGui's own measure of the panel: the widest item, label included, against the room inside
// the panel. Wrapped text never widens it; a label longer than its share of the width does.
TEST_F(ClassroomViewer, ThePanelFitsItsWidthInBothLanguages) {
  for (const char* dump : {"es_panel_phong.json", "es_panel_whitted.json", "es_panel_radiosity.json",
                           "es_panel_hybrid.json", "en_panel_phong.json", "en_panel_whitted.json",
                           "en_panel_radiosity.json", "en_panel_hybrid.json"}) {
    bool found = false;
    const json windows = json_of(run_dir / dump)["windows"];
    for (const json& w : windows) {
      if (w["name"] != "Luz") continue;
      found = true;
      EXPECT_LE(w["content_width"].get<double>(), w["visible_width"].get<double>()) << dump;
      EXPECT_FALSE(w["scrolls_sideways"].get<bool>()) << dump;
    }
    EXPECT_TRUE(found) << dump;
  }
  // The lights' tree nodes were open in both languages: their widgets were drawn, and measured.
  for (const char* dump : {"es_widgets_hybrid.json", "en_widgets_phong.json"}) {
    const json widgets = json_of(run_dir / dump)["widgets"];  // a copy: the parsed file is a temporary
    std::set<std::string> labels;
    for (const json& w : widgets) labels.insert(w["label"].get<std::string>());
    for (const char* label : {"key_light/colour", "key_light/position", "key_light/f_att", "fill_light/c0 c1 c2"})
      EXPECT_TRUE(labels.count(label)) << dump << ": " << label;
  }
}

// A warning of the loader reaches the window in the language chosen: listed in the state and in
// the warnings window, whose title is Spanish too.
TEST_F(ClassroomViewer, TheLoadersWarningReachesTheWindowInSpanish) {
  const json state = json_of(run_dir / "es_warning.json");
  EXPECT_EQ(state["language"], "es");
  const std::string notice = spanish(io::kDefaultLightsNotice);
  ASSERT_FALSE(notice.empty());
  ASSERT_NE(notice, io::kDefaultLightsNotice);
  bool listed = false;
  for (const json& w : state["warnings"]) listed |= w.get<std::string>() == "unlit.gltf: " + notice;
  EXPECT_TRUE(listed) << state["warnings"].dump();
  bool window = false;
  const json windows = json_of(run_dir / "es_warning_windows.json")["windows"];
  for (const json& w : windows)
    window |= w["name"].get<std::string>().rfind(spanish("1 warning"), 0) == 0;
  EXPECT_TRUE(window);
}

TEST_F(ClassroomViewer, EachStepSetsItsModelAndSettings) {
  expect_step(json_of(run_dir / "step1_state.json"), 0);
  expect_step(json_of(run_dir / "step2.json"), 1);
  expect_step(json_of(run_dir / "step4.json"), 3);
  expect_step(json_of(run_dir / "step3.json"), 2);
  expect_step(json_of(run_dir / "back1.json"), 0);  // goto 1 after step 3: what step 1 set, only that
}

TEST_F(ClassroomViewer, F8AndF7WalkTheLesson) {
  expect_step(json_of(run_dir / "key_next.json"), 1);
  expect_step(json_of(run_dir / "key_prev.json"), 0);
}

TEST_F(ClassroomViewer, DumpLessonSpeaksTheCurrentLanguage) {
  const app::Lesson lesson = app::parse_lesson(lesson_file);
  const json en = json_of(run_dir / "step1_en.json"), es = json_of(run_dir / "step1_es.json");
  EXPECT_EQ(en["language"], "en");
  EXPECT_EQ(en["title"], lesson.steps[0].title.en);
  EXPECT_EQ(en["text"], lesson.steps[0].text.en);
  EXPECT_EQ(es["language"], "es");
  EXPECT_EQ(es["title"], lesson.steps[0].title.es);
  EXPECT_EQ(es["text"], lesson.steps[0].text.es);
  EXPECT_EQ(es["step"], 1);
  EXPECT_EQ(es["slide"], lesson.steps[0].slide);
  EXPECT_EQ(es["model"], "phong");
  const json step2 = json_of(run_dir / "step2_es.json"), step3 = json_of(run_dir / "step3_es.json");
  EXPECT_EQ(step2["step"], 2);
  EXPECT_EQ(step2["slide"], lesson.steps[1].slide);
  EXPECT_EQ(step2["title"], lesson.steps[1].title.es);
  EXPECT_EQ(step2["model"], "gouraud");
  EXPECT_EQ(step3["step"], 3);  // after goto 4 and prev
  EXPECT_EQ(step3["model"], "whitted");
}

}  // namespace
}  // namespace luz
