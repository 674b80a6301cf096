#include "app/overlays.h"

#include <algorithm>
#include <string>

#include <fmt/format.h>
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
  // Whitted's line says where the trace is: progress while it runs, rays per second at its end.
  std::string model = info(state.model).label;
  const TraceProgress& t = state.trace;
  if (state.model == Model::whitted || state.model == Model::hybrid) {
    if (t.phase == TracePhase::raster) model += state.model == Model::hybrid ? " (radiosity picture)" : " (raster view)";
    else if (t.phase == TracePhase::tracing)
      model += fmt::format(" tracing {}%", t.total > 0 ? 100 * t.done / t.total : 0);
    else model += fmt::format(" traced: {:.2f} s, {:.2f} Mrays/s", t.counters.seconds, t.counters.rays_per_second() / 1e6);
  }
  // Radiosity's: how far the shooting has got.
  const RadiosityStatus& r = state.radiosity.status;
  if ((state.model == Model::radiosity || (state.model == Model::hybrid && t.phase == TracePhase::raster)) && r.built)
    model += fmt::format(" shot {}, {:.2f}% unshot{}", r.shots, 100.0 * r.unshot_fraction,
                         state.radiosity.drive.running ? ", running" : r.done ? ", done" : ", paused");
  ImGui::Text("%s  |  %.1f ms  |  %zu triangles  |  %d lights, %zu emitters  |  %s  |  %s",
              model.c_str(), state.frame_ms, scene.triangle_count(), int(lights),
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
    row("left click", "inspect the pixel: each term's value (Whitted: its ray tree; radiosity: the patch)");
    row("drop a file", "load a .gltf / .glb scene");
    ImGui::EndTable();
  }
  ImGui::End();
}

void draw_trace_hint(const ViewerState& state, float x, float y) {
  const TraceProgress& t = state.trace;
  const bool hybrid = state.model == Model::hybrid;
  if ((state.model != Model::whitted && !hybrid) || t.phase == TracePhase::done) return;
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.75f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
  ImGui::Begin("trace hint", nullptr, flags);
  if (t.phase == TracePhase::tracing) {
    const std::string label = fmt::format("tracing {}/{} tiles, {:.1f} s  (Backspace or moving cancels)",
                                          t.done, t.total, t.seconds);
    ImGui::ProgressBar(t.total > 0 ? float(t.done) / float(t.total) : 0.0f, ImVec2(0.0f, 0.0f), "");
    ImGui::SameLine();
    ImGui::TextUnformatted(label.c_str());
  } else if (!hybrid) {
    ImGui::TextUnformatted("Whitted: the raster (Phong) view. Press Enter / click Render to trace this view");
  } else if (state.trace_requested) {  // the viewer solves radiosity first (see Viewer::show_traced)
    const RadiosityStatus& r = state.radiosity.status;
    ImGui::Text("hybrid: solving radiosity first (shot %d, %.2f %% unshot); the trace starts when it stops",
                r.shots, 100.0 * r.unshot_fraction);
  } else {
    ImGui::TextUnformatted("hybrid: the radiosity picture. Press Enter / click Render to trace its highlights");
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
