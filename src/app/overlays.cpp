#include "app/overlays.h"

#include <algorithm>
#include <string>

#include <imgui.h>

#include "app/shortcuts.h"

namespace luz::app {

void draw_status_line(const ViewerState& state, float top, float width, float height) {
  const Scene& scene = *state.scene;
  ImGui::SetNextWindowPos(ImVec2(0, top));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  ImGui::Begin("status", nullptr, fixed);
  const auto lights = std::count_if(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.enabled; });
  const std::string camera = state.free_camera ? "free camera (C: back)" : scene.cameras[size_t(state.scene_camera)].name;
  ImGui::Text("%s  |  %.1f ms  |  %zu triangles  |  %d lights, %zu emitters  |  %s  |  %s",
              info(state.model).label, state.frame_ms, scene.triangle_count(), int(lights),
              scene.area_lights.size(), camera.c_str(), state.note.c_str());
  ImGui::End();
}

void draw_help(bool& open, float x, float y) {
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::Begin("Keys (F1)", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    auto row = [](const char* keys, const char* what) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(what);
    };
    for (const Shortcut& s : shortcuts()) row(s.keys, s.what);
    row("left drag", "orbit around the scene");
    row("right drag", "pan");
    row("wheel", "zoom");
    row("left click", "inspect the pixel: each term's value");
    row("drop a file", "load a .gltf / .glb scene");
    ImGui::EndTable();
  }
  ImGui::End();
}

void draw_load_error(ViewerState& state, float x, float y, float max_width) {
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(0.9f * max_width, 1e6f));
  // A red title: the tests find the window by it (tests/test_viewer.cpp).
  ImGui::PushStyleColor(ImGuiCol_TitleBgActive, ImVec4(0.6f, 0.1f, 0.1f, 1.0f));
  ImGui::PushStyleColor(ImGuiCol_TitleBg, ImVec4(0.6f, 0.1f, 0.1f, 1.0f));
  ImGui::Begin("The scene did not load", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::PushTextWrapPos(0.85f * max_width);
  ImGui::TextUnformatted(state.error.c_str());
  ImGui::PopTextWrapPos();
  ImGui::TextDisabled("Still showing %s. Fix the file and press R, or drop another.",
                      state.scene_path.filename().string().c_str());
  if (ImGui::Button("OK")) state.error.clear();
  ImGui::End();
  ImGui::PopStyleColor(2);
}

}  // namespace luz::app
