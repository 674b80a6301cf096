#include "app/viewer/panes.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/common/json_file.h"
#include "app/common/i18n.h"
#include "app/common/label_text.h"
#include "app/common/model_registry.h"
#include "app/cli/render_grid.h"
#include "app/script/script.h"
#include "app/viewer/viewer_window.h"
#include "app/viewer/widget_registry.h"
#include "core/error.h"
#include "gl/framebuffer.h"
#include "io/image_io.h"

namespace luz::app {

std::vector<std::string> split_model_list(const std::string& text) {
  std::vector<std::string> models;
  for (size_t start = 0;;) {
    const size_t comma = text.find(',', start);
    models.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return models;
    start = comma + 1;
  }
}

std::string pane_list_problem(const std::vector<std::string>& models) {
  if (models.empty()) return tr("no model to show");
  for (size_t i = 0; i < models.size(); ++i) {
    const ModelEntry* entry = find_model(models[i]);
    if (!entry) return trf("unknown model \"{}\" ({})", models[i], model_names());
    if (std::find(models.begin(), models.begin() + long(i), models[i]) != models.begin() + long(i))
      return trf("{} is in the list twice: each pane shows another model", models[i]);
  }
  if (models.size() > kMaxPanes) return trf("side by side takes at most {} models, not {}", kMaxPanes, models.size());
  return "";
}

std::vector<Viewport> pane_viewports(const Viewport& view, size_t count) {
  if (count <= 1) return {view};
  const GridLayout grid = grid_layout(count);
  const glm::ivec2 pixels(view.pixels.x / grid.columns, view.pixels.y / grid.rows);
  std::vector<Viewport> panes;
  for (size_t i = 0; i < count; ++i) {
    const glm::ivec2 cell(int(i) % grid.columns, int(i) / grid.columns);  // row 0 at the top
    Viewport pane;
    pane.scale = view.scale;
    pane.pixels = pixels;
    pane.origin = view.origin + glm::vec2(cell * pixels) / view.scale;
    pane.size = glm::vec2(pixels) / view.scale;
    pane.gl_origin = view.gl_origin + glm::ivec2(cell.x * pixels.x, view.pixels.y - (cell.y + 1) * pixels.y);
    panes.push_back(pane);
  }
  return panes;
}

int pane_at(const std::vector<Viewport>& panes, glm::vec2 p) {
  for (size_t i = 0; i < panes.size(); ++i)
    if (panes[i].contains(p)) return int(i);
  return -1;
}

// ---- labels --------------------------------------------------------------------------------------
PaneLabel pane_label(const std::string& model, const Viewport& pane) {
  PaneLabel label;
  label.text = model_label(model);
  label.text_size = label_pixel_height(pane.pixels.y) / pane.scale.y;  // the grid's, in window units
  label.pad = std::ceil(0.3f * label.text_size);
  const ImVec2 text = ImGui::GetFont()->CalcTextSizeA(label.text_size, FLT_MAX, 0.0f, label.text.c_str());
  label.origin = pane.origin;
  label.size = glm::vec2(text.x + 2.0f * label.pad, text.y + 2.0f * label.pad);
  return label;
}

void draw_pane_label(const PaneLabel& label, bool active) {
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const ImVec2 from(label.origin.x, label.origin.y), to(label.origin.x + label.size.x, label.origin.y + label.size.y);
  list->AddRectFilled(from, to, active ? ImGui::GetColorU32(ImGuiCol_ButtonActive) : IM_COL32(0, 0, 0, 190));
  list->AddText(ImGui::GetFont(), label.text_size, ImVec2(from.x + label.pad, from.y + label.pad),
                IM_COL32(255, 255, 255, 255), label.text.c_str());
}

// ---- the screenshot ------------------------------------------------------------------------------
PixelRect screenshot_label_box(const std::string& model, glm::ivec2 pane_pixels) {
  const LabelBox box = label_box(LabelFont(), model_label(model), pane_pixels.y);
  return {box.x, box.y, box.width, box.height};
}

void save_panes(const std::vector<const gl::Framebuffer*>& pictures, const std::vector<Viewport>& panes,
                const std::vector<std::string>& models, const Viewport& view, const std::filesystem::path& path,
                float exposure) {
  const GridLayout grid = grid_layout(panes.size());
  const glm::ivec2 pane_pixels = panes.front().pixels;
  Image sheet(grid.columns * pane_pixels.x, grid.rows * pane_pixels.y);  // the headless grid's shape
  const LabelFont font;
  {
    const gl::KeptBinding kept;
    for (size_t i = 0; i < panes.size(); ++i) {
      Image pane = pictures[i]->read();
      draw_label(pane, font, model_label(models[i]), exposure);
      const glm::ivec2 at = glm::ivec2(glm::round((panes[i].origin - view.origin) * view.scale));
      for (int y = 0; y < pane.height; ++y) std::copy_n(&pane.at(0, y), pane.width, &sheet.at(at.x, at.y + y));
    }
  }
  io::write_image(sheet, path, exposure);
}

// ---- the panel -----------------------------------------------------------------------------------
namespace {

std::string joined_labels(const std::vector<std::string>& models) {
  std::string text;
  for (const std::string& m : models) text += (text.empty() ? "" : " | ") + model_label(m);
  return text;
}

// A button on the current line when it fits there, else on the next: never cut at the panel's edge.
bool flowing_button(const char* label, bool first) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = ImGui::CalcTextSize(label).x + 2.0f * style.FramePadding.x;
  if (!first) {
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
  }
  return ImGui::Button(label);
}

}  // namespace

void panes_section(ViewerState& state) {
  const bool section_open = ImGui::CollapsingHeader(tr("Side by side (slide 44)"), ImGuiTreeNodeFlags_DefaultOpen);
  name_widget("Side by side (slide 44)");  // a script folds a section to reach the ones below
  if (!section_open) return;
  const std::vector<std::string> shown = state.panes.empty() ? std::vector<std::string>{state.model} : state.panes;
  int column = 0;
  for (const ModelEntry& m : models()) {
    const auto found = std::find(shown.begin(), shown.end(), m.name);
    bool in = found != shown.end();
    const bool locked = in ? shown.size() == 1 : shown.size() >= kMaxPanes;  // one picture at least, four at most
    ImGui::BeginDisabled(locked);
    const std::string id = fmt::format("{}##pane-{}", model_label(m.name), m.name);
    if (ImGui::Checkbox(id.c_str(), &in)) {
      std::vector<std::string> wanted = shown;
      if (in) wanted.push_back(m.name);
      else wanted.erase(std::find(wanted.begin(), wanted.end(), m.name));
      state.panel_lines.push_back(fmt::format("panes {}", fmt::join(wanted, ",")));
    }
    ImGui::EndDisabled();
    if (++column % 3 != 0) ImGui::SameLine();
  }
  if (column % 3 != 0) ImGui::NewLine();
  bool first = true;
  for (const std::vector<std::string>& preset : lecture_comparisons()) {
    if (!pane_list_problem(preset).empty()) continue;
    if (flowing_button(joined_labels(preset).c_str(), first)) state.panel_lines.push_back(fmt::format("panes {}", fmt::join(preset, ",")));
    first = false;
  }
  ImGui::BeginDisabled(state.panes.empty());
  if (flowing_button(tr("One picture"), first)) state.panel_lines.push_back("panes off");
  ImGui::EndDisabled();
}

// ---- the script's verbs --------------------------------------------------------------------------
std::string check_panes(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  if (c.args[0] == "off") return "";
  return pane_list_problem(split_model_list(c.args[0]));
}

bool run_panes(Viewer& viewer, const ScriptCommand& c, std::string&) {
  viewer.set_panes(c.args[0] == "off" ? std::vector<std::string>{viewer.model().name} : split_model_list(c.args[0]));
  return true;
}

bool run_dump_panes(Viewer& viewer, const ScriptCommand& c, std::string& error) {
  const Layout& l = viewer.drawn_layout();
  const std::vector<const ModelEntry*>& models = viewer.panes();
  nlohmann::json panes = nlohmann::json::array();
  for (size_t i = 0; i < models.size() && i < l.panes.size(); ++i) {
    const Viewport& v = l.panes[i];
    const PaneLabel label = pane_label(models[i]->name, v);
    const glm::ivec2 at = glm::ivec2(glm::round((v.origin - l.view.origin) * v.scale));
    const PixelRect box = screenshot_label_box(models[i]->name, v.pixels);
    const Camera& camera = viewer.drawn_camera(i);
    const glm::vec3 eye = camera.position(), forward = camera.forward();
    panes.push_back({{"model", models[i]->name},
                     {"label", label.text},
                     {"rect", {v.origin.x, v.origin.y, v.origin.x + v.size.x, v.origin.y + v.size.y}},
                     {"label_rect", {label.origin.x, label.origin.y, label.origin.x + label.size.x,
                                     label.origin.y + label.size.y}},
                     {"screenshot", {at.x, at.y, v.pixels.x, v.pixels.y}},
                     {"screenshot_label", {box.x, box.y, box.width, box.height}},
                     {"camera", {{"position", {eye.x, eye.y, eye.z}},
                                 {"forward", {forward.x, forward.y, forward.z}},
                                 {"yfov", camera.yfov}}}});
    // A traced pane's trace: raster (not asked for), tracing or done.
    if (const char* trace = viewer.view(models[i]->name).trace_state()) panes.back()["trace"] = trace;
  }
  const nlohmann::json j = {{"active", viewer.active_pane()}, {"panes", panes}};
  return write_json(c.args[0], j, "the panes", error);
}

}  // namespace luz::app
