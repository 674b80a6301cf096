// The difference view. Sections: [the comparison] [the legend and the panel] [script verbs]
#include "app/viewer/difference_window.h"

#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/common/json_file.h"
#include "app/common/i18n.h"
#include "app/viewer/background_render.h"
#include "app/common/model_registry.h"
#include "app/viewer/overlays.h"
#include "app/viewer/viewer_window.h"
#include "app/viewer/widget_registry.h"
#include "gl/functions.h"

namespace luz::app {

// ---- [the comparison] ----------------------------------------------------------------------------
DifferenceFigures difference_figures(const ImageComparison& c, int width, int height) {
  DifferenceFigures f;
  f.width = width;
  f.height = height;
  f.mean_error = c.mean_error;
  f.mean_absolute_error = c.mean_absolute_error;
  f.rel_rmse = c.rel_rmse;
  f.mean_relative_error = c.mean_relative_error;
  f.lit_pixels = c.lit_pixels;
  f.range = kHeatmapRange;
  return f;
}

void DifferenceView::draw(ViewerServices& viewer, const ModelEntry& compared, const Camera& camera,
                          const Viewport& viewport, gl::Framebuffer& picture, bool reference_in_a_pane) {
  const ViewerState& state = viewer.state();
  DifferenceState& d = state_;
  const ModelEntry& reference_entry = reference_model();
  const bool reference_shown = &compared == &reference_entry;
  if (!d.on || reference_shown) {
    // The reference ran for the comparison: it stops (when it is shown, the viewer drives it).
    if (d.running && !reference_in_a_pane) viewer.view(reference_entry.name).hidden();
    d.running = d.refining = d.waiting = d.valid = false;
    d.why = d.on ? tr("the path tracer is the reference itself: choose another model to compare") : "";
    return;
  }
  ModelView& reference = viewer.view(reference_entry.name);
  reference.advance(camera, viewport);
  d.running = true;
  d.refining = reference.animating();
  d.waiting = d.waiting && reference.busy();
  const PathPicture* pass = reference.picture_for(camera, viewport.pixels);
  if (!pass) {
    d.valid = false;
    d.why = tr("waiting for the path tracer's first pass");
    return;  // the model's own picture meanwhile
  }
  const Image model = picture.read();
  const ImageComparison comparison = compare_images(model, pass->mean);
  d.figures = difference_figures(comparison, model.width, model.height);
  d.figures.model = compared.label;
  d.figures.reference_spp = pass->spp;
  d.figures.reference_noise = pass->noise;
  d.valid = true;
  d.why.clear();
  // Shown through the exposure, as every picture: divided by 2^exposure here, the heat map's
  // colours reach the screen as they are.
  Image heatmap = relative_difference_heatmap(comparison, model.width, model.height, d.figures.range);
  const float scale = std::exp2(-state.exposure);
  for (Rgb& p : heatmap.pixels) p = p * scale;
  std::vector<float> scratch;
  upload_pixels(picture, heatmap, 0, 0, heatmap.width, heatmap.height, scratch);
  picture.bind();
}

// ---- [the legend and the panel] ------------------------------------------------------------------
namespace {

ImU32 imgui_colour(const Rgb& linear) {
  return IM_COL32(srgb_byte(linear.r), srgb_byte(linear.g), srgb_byte(linear.b), 255);
}

std::string percent(double fraction) { return fmt::format("{:.2f}%", 100.0 * fraction); }

}  // namespace

void DifferenceView::windows(const Viewport& viewport, WindowCorners& corners) const {
  const DifferenceState& d = state_;
  if (!d.on) return;
  // As wide as its corner allows (WindowCorners keeps the quarter), the text wrapped to it.
  const float width = std::min(24.0f * ImGui::GetFontSize(), std::max(0.5f * viewport.size.x - 24.0f, 80.0f));
  corners.place(WindowCorners::bottom_right);
  ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);  // 0: its height fits the text
  ImGui::SetNextWindowBgAlpha(0.85f);
  // A small pane (side by side, or a small window) gets the bar, its scale and the one figure,
  // untitled: the whole legend would be a column of broken words there.
  const bool compact = width < 16.0f * ImGui::GetFontSize() ||
                       0.5f * viewport.size.y < 15.0f * ImGui::GetTextLineHeightWithSpacing();
  ImGui::Begin(tr("difference view"), nullptr,
               ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | (compact ? ImGuiWindowFlags_NoTitleBar : 0));
  if (!d.valid) {
    ImGui::TextWrapped("%s", d.why.c_str());
    ImGui::End();
    return;
  }
  const DifferenceFigures& f = d.figures;
  if (!compact) {
    ImGui::TextWrapped("%s", trf("{} against the path tracer ({} spp)", tr(f.model.c_str()), f.reference_spp).c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s", tr("(Y(model) - Y(reference)) / Y(reference), lit pixels"));
    ImGui::PopStyleColor();
  }

  // The colour bar, -range .. +range, as the heat map colours it.
  const float bar = ImGui::GetContentRegionAvail().x, height = ImGui::GetFontSize();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  constexpr int steps = 64;
  for (int i = 0; i < steps; ++i) {
    const float t = 2.0f * (float(i) + 0.5f) / float(steps) - 1.0f;
    draw->AddRectFilled(ImVec2(at.x + bar * float(i) / steps, at.y), ImVec2(at.x + bar * float(i + 1) / steps, at.y + height),
                        imgui_colour(diverging_colour(t)));
  }
  ImGui::Dummy(ImVec2(bar, height));
  const std::string low = fmt::format("-{:g}%", 100.0 * double(f.range)), high = fmt::format("+{:g}%", 100.0 * double(f.range));
  const float left = ImGui::GetCursorPosX();
  if (ImGui::CalcTextSize((low + " 0 " + high).c_str()).x <= bar) {
    ImGui::TextUnformatted(low.c_str());
    ImGui::SameLine(left + 0.5f * (bar - ImGui::CalcTextSize("0").x));
    ImGui::TextUnformatted("0");
    ImGui::SameLine(left + bar - ImGui::CalcTextSize(high.c_str()).x);
    ImGui::TextUnformatted(high.c_str());
  } else {
    ImGui::TextUnformatted(fmt::format("±{:g}%", 100.0 * double(f.range)).c_str());
  }
  if (compact) {
    ImGui::TextWrapped("%s", trf("mean rel. error {}", percent(f.mean_relative_error)).c_str());
    ImGui::End();
    return;
  }
  ImGui::TextWrapped("%s", tr("blue: the model is darker, red: brighter, grey: unlit"));
  ImGui::Separator();
  ImGui::TextWrapped("%s", trf("mean relative error: {} over {} lit pixels", percent(f.mean_relative_error), f.lit_pixels).c_str());
  ImGui::TextWrapped("%s", trf("mean error (model - reference): R {:+.4f}  G {:+.4f}  B {:+.4f}", f.mean_error.r,
                               f.mean_error.g, f.mean_error.b).c_str());
  ImGui::TextWrapped("%s", trf("rel-RMSE {:.4f}; the reference's own noise {}", f.rel_rmse, percent(f.reference_noise)).c_str());
  ImGui::End();
}

void DifferenceView::panel() {
  DifferenceState& d = state_;
  // On the model buttons' last row when it fits there (in the language shown), else below.
  const char* label = tr("difference against the path tracer");
  const float width = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
  if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
  ImGui::Checkbox(label, &d.on);
  name_widget("difference against the path tracer");
  if (!d.on) return;
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  if (d.valid)
    ImGui::TextWrapped("%s", trf("mean relative error {} ({} spp reference)", percent(d.figures.mean_relative_error),
                                 d.figures.reference_spp).c_str());
  else if (!d.why.empty())
    ImGui::TextWrapped("%s", d.why.c_str());
  ImGui::PopStyleColor();
}

// ---- [script verbs] ------------------------------------------------------------------------------
std::string check_difference(const ScriptCommand& c) {
  if (auto e = check_count(c, 1, 1); !e.empty()) return e;
  return c.args[0] == "on" || c.args[0] == "off" ? "" : "`difference` takes on or off";
}

bool run_difference(ViewerServices& viewer, const ScriptCommand& c, std::string&) {
  viewer.difference().set_on(c.args[0] == "on");
  return true;
}

bool run_dump_difference(ViewerServices& viewer, const ScriptCommand& c, std::string& error) {
  const DifferenceState& d = viewer.difference().state();
  const DifferenceFigures& f = d.figures;
  auto rgb = [](const Rgb& v) { return nlohmann::json::array({v.r, v.g, v.b}); };
  nlohmann::json j = {{"on", d.on}, {"valid", d.valid}, {"why", d.why}};
  if (d.valid) {
    j["model"] = f.model;
    j["size"] = {f.width, f.height};
    j["mean_error"] = rgb(f.mean_error);
    j["mean_absolute_error"] = rgb(f.mean_absolute_error);
    j["rel_rmse"] = f.rel_rmse;
    j["mean_relative_error"] = f.mean_relative_error;
    j["lit_pixels"] = f.lit_pixels;
    j["range"] = f.range;
    j["reference_spp"] = f.reference_spp;
    j["reference_noise"] = f.reference_noise;
  }
  return write_json(c.args[0], j, "the difference view's figures", error);
}

}  // namespace luz::app
