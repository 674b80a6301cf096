#pragma once
// A Dear ImGui context without a window or GL, for tests that build frames and read what ImGui
// laid out or drew: the given display size, the viewer's font at 16 px with the panel's glyphs,
// the font atlas built (its texture never uploaded). One per test: made in SetUp, gone in
// TearDown.
#include <imgui.h>

#include "app/common/label_text.h"
#include "app/viewer/ui_glyphs.h"

namespace luz::test {

inline void create_headless_imgui(float width, float height) {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = ImVec2(width, height);
  io.DeltaTime = 1.0f / 60.0f;
  io.Fonts->AddFontFromFileTTF(app::LabelFont::default_file().c_str(), 16.0f, nullptr,
                               reinterpret_cast<const ImWchar*>(app::kUiGlyphRanges));
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
}

}  // namespace luz::test
