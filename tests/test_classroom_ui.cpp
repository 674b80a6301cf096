// The lesson's caption as the viewer would draw it, in a Dear ImGui frame without a window: every
// step of the shipped lesson, in both languages, fits a box the class can read without hiding
// the picture; and the Spanish letters the panel and the caption draw are glyphs of their own.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>

#include "app/classroom/classroom_ui.h"
#include "app/common/label_text.h"
#include "app/viewer/ui_glyphs.h"
#include "imgui_headless.h"

namespace luz {
namespace {

constexpr float kWindowW = 1280.0f, kWindowH = 760.0f;  // the viewer's default window

class Caption : public ::testing::Test {
protected:
  void SetUp() override { test::create_headless_imgui(kWindowW, kWindowH); }
  void TearDown() override { ImGui::DestroyContext(); }

  // A few frames, as auto-resizing windows take two to settle.
  app::CaptionResult draw(const app::LessonPlayer& player, i18n::Language language, float width, float scale,
                          float max_height = kWindowH, bool collapsed = false) {
    app::CaptionResult result;
    for (int frame = 0; frame < 3; ++frame) {
      ImGui::NewFrame();
      app::CaptionText text;
      text.scale = text.least_scale = scale;
      text.collapsed = collapsed;
      result = app::draw_lesson_caption(player, language, ImVec2(440.0f, 8.0f), width, max_height, text);
      ImGui::Render();
    }
    return result;
  }
};

// In the dock beside the picture, at its narrowest (a third of the 840 units right of the
// panel, less its margins), at 1.25 times the panel's text: the box keeps its width and its
// text fits in the dock's height, above the status line.
TEST_F(Caption, EveryStepFitsInBothLanguages) {
  app::LessonPlayer player(app::parse_lesson(std::filesystem::path(LUZ_LESSON_DIR) / "sintesis.json"));
  const float width = 0.3f * (kWindowW - 440.0f) - 16.0f;
  float tallest = 0.0f;
  for (size_t i = 0; i < player.size(); ++i) {
    player.go_to(i);
    for (i18n::Language language : {i18n::Language::es, i18n::Language::en}) {
      const app::CaptionResult r = draw(player, language, width, 1.25f);
      EXPECT_FLOAT_EQ(r.size.x, width) << "step " << i + 1;
      EXPECT_LE(r.size.y, 0.9f * kWindowH) << "step " << i + 1 << " (" << i18n::language_name(language) << ")";
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

// The height a caption asks for is that of its whole text, also when the box given is lower (the
// viewer makes a dock below the picture that high); folded, it is one line, whatever the step.
TEST_F(Caption, AsksForItsWholeTextAndFoldsToOneLine) {
  app::LessonPlayer player(app::parse_lesson(std::filesystem::path(LUZ_LESSON_DIR) / "sintesis.json"));
  const app::CaptionResult whole = draw(player, i18n::Language::es, 500.0f, 1.0f);
  EXPECT_NEAR(whole.wanted_height, whole.size.y, 1.0f);
  const app::CaptionResult cut = draw(player, i18n::Language::es, 500.0f, 1.0f, 0.5f * whole.size.y);
  EXPECT_NEAR(cut.size.y, 0.5f * whole.size.y, 1.0f);
  EXPECT_NEAR(cut.wanted_height, whole.size.y, 1.0f);
  for (size_t i = 0; i < player.size(); ++i) {
    player.go_to(i);
    const app::CaptionResult folded = draw(player, i18n::Language::es, 500.0f, 1.0f, kWindowH, true);
    EXPECT_LT(folded.size.y, 2.5f * ImGui::GetFontSize()) << "step " << i + 1;
    EXPECT_FALSE(folded.toggle_collapsed);
  }
}

// The smallest box the presenter layout gives the caption at 1280x720 (the panel shown at UI
// scale 2: a row below the 512-unit picture, half of it beside a docked window, less the
// margins: 224 x 296 units), the interface doubled as --ui-scale 2 doubles it: every step's
// whole text, in both languages, fits the box, smaller than asked but at least 0.35 of it (the
// viewer's least, 11 pixels). Kept at the scale asked, the longest texts would be cut.
TEST_F(Caption, EveryStepIsWholeInTheSmallestBoxSmallerIfNeeded) {
  app::LessonPlayer player(app::parse_lesson(std::filesystem::path(LUZ_LESSON_DIR) / "sintesis.json"));
  ImGui::GetStyle().ScaleAllSizes(2.0f);
  constexpr float width = 224.0f, max_height = 296.0f;
  int shrunk = 0;
  for (size_t i = 0; i < player.size(); ++i) {
    player.go_to(i);
    for (i18n::Language language : {i18n::Language::es, i18n::Language::en}) {
      SCOPED_TRACE(testing::Message() << "step " << i + 1 << " (" << i18n::language_name(language) << ")");
      app::CaptionText text;
      text.scale = 2.0f;  // the 16-pixel font doubled
      text.least_scale = 0.7f;
      app::CaptionResult r;
      for (int frame = 0; frame < 3; ++frame) {
        ImGui::NewFrame();
        r = app::draw_lesson_caption(player, language, ImVec2(784.0f, 344.0f), width, max_height, text);
        ImGui::Render();
      }
      const ImGuiWindow* box = ImGui::FindWindowByName("##lesson caption");
      ASSERT_NE(box, nullptr);
      EXPECT_LE(box->ContentSize.y, box->ContentRegionRect.GetHeight() + 1.0f);
      EXPECT_LE(box->ContentSize.x, box->ContentRegionRect.GetWidth() + 1.0f);
      EXPECT_LE(r.size.y, max_height + 0.5f);
      EXPECT_GE(r.text_scale, text.least_scale);
      EXPECT_LE(r.text_scale, text.scale);
      // Shrunk only when the whole text at the scale asked would not fit.
      EXPECT_EQ(r.text_scale < text.scale, r.wanted_height > max_height) << r.wanted_height;
      shrunk += r.text_scale < text.scale;
    }
  }
  EXPECT_GT(shrunk, 0);  // the box is small enough for the fitting to matter
}

// The glyph's coverage in the font atlas (alpha, row by row) and its size.
struct GlyphBitmap {
  int width = 0, height = 0;
  std::vector<unsigned char> alpha;
  bool operator==(const GlyphBitmap&) const = default;
};

GlyphBitmap bitmap_of(const ImFontGlyph& glyph) {
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  ImGui::GetIO().Fonts->GetTexDataAsAlpha8(&pixels, &w, &h);
  GlyphBitmap out;
  const int x0 = int(glyph.U0 * float(w) + 0.5f), x1 = int(glyph.U1 * float(w) + 0.5f);
  const int y0 = int(glyph.V0 * float(h) + 0.5f), y1 = int(glyph.V1 * float(h) + 0.5f);
  out.width = x1 - x0;
  out.height = y1 - y0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) out.alpha.push_back(pixels[y * w + x]);
  return out;
}

// A Spanish label drawn as the panel draws text: each accented letter is its own glyph, not
// ImGui's fallback for a missing one, and not its bare letter (the accent has ink of its own).
TEST_F(Caption, AccentedLettersDrawTheirOwnGlyphs) {
  const char* label = "á é í ó ú ñ ¿ Á É Í Ó Ú Ñ ü";
  const char32_t letters[] = {U'á', U'é', U'í', U'ó', U'ú', U'ñ', U'¿', U'Á', U'É', U'Í', U'Ó', U'Ú', U'Ñ', U'ü'};
  const char bare[] = {'a', 'e', 'i', 'o', 'u', 'n', '?', 'A', 'E', 'I', 'O', 'U', 'N', 'u'};
  ImGui::NewFrame();
  ImGui::SetNextWindowSize(ImVec2(kWindowW, 200.0f));  // the whole line in view: ImGui skips glyphs it clips
  ImGui::Begin("label");
  ImGui::TextUnformatted(label);
  ImGui::End();
  ImGui::Render();
  // The quads the frame drew, by the atlas corner of their glyph.
  std::vector<ImVec2> drawn;
  const ImDrawData* data = ImGui::GetDrawData();
  for (int l = 0; l < data->CmdListsCount; ++l)
    for (const ImDrawVert& v : data->CmdLists[l]->VtxBuffer) drawn.push_back(v.uv);
  auto was_drawn = [&](const ImFontGlyph& g) {
    return std::any_of(drawn.begin(), drawn.end(), [&](const ImVec2& uv) { return uv.x == g.U0 && uv.y == g.V0; });
  };
  const ImFont* font = ImGui::GetIO().Fonts->Fonts[0];
  ASSERT_NE(font->FallbackGlyph, nullptr);
  const GlyphBitmap fallback = bitmap_of(*font->FallbackGlyph);
  for (size_t i = 0; i < std::size(letters); ++i) {
    const ImFontGlyph* glyph = font->FindGlyphNoFallback(ImWchar(letters[i]));
    ASSERT_NE(glyph, nullptr) << "U+" << std::hex << unsigned(letters[i]);
    EXPECT_TRUE(was_drawn(*glyph)) << "U+" << std::hex << unsigned(letters[i]);
    const GlyphBitmap own = bitmap_of(*glyph);
    EXPECT_NE(own, fallback) << "U+" << std::hex << unsigned(letters[i]);
    EXPECT_NE(own, bitmap_of(*font->FindGlyphNoFallback(ImWchar(bare[i])))) << bare[i];
  }
  EXPECT_FALSE(was_drawn(*font->FallbackGlyph));
}

}  // namespace
}  // namespace luz
