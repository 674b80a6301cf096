// Which of a frame's ImGui draw lists the panel cache may hold (app/panel_cache.h), on frames
// built by Dear ImGui without a window: the panel's own lists and the status line's are the
// cache's; a window over the picture, a window over the panel's edge and whatever the panel must
// show under it are drawn as they are. (The cached pixels against the panel drawn every frame: test_viewer_layout.)
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <vector>

#include <imgui.h>

#include "app/viewer/overlays.h"
#include "app/viewer/panel_cache.h"
#include "imgui_headless.h"

namespace luz {
namespace {

constexpr float kWindowW = 1280.0f, kWindowH = 760.0f, kPanelW = 440.0f, kStatusH = 32.0f;
constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoSavedSettings |
                                    ImGuiWindowFlags_NoBringToFrontOnFocus;

class PanelCacheLists : public ::testing::Test {
protected:
  void SetUp() override {
    test::create_headless_imgui(kWindowW, kWindowH);
    ImGui::GetIO().Fonts->SetTexID(reinterpret_cast<ImTextureID>(intptr_t(1)));
  }
  void TearDown() override { ImGui::DestroyContext(); }

  // The viewer's frame: the status line, the panel, then `more` (other windows), twice so that
  // every window has settled; returns the lists' owners by name, cached then live.
  std::pair<std::vector<std::string>, std::vector<std::string>> split(const std::function<void()>& more) {
    std::vector<ImDrawList*> cached, live;
    for (int frame = 0; frame < 2; ++frame) {
      ImGui::NewFrame();
      app::begin_frame_window("status", {0.0f, kWindowH - kStatusH}, {kWindowW, kStatusH}, kFixed, app::Edge::top);
      ImGui::Text("flat | 9.8 ms");
      ImGui::End();
      app::begin_frame_window("Luz", {0.0f, 0.0f}, {kPanelW, kWindowH - kStatusH}, kFixed, app::Edge::right);
      ImGui::Text("Model");
      ImGui::Button("a button");
      ImGui::End();
      more();
      ImGui::Render();
      const app::FramebufferRect panel[] = {{0, int(kStatusH), int(kPanelW), int(kWindowH - kStatusH)},
                                            {0, 0, int(kWindowW), int(kStatusH)}};
      app::split_lists(*ImGui::GetDrawData(), panel, ImGui::GetIO().Fonts->TexID, cached, live);
    }
    return {names(cached), names(live)};
  }

  static std::vector<std::string> names(const std::vector<ImDrawList*>& lists) {
    std::vector<std::string> out;
    for (const ImDrawList* list : lists) out.push_back(list->_OwnerName ? list->_OwnerName : "?");
    return out;
  }
};

void window(const char* name, ImVec2 at, ImVec2 size) {
  ImGui::SetNextWindowPos(at, ImGuiCond_Always);
  ImGui::SetNextWindowSize(size, ImGuiCond_Always);
  ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoSavedSettings);
  ImGui::Text("%s", name);
  ImGui::End();
}

using Names = std::vector<std::string>;

// The panel and the status line, each inside its rectangle, are the cache's; a window over the
// picture is not, nor one across the picture and the status line.
TEST_F(PanelCacheLists, ThePanelIsCachedAndTheRestDrawnAsItIs) {
  const auto [cached, live] = split([] {
    window("hint", {600.0f, 100.0f}, {200.0f, 80.0f});
    window("warning", {600.0f, kWindowH - kStatusH - 20.0f}, {200.0f, 40.0f});
  });
  EXPECT_EQ(cached, (Names{"Luz", "status"}));
  EXPECT_EQ(live, (Names{"hint", "warning"}));
}

// A window across the panel's edge is drawn after the cached panel, so it stays on top; a
// window inside the panel drawn after it cannot come from the cache (the copy would cover the
// crossing window), while a window inside the panel drawn before it can.
TEST_F(PanelCacheLists, WhatMustStayOnTopOfAWindowOverThePanelIsNotCached) {
  const auto [cached, live] = split([] {
    window("popup before", {20.0f, 200.0f}, {150.0f, 60.0f});
    window("tooltip", {380.0f, 300.0f}, {200.0f, 60.0f});
    window("popup after", {20.0f, 400.0f}, {150.0f, 60.0f});
  });
  EXPECT_EQ(cached, (Names{"Luz", "status", "popup before"}));
  EXPECT_EQ(live, (Names{"tooltip", "popup after"}));
}

// An image (the hemicube's item buffer) changes without its vertices changing: a window showing
// one over the panel is drawn as it is.
TEST_F(PanelCacheLists, AnImageOverThePanelIsDrawnAsItIs) {
  const auto [cached, live] = split([] {
    ImGui::SetNextWindowPos({20.0f, 200.0f}, ImGuiCond_Always);
    ImGui::Begin("item buffer", nullptr, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::Image(reinterpret_cast<ImTextureID>(intptr_t(7)), ImVec2(64.0f, 64.0f));
    ImGui::End();
  });
  EXPECT_EQ(cached, (Names{"Luz", "status"}));
  EXPECT_EQ(live, Names{"item buffer"});
}

}  // namespace
}  // namespace luz
