// The shipped lesson opened at --ui-scale 2 in a 1280x720 window, as on a projector with the
// interface enlarged: tests/lesson/presenter_start.txt is played by the
// `viewer_presenter_start_script` CTest fixture (Xvfb, Mesa's software GL); these tests read what
// it dumped. Skipped only when xvfb-run is missing.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "viewer_support.h"

namespace luz {
namespace {

namespace fs = std::filesystem;
using test::json_of;

const fs::path run_dir = LUZ_VIEWER_RUN_DIR;

class ViewerPresenterStart : public ::testing::Test {
protected:
  void SetUp() override { test::require_scripted_run(run_dir, LUZ_VIEWER_SCRIPT_TEST); }
  static fs::path file(const std::string& name) { return run_dir / name; }
};

const nlohmann::json* window_named(const nlohmann::json& dump, const std::string& name) {
  for (const auto& w : dump["windows"])
    if (w["name"] == name) return &w;
  return nullptr;
}

double width_of(const nlohmann::json& rect) { return rect[2].get<double>() - rect[0].get<double>(); }

// The panel at scale 2 would take 60 % of the 1280 units (768 of them): a lesson starts with it
// hidden, the picture and the caption sharing the whole width, and the caption's first line says
// which key shows it, in the class's language. Tab shows the panel and the hint goes; Tab again
// hides the panel without bringing the hint back (the class has found the key).
TEST_F(ViewerPresenterStart, AWidePanelStartsHiddenAndTheCaptionSaysTab) {
  const nlohmann::json start = json_of(file("start.json"));
  EXPECT_FALSE(start["show_panel"].get<bool>()) << start.dump(2);
  EXPECT_EQ(start["panel_hint"], "Tab: panel");
  EXPECT_EQ(json_of(file("start-es.json"))["panel_hint"], "Tab: el panel");
  const nlohmann::json windows = json_of(file("start-windows.json"));
  EXPECT_EQ(window_named(windows, "Luz"), nullptr) << windows.dump(2);
  EXPECT_NE(window_named(windows, "##lesson caption"), nullptr) << windows.dump(2);
  EXPECT_NEAR(width_of(windows["view"]) + width_of(windows["dock"]), 1280.0, 1.0) << windows.dump(2);

  const nlohmann::json shown = json_of(file("shown.json"));
  EXPECT_TRUE(shown["show_panel"].get<bool>());
  EXPECT_TRUE(shown["panel_hint"].is_null()) << shown.dump(2);
  EXPECT_NE(window_named(json_of(file("shown-1.json")), "Luz"), nullptr);
  const nlohmann::json again = json_of(file("hidden-again.json"));
  EXPECT_FALSE(again["show_panel"].get<bool>());
  EXPECT_TRUE(again["panel_hint"].is_null()) << again.dump(2);
}

// With the panel shown at scales 2 and 1.5, the room beside it is small: the caption's text is
// drawn smaller rather than cut, for the lesson's longest texts too (steps 12 and 33), below the
// picture and beside a docked window. Its content is never taller or wider than the box shows.
TEST_F(ViewerPresenterStart, WithThePanelShownTheCaptionsTextIsWhole) {
  for (const char* name : {"shown-1.json", "shown-12.json", "shown-33.json", "shown-12-1.5.json", "shown-33-1.5.json"}) {
    SCOPED_TRACE(name);
    const nlohmann::json dump = json_of(file(name));
    ASSERT_NE(window_named(dump, "Luz"), nullptr) << dump.dump(2);
    const nlohmann::json* caption = window_named(dump, "##lesson caption");
    ASSERT_NE(caption, nullptr) << dump.dump(2);
    EXPECT_LE((*caption)["content_height"].get<double>(), (*caption)["visible_height"].get<double>() + 1.0)
        << caption->dump(2);
    EXPECT_LE((*caption)["content_width"].get<double>(), (*caption)["visible_width"].get<double>() + 1.0)
        << caption->dump(2);
  }
}

bool inside(const nlohmann::json& rect, const nlohmann::json& room) {
  return rect[0].get<double>() >= room[0].get<double>() && rect[1].get<double>() >= room[1].get<double>() &&
         rect[2].get<double>() <= room[2].get<double>() && rect[3].get<double>() <= room[3].get<double>();
}

// Whitted's hint at step 12 lies in the dock's column beside the caption, at scales 2, 1.5 and 1:
// while the step's trace runs (when the first dump still sees it) and, after the camera moves,
// the untraced view's longer hint, in English and in Spanish. Its text wraps to the column and is drawn smaller when the room
// below the column's top is short: never taller or wider than its box, the box inside the dock.
TEST_F(ViewerPresenterStart, TheTraceHintsTextIsWholeAtEveryScale) {
  const nlohmann::json moved = json_of(file("shown-12-moved-state.json"));
  ASSERT_EQ(moved["panes"][0]["trace"], "raster") << moved.dump(2);
  for (const char* name : {"shown-12.json", "shown-12-moved.json", "shown-12-moved-es.json", "shown-12-1.5.json",
                           "shown-12-moved-1.5.json", "shown-12-1.json", "shown-12-moved-1.json"}) {
    SCOPED_TRACE(name);
    const nlohmann::json dump = json_of(file(name));
    const nlohmann::json* hint = window_named(dump, "trace hint");
    const bool untraced = std::string(name).find("moved") != std::string::npos;
    if (untraced) {
      ASSERT_NE(hint, nullptr) << dump.dump(2);
    }
    if (hint == nullptr) continue;  // the trace was done before the dump
    EXPECT_LE((*hint)["content_height"].get<double>(), (*hint)["visible_height"].get<double>() + 1.0) << hint->dump(2);
    EXPECT_LE((*hint)["content_width"].get<double>(), (*hint)["visible_width"].get<double>() + 1.0) << hint->dump(2);
    EXPECT_TRUE(inside((*hint)["rect"], dump["dock"])) << dump.dump(2);
  }
}

}  // namespace
}  // namespace luz
