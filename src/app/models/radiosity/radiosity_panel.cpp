// The panel's radiosity section (model 5) and the small window with the last shot's hemicube.
// The section follows slide 39: the loop's controls (run, pause, one shot, back to step 1), how
// far it has got (shots, unshot power, its plot against the shots), then the settings: how much
// of each frame goes to shooting, when to stop, the mesh and the hemicube (slide 37, 40), and
// what step 3 displays.
//
// Sections: [the loop] [the plot] [settings] [display] [the section] [the item-buffer window]
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <imgui.h>

#include "app/common/i18n.h"
#include "app/viewer/overlays.h"
#include "app/common/options_tables.h"
#include "app/viewer/panel.h"
#include "app/models/radiosity/radiosity_panel.h"
#include "app/models/radiosity/radiosity_session.h"
#include "core/image.h"

namespace luz::app {
namespace {

const ImVec4 shooter_colour(1.0f, 0.35f, 1.0f, 1.0f);  // the renderer's magenta highlight

// ---- [the loop] --------------------------------------------------------------------------------
void loop_controls(RadiosityState& r) {
  const RadiosityStatus& s = r.status;
  const char* run = r.drive.running ? N_("pause  [Space]") : N_("run  [Space]");
  if (ImGui::Button(tr(run), ImVec2(9.0f * ImGui::GetFontSize(), 0.0f))) r.drive.running = !r.drive.running;
  name_widget(run);
  ImGui::SameLine();
  if (ImGui::Button(tr("one shot  [.]"))) r.steps += 1;
  name_widget("one shot  [.]");
  ImGui::SameLine();
  if (ImGui::Button(tr("reset  [0]"))) r.reset = true;
  name_widget("reset  [0]");

  // Counters in two columns: what, then its value at a fixed indent.
  const float column = 9.0f * ImGui::GetFontSize();
  auto row = [column](const char* what, const std::string& value) {
    ImGui::TextUnformatted(what);
    ImGui::SameLine(column);
    ImGui::TextWrapped("%s", value.c_str());
  };
  row(tr("shots"), fmt::format("{}{}", s.shots, s.done ? tr("  (done: the stopping rule holds)") : ""));
  // xgettext:no-c-format (a fmt string, where "% o" is not a printf directive)
  const std::string unshot = trf("{:.3f} % of the emitted", 100.0 * s.unshot_fraction);
  row(tr("unshot power"), unshot);
  row(tr("shots / s"), r.drive.running ? fmt::format("{:.0f}", s.shots_per_second) : std::string(tr("paused")));
  row(tr("patches"), trf("{}  (longest edge {:.3g} m), {} elements", s.patches, s.patch_size, s.elements));
  ImGui::TextUnformatted(tr("shooter"));
  ImGui::SameLine(column);
  if (s.shooter.empty()) dim_text("%s", tr("none yet (step 1: unshot = E)"));
  else ImGui::TextColored(shooter_colour, "%s", s.shooter.c_str());
}

// ---- [the plot] --------------------------------------------------------------------------------
// log10 of the unshot fraction against the shots: the straight-ish fall of progressive
// refinement reads better on a log scale, with a faint line at every decade (100 %, 10 %, ...)
// and the stopping level dashed.
void unshot_plot(RadiosityState& r, const RadiosityOptions& o) {
  RadiosityStatus& s = r.status;
  const float stop = o.converge > 0.0f ? std::log10(o.converge) : -3.0f;
  float low = stop;
  for (const float v : s.plot) low = std::min(low, v);
  low = std::floor(low * 2.0f - 0.25f) / 2.0f;  // a little room under the lowest point
  const float high = 0.1f;
  dim_text(tr("unshot power / emitted (log scale) against shots 0 .. %d"), s.shots);
  ImGui::PushStyleColor(ImGuiCol_PlotLines, ImVec4(1.0f, 0.8f, 0.3f, 1.0f));  // brighter than the default grey
  ImGui::PlotLines("##unshot", s.plot.data(), int(s.plot.size()), 0, nullptr, low, high,
                   ImVec2(ImGui::GetContentRegionAvail().x, 6.0f * ImGui::GetFontSize()));  // 1.86: no -1
  ImGui::PopStyleColor();
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  s.plot_min = glm::vec2(min.x, min.y);
  s.plot_max = glm::vec2(max.x, max.y);

  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImGuiStyle& style = ImGui::GetStyle();
  const float top = min.y + style.FramePadding.y, bottom = max.y - style.FramePadding.y;
  auto y_of = [&](float v) { return bottom - (v - low) / (high - low) * (bottom - top); };
  for (int decade = 0; decade >= int(std::ceil(low)); --decade) {
    const float y = y_of(float(decade));
    draw->AddLine(ImVec2(min.x, y), ImVec2(max.x, y), IM_COL32(255, 255, 255, 40));
    const std::string label = decade >= -2 ? fmt::format("{:g} %", 100.0 * std::pow(10.0, decade))
                                           : fmt::format("1e{} ", decade);
    // Above its line, but inside the frame: the top decade's label would cover the caption.
    draw->AddText(ImVec2(min.x + style.FramePadding.x, std::max(y - ImGui::GetFontSize(), min.y)),
                  IM_COL32(200, 200, 200, 160), label.c_str());
  }
  if (o.converge > 0.0f) {
    const float y = y_of(stop);
    for (float x = min.x; x < max.x; x += 8.0f)
      draw->AddLine(ImVec2(x, y), ImVec2(std::min(x + 4.0f, max.x), y), IM_COL32(120, 220, 120, 200), 1.5f);
  }
}

// ---- [settings] --------------------------------------------------------------------------------
void drive_settings(RadiosityState& r, RadiosityOptions& o) {
  RadiosityDrive& d = r.drive;
  int by_time = d.by_time ? 1 : 0;
  ImGui::TextUnformatted(tr("each frame:"));
  ImGui::SameLine();
  ImGui::RadioButton(tr("time budget"), &by_time, 1);
  name_widget("time budget");
  ImGui::SameLine();
  ImGui::RadioButton(tr("shots"), &by_time, 0);
  name_widget("shots");
  d.by_time = by_time == 1;
  if (d.by_time) {
    if (ImGui::SliderFloat(tr("ms of shooting / frame"), &d.budget_ms, 1.0f, 200.0f, "%.0f ms",
                           ImGuiSliderFlags_Logarithmic))
      d.budget_chosen = true;
    name_widget("ms of shooting / frame");
  } else {
    ImGui::SliderInt(tr("shots / frame"), &d.shots_per_frame, 1, 500, "%d", ImGuiSliderFlags_Logarithmic);
    name_widget("shots / frame");
  }

  int by_shots = o.max_shots > 0 ? 1 : 0;
  ImGui::TextUnformatted(tr("stop:"));
  ImGui::SameLine();
  ImGui::RadioButton(tr("unshot below"), &by_shots, 0);
  name_widget("unshot below");
  ImGui::SameLine();
  ImGui::RadioButton(tr("after shots"), &by_shots, 1);
  name_widget("after shots");
  if (by_shots == 1) {
    if (o.max_shots <= 0) o.max_shots = std::max(r.status.shots, 100);
    const SliderRange shots = slider_range(radiosity_table(), "shots", 1e6);
    ImGui::DragInt(tr("shots##stop"), &o.max_shots, 5.0f, int(shots.low), int(shots.high));
    name_widget("shots##stop");
    o.max_shots = std::max(o.max_shots, 1);
    o.converge = 0.0f;  // as `luz render --shots N`
  } else {
    if (o.converge <= 0.0f) o.converge = RadiosityOptions{}.converge;
    o.max_shots = 0;
    float percent = 100.0f * o.converge;
    const SliderRange converge = slider_range(radiosity_table(), "converge");
    ImGui::SliderFloat(tr("percent of the emitted"), &percent, 100.0f * converge.low, 100.0f * converge.high, "%.2g %%",
                       ImGuiSliderFlags_Logarithmic);
    name_widget("% of the emitted");
    o.converge = std::clamp(percent / 100.0f, converge.low, converge.high);
  }
}

void mesh_settings(RadiosityState& r, RadiosityOptions& o) {
  const SliderRange size = slider_range(radiosity_table(), "patch-size");
  ImGui::DragFloat(tr("patch size (m)"), &o.patch_size, 0.002f, size.low, size.high, o.patch_size > 0.0f ? "%.3f" : tr("auto"));
  name_widget("patch size (m)");
  o.patch_size = std::clamp(o.patch_size, size.low, size.high);
  if (o.patch_size == 0.0f) dim_text(tr("auto: the scene's triangles and about %d patches more"), o.target_patches);
  const SliderRange elements = slider_range(radiosity_table(), "elements");
  ImGui::SliderInt(tr("elements per patch edge"), &o.elements_per_edge, int(elements.low), int(elements.high));
  name_widget("elements per patch edge");
  dim_text("%s", tr("patches shoot, their N x N elements receive (1 = every element shoots)"));
  bool adaptive = o.meshing == Meshing::adaptive;
  ImGui::Checkbox(tr("adaptive subdivision"), &adaptive);
  name_widget("adaptive subdivision");
  o.meshing = adaptive ? Meshing::adaptive : Meshing::uniform;
  if (adaptive) {
    const SliderRange threshold = slider_range(radiosity_table(), "refine-threshold");
    ImGui::SliderFloat(tr("cut threshold"), &o.refine_threshold, threshold.low, 1.0f, tr("%.3f x mean"),
                       ImGuiSliderFlags_Logarithmic);
    name_widget("cut threshold");
    const SliderRange levels = slider_range(radiosity_table(), "refine-levels");
    ImGui::SliderInt(tr("cuts at most"), &o.refine_levels, int(levels.low), 8);
    name_widget("cuts at most");
    dim_text("%s", tr("cut where the light is off linear"));
    dim_text("%s", trf("+{} elements, {} passes", r.status.refined_elements, r.status.refinement_passes).c_str());
  }
  // The powers of two in the table's range.
  const SliderRange res = slider_range(radiosity_table(), "hemicube");
  std::vector<int> sizes;
  for (int n = int(res.low); n <= int(res.high); n *= 2) sizes.push_back(n);
  const std::string preview = fmt::format("{}", o.hemicube_res);
  const bool choosing = ImGui::BeginCombo(tr("hemicube (px)"), preview.c_str());
  name_widget("hemicube (px)");
  if (choosing) {
    for (int n : sizes)
      if (ImGui::Selectable(fmt::format("{}", n).c_str(), n == o.hemicube_res)) o.hemicube_res = n;
    ImGui::EndCombo();
  }
  // A new mesh or hemicube is a new solve: only on request, so a drag does not restart it.
  const bool pending = r.status.remesh_pending;
  if (pending) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.7f, 0.45f, 0.1f, 1.0f));
  if (ImGui::Button(tr("remesh and restart"))) r.remesh = true;
  name_widget("remesh and restart");
  if (pending) ImGui::PopStyleColor();
  ImGui::SameLine();
  dim_text("%s", pending ? tr("to apply the new size") : tr("also applies kd, Le, light edits"));
  int method = int(o.form_factors);  // FormFactorMethod's order
  ImGui::RadioButton(tr("hemicube form factors"), &method, 0);
  name_widget("hemicube form factors");
  ImGui::RadioButton(tr("analytic near the shooter"), &method, 1);
  name_widget("analytic near the shooter");
  ImGui::RadioButton(tr("analytic, visibility by rays"), &method, 2);
  name_widget("analytic, visibility by rays");
  o.form_factors = FormFactorMethod(method);
  if (o.form_factors == FormFactorMethod::rays) {
    ImGui::SliderInt(tr("rays per element"), &o.visibility_rays, 1, 16);
    name_widget("rays per element");
  }
  const SliderRange overshoot = slider_range(radiosity_table(), "overshoot");
  ImGui::SliderFloat(tr("overshoot"), &o.overshoot, overshoot.low, overshoot.high, "x%.2f");
  name_widget("overshoot");
  ImGui::Checkbox(tr("turn the hemicube at random each shot"), &o.random_rotation);
  name_widget("turn the hemicube at random each shot");
  dim_text("%s", tr("(seeded: the same shots give the same picture)"));
}

// ---- [display] ---------------------------------------------------------------------------------
// The heat map's fixed scale: the ramp with its decades, in units of the mean emitted exitance.
void heat_map_legend() {
  dim_text("%s", tr("unshot exitance of a patch / the scene's mean emitted exitance (fixed scale):"));
  const float width = ImGui::GetContentRegionAvail().x, height = ImGui::GetTextLineHeight();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const int steps = 64;
  const double decades = std::log10(kHeatMapHighest / kHeatMapLowest);
  for (int i = 0; i < steps; ++i) {
    const double share = kHeatMapLowest * std::pow(10.0, decades * (i + 0.5) / steps);
    const Rgb c = heat_colour(share);
    draw->AddRectFilled(ImVec2(at.x + width * float(i) / steps, at.y), ImVec2(at.x + width * float(i + 1) / steps, at.y + height),
                        ImGui::ColorConvertFloat4ToU32(ImVec4(srgb_encode(c.r), srgb_encode(c.g), srgb_encode(c.b), 1.0f)));
  }
  ImGui::Dummy(ImVec2(width, height));
  // The decades' labels under the ramp, the first and last flush with its ends.
  const float y = ImGui::GetCursorScreenPos().y;
  for (int k = 0; k <= int(decades); ++k) {
    const std::string label = fmt::format("{:g}", kHeatMapLowest * std::pow(10.0, k));
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    ImGui::SetCursorScreenPos(ImVec2(at.x + std::clamp(width * float(k) / float(decades) - 0.5f * w, 0.0f, width - w), y));
    ImGui::TextUnformatted(label.c_str());
  }
  dim_text("%s", tr("black: nothing left to shoot"));
}

void display_settings(RadiosityState& r, RadiosityOptions& o, bool& textures) {
  RadiosityDrive& d = r.drive;
  int flat = o.flat_patches ? 1 : 0;
  ImGui::RadioButton(tr("Gouraud (vertex B/π)"), &flat, 0);
  name_widget("Gouraud (vertex B/π)");
  ImGui::SameLine();
  ImGui::RadioButton(tr("flat patches"), &flat, 1);
  name_widget("flat patches");
  o.flat_patches = flat == 1;
  ImGui::Checkbox(tr("patch outlines"), &o.outlines);
  name_widget("patch outlines");
  ImGui::SameLine();
  ImGui::TextDisabled("%s", tr("[L]: flat + outlines"));
  ImGui::Checkbox(tr("kd texture [T]"), &textures);
  name_widget("kd texture [T]");
  ImGui::SameLine();
  ImGui::TextDisabled("%s", tr("(ρ: the solution starts over)"));
  ImGui::Checkbox(tr("ambient estimate ρ·ambient  [Shift+A]"), &o.ambient_estimate);
  name_widget("ambient estimate ρ·ambient  [Shift+A]");
  ImGui::Checkbox(tr("heat map of unshot power  [U]"), &d.heat_map);
  name_widget("heat map of unshot power  [U]");
  if (d.heat_map) heat_map_legend();
  ImGui::PushStyleColor(ImGuiCol_CheckMark, shooter_colour);
  ImGui::Checkbox(tr("the shooter in magenta"), &d.show_shooter);
  name_widget("the shooter in magenta");
  ImGui::PopStyleColor();
  ImGui::Checkbox(tr("its hemicube's item buffer (window)"), &d.show_item_buffer);
  name_widget("its hemicube's item buffer (window)");
}

}  // namespace

// ---- [the section] -----------------------------------------------------------------------------
void radiosity_section(ViewerServices& viewer, RadiosityState& r) {
  ViewerState& state = viewer.state();
  RadiosityOptions& o = state.radiosity;
  dim_text("%s", tr("progressive refinement, slide 39; B/π drawn (slide 39 step 3)"));
  ImGui::TextWrapped("%s", tr("shoot i:  ΔB_j = ρ_j · F_ji · unshot_i,   F_ji = F_ij · A_i / A_j"));
  ImGui::Spacing();
  loop_controls(r);
  unshot_plot(r, o);
  if (ImGui::TreeNodeEx(tr("shooting, stopping, mesh"), ImGuiTreeNodeFlags_DefaultOpen)) {
    drive_settings(r, o);
    mesh_settings(r, o);
    ImGui::TreePop();
  }
  if (ImGui::TreeNodeEx(tr("display"), ImGuiTreeNodeFlags_DefaultOpen)) {
    display_settings(r, o, state.local.terms.textures);
    ImGui::TreePop();
  }
  // Slide 36 beside slide 39: why shooting shows a usable picture first.
  if (ImGui::Button(tr("slide 36: the system solved four ways  [J]"))) viewer.run_line("solvers toggle");
  name_widget("slide 36: the system solved four ways  [J]");
}

// ---- [the item-buffer window] ------------------------------------------------------------------
void draw_item_buffer_window(RadiosityState& r, const RadiosityOptions& options, float side) {
  r.status.item_view_min = r.status.item_view_max = glm::vec2(0.0f);
  if (!r.drive.show_item_buffer) return;
  ImGui::SetNextWindowBgAlpha(0.85f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                                 ImGuiWindowFlags_NoCollapse;
  ImGui::Begin(tr("item buffer (hemicube)"), &r.drive.show_item_buffer, flags);
  const RadiosityStatus& s = r.status;
  if (s.item_view_texture != 0) {
    ImGui::TextColored(shooter_colour, "%s", s.item_view_shooter.c_str());
    // The cross's texture is drawn bottom-up by GL: flip v so its top face's +b is up.
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(s.item_view_texture)), ImVec2(side, side),
                 ImVec2(0.0f, 1.0f), ImVec2(1.0f, 0.0f));
    r.status.item_view_min = glm::vec2(ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y);
    r.status.item_view_max = glm::vec2(ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y);
    dim_text("%s", tr("top face, 4 half faces folded out; a colour per patch"));
    dim_text("%s", tr("black: no patch (an open side) or a patch's back"));
    if (options.form_factors == FormFactorMethod::rays)
      dim_text("%s", tr("(form factors by rays: this hemicube is drawn for the window only)"));
  } else if (s.last_shooter < -1 || (s.last_shooter == -1 && s.shots > 0)) {
    ImGui::TextUnformatted(s.shooter.c_str());
    dim_text("%s", tr("a point light: shot through a cube of 6 item buffers"));
  } else {
    dim_text("%s", tr("no patch has shot yet"));
    ImGui::Dummy(ImVec2(side, 0.0f));
  }
  ImGui::End();
}

// ---- [the heat map's legend] ------------------------------------------------------------------
void draw_heat_map_legend_window(float width) {
  ImGui::SetNextWindowBgAlpha(0.85f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize;
  ImGui::SetNextWindowContentSize(ImVec2(width, 0.0f));
  if (ImGui::Begin(tr("heat map: the unshot power"), nullptr, flags)) {
    ImGui::PushTextWrapPos(0.0f);
    heat_map_legend();
    ImGui::TextWrapped("%s", tr("Each patch shoots what it holds and keeps none: as the energy spreads and is absorbed, the map cools from yellow to red, blue and black."));
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

}  // namespace luz::app
