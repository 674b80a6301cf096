// The lesson's caption as the viewer would draw it, in a Dear ImGui frame without a window: every
// step of the shipped lesson, in both languages, fits a box the class can read without hiding
// the picture.
#include <gtest/gtest.h>

#include <imgui.h>

#include "app/classroom_ui.h"
#include "app/label_text.h"
#include "app/ui_glyphs.h"

namespace luz {
namespace {

constexpr float kWindowW = 1280.0f, kWindowH = 760.0f;  // the viewer's default window

class Caption : public ::testing::Test {
protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(kWindowW, kWindowH);
    io.DeltaTime = 1.0f / 60.0f;
    io.Fonts->AddFontFromFileTTF(app::LabelFont::default_file().c_str(), 16.0f, nullptr,
                                 reinterpret_cast<const ImWchar*>(app::kUiGlyphRanges));
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  }
  void TearDown() override { ImGui::DestroyContext(); }

  // A few frames, as auto-resizing windows take two to settle.
  app::CaptionResult draw(const app::LessonPlayer& player, i18n::Language language, float width, float scale) {
    app::CaptionResult result;
    for (int frame = 0; frame < 3; ++frame) {
      ImGui::NewFrame();
      result = app::draw_lesson_caption(player, language, ImVec2(440.0f, 8.0f), width, scale);
      ImGui::Render();
    }
    return result;
  }
};

// Over the picture (840 units wide right of the panel), at 1.25 times the panel's text: the box
// keeps its width and never takes more than half the window's height.
TEST_F(Caption, EveryStepFitsInBothLanguages) {
  app::LessonPlayer player(app::parse_lesson(std::filesystem::path(LUZ_LESSON_DIR) / "sintesis.json"));
  const float width = 0.8f * (kWindowW - 440.0f);
  float tallest = 0.0f;
  for (size_t i = 0; i < player.size(); ++i) {
    player.go_to(i);
    for (i18n::Language language : {i18n::Language::es, i18n::Language::en}) {
      const app::CaptionResult r = draw(player, language, width, 1.25f);
      EXPECT_FLOAT_EQ(r.size.x, width) << "step " << i + 1;
      EXPECT_LE(r.size.y, 0.5f * kWindowH) << "step " << i + 1 << " (" << i18n::language_name(language) << ")";
      EXPECT_EQ(r.move, app::LessonMove::none);
      tallest = std::max(tallest, r.size.y);
    }
  }
  EXPECT_GT(tallest, 60.0f);  // the text is really there, on several lines
}

// A longer text takes more lines, not more width.
TEST_F(Caption, WrapsInsteadOfWidening) {
  app::LessonPlayer player(app::parse_lesson(std::filesystem::path(LUZ_LESSON_DIR) / "sintesis.json"));
  const app::CaptionResult wide = draw(player, i18n::Language::es, 800.0f, 1.0f);
  const app::CaptionResult narrow = draw(player, i18n::Language::es, 300.0f, 1.0f);
  EXPECT_FLOAT_EQ(narrow.size.x, 300.0f);
  EXPECT_GT(narrow.size.y, wide.size.y);
}

}  // namespace
}  // namespace luz
