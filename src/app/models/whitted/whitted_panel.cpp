// The panel's Whitted section (model 4): the formula with its rays, the Render button, progress
// and counters, the tracer's switches (the rt::WhittedOptions `luz render --model whitted` fills),
// and the clicked pixel's ray tree (slide 24) as an indented list. The hybrid's section (model 6)
// is the same with radiosity's state on top: the same tracer renders it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <imgui.h>

#include "app/common/i18n.h"
#include "app/common/options_tables.h"
#include "app/viewer/panel.h"
#include "app/models/whitted/traced_view.h"
#include "app/models/whitted/ray_tree_drawing.h"
#include "core/image.h"

namespace luz::app {
namespace {

ImVec4 colour_of(rt::RayKind kind, bool blocked = false) {
  const glm::vec3 c = ray_colour(kind, blocked);
  return ImVec4(c.r, c.g, c.b, 1.0f);
}

// The ray kinds of slide 24, in the current language.
const char* kind_label(rt::RayKind kind) {
  switch (kind) {
    case rt::RayKind::primary: return tr("primary");
    case rt::RayKind::shadow: return tr("shadow");
    case rt::RayKind::reflected: return tr("reflected");
    case rt::RayKind::transmitted: return tr("transmitted");
  }
  return "?";
}

void progress_and_counters(TracedView& view) {
  const TraceProgress& t = view.progress();
  if (t.phase == TracePhase::tracing) {
    if (ImGui::Button(tr("cancel  [Backspace]"))) view.requests.cancel = true;
    name_widget("cancel  [Backspace]");
  } else {
    const char* render = t.phase == TracePhase::done ? N_("render again  [Enter]") : N_("Render this view  [Enter]");
    if (ImGui::Button(tr(render))) view.requests.trace = true;
    name_widget(render);
  }
  const char* untraced = view.hybrid() ? tr("radiosity") : tr("raster (Phong)");
  const float fraction = t.total > 0 ? float(t.done) / float(t.total) : 0.0f;
  const std::string label = t.phase == TracePhase::raster
                                ? (t.cancelled ? trf("cancelled at {}/{} tiles: {} view", t.done, t.total, untraced)
                                               : trf("{} view: not traced", untraced))
                                : trf("{}/{} tiles  {:.2f} s", t.done, t.total, t.seconds);
  ImGui::ProgressBar(t.phase == TracePhase::raster && !t.cancelled ? 0.0f : fraction, ImVec2(-1.0f, 0.0f),
                     label.c_str());
  if (t.phase != TracePhase::done) return;
  const rt::Counters& c = t.counters;
  // Two columns by hand: what, then its value at a fixed indent.
  const float column = 12.0f * ImGui::GetFontSize();
  auto row = [column](const ImVec4& colour, const std::string& what, const std::string& value) {
    ImGui::TextColored(colour, "%s", what.c_str());
    ImGui::SameLine(column);
    ImGui::TextWrapped("%s", value.c_str());
  };
  for (int k = 0; k < rt::kRayKinds; ++k)
    row(colour_of(rt::RayKind(k)), trf("{} rays", kind_label(rt::RayKind(k))),
        fmt::format("{}", c.rays[size_t(k)]));
  const ImVec4 plain = ImGui::GetStyle().Colors[ImGuiCol_Text];
  row(plain, tr("ray-triangle tests"),
      c.intersection_tests > 0 ? fmt::format("{}", c.intersection_tests) : std::string(tr("not counted (Embree)")));
  row(plain, tr("time"), fmt::format("{:.3f} s", c.seconds));
  row(plain, tr("rays per second"), fmt::format("{:.2f} M", c.rays_per_second() / 1e6));
}

void options(ViewerState& state, bool hybrid) {
  rt::WhittedOptions& o = state.whitted;
  const SliderRange depth = slider_range(whitted_table(), "depth");
  ImGui::SliderInt(tr("max depth"), &o.max_depth, int(depth.low), int(depth.high));
  name_widget("max depth");
  dim_text("%s", tr("primary ray: depth 1; a hit at depth d spawns R and T while d < max"));
  bool adaptive = o.sampling == rt::Sampling::adaptive;
  ImGui::BeginDisabled(adaptive);
  const int max_root = int(std::lround(std::sqrt(slider_range(whitted_table(), "spp").high)));
  int root = std::clamp(int(std::lround(std::sqrt(float(std::max(o.spp, 1))))), 1, max_root);
  const std::string spp = trf("{} ({}x{} jittered)", root * root, root, root);
  if (ImGui::SliderInt(tr("samples / pixel"), &root, 1, max_root, spp.c_str(), ImGuiSliderFlags_Logarithmic))
    o.spp = root * root;  // squares only
  name_widget("samples / pixel");
  ImGui::EndDisabled();
  if (ImGui::Checkbox(tr("adaptive supersampling (Whitted)"), &adaptive))
    o.sampling = adaptive ? rt::Sampling::adaptive : rt::Sampling::stratified;
  name_widget("adaptive supersampling (Whitted)");
  if (adaptive) {
    const SliderRange levels = slider_range(whitted_table(), "adaptive-levels"), threshold = slider_range(whitted_table(), "adaptive-threshold");
    ImGui::SliderInt(tr("levels"), &o.adaptive_levels, int(levels.low), int(levels.high));
    name_widget("levels");
    ImGui::DragFloat(tr("threshold (sRGB)"), &o.adaptive_threshold, 0.002f, threshold.low, threshold.high, "%.3f");
    name_widget("threshold (sRGB)");
  }
  ImGui::Checkbox(tr("Fresnel: kr + kt·F, kt·(1 - F)"), &o.fresnel);
  name_widget("Fresnel: kr + kt·F, kt·(1 - F)");
  ImGui::Checkbox(tr("shadow rays S_i"), &o.shadows);
  name_widget("shadow rays S_i");
  const SliderRange samples = slider_range(whitted_table(), "light-samples");
  ImGui::SliderInt(tr("samples per emitter"), &o.light_samples, int(samples.low), int(samples.high), "%d",
                   ImGuiSliderFlags_Logarithmic);
  name_widget("samples per emitter");
  dim_text("%s", tr("1: its centroid; N: N-rooks over its area (soft shadows)"));
  ImGui::Checkbox(tr("brute force (every triangle, counted)"), &o.brute_force);
  name_widget("brute force (every triangle, counted)");
  // The same picture either way (wavefront.h); the trace time tells them apart.
  bool wavefront = o.renderer == rt::RendererKind::wavefront;
  if (ImGui::Checkbox(tr("wavefront (rays by generation, as streams)"), &wavefront))
    o.renderer = wavefront ? rt::RendererKind::wavefront : rt::RendererKind::recursive;
  name_widget("wavefront (rays by generation, as streams)");
  // The local part's terms: the same switches (and keys) as the local models'. In the hybrid,
  // radiosity's B/pi holds the ambient light and Le, and [D] switches it off.
  TermSwitches& l = state.local.terms;
  if (hybrid) {
    ImGui::Checkbox("B/π [D]", &l.diffuse);
    name_widget("B/π [D]");
    ImGui::SameLine();
    ImGui::Checkbox("ks [S]", &l.specular);
    name_widget("ks [S]");
  } else {
    ImGui::Checkbox("Ia·ka [A]", &l.ambient);
    name_widget("Ia·ka [A]");
    ImGui::SameLine();
    ImGui::Checkbox("kd [D]", &l.diffuse);
    name_widget("kd [D]");
    ImGui::SameLine();
    ImGui::Checkbox("ks [S]", &l.specular);
    name_widget("ks [S]");
    ImGui::SameLine();
    ImGui::Checkbox("Le [E]", &l.emission);
    name_widget("Le [E]");
  }
  ImGui::Checkbox(tr("kd texture [T]"), &l.textures);
  name_widget("kd texture [T]");
  ImGui::SameLine();
  ImGui::Checkbox(tr("Blinn N·H [B]"), &l.blinn);
  name_widget("Blinn N·H [B]");
}

// One node and, indented under it, the rays its hit spawned.
std::string rgb(const Rgb& c) { return fmt::format("{:.3f} {:.3f} {:.3f}", c.r, c.g, c.b); }

// A radiance as a swatch, encoded for the screen as the picture is (2^exposure, sRGB), its
// numbers in the tooltip.
void swatch(const char* id, const Rgb& radiance, float exposure) {
  const float scale = std::exp2(exposure);
  const ImVec4 shown(srgb_encode(radiance.r * scale), srgb_encode(radiance.g * scale), srgb_encode(radiance.b * scale), 1.0f);
  const float side = ImGui::GetTextLineHeight();
  ImGui::ColorButton(id, shown, ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop, ImVec2(2.0f * side, side));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", rgb(radiance).c_str());
}

void node_row(const rt::RayTree& tree, const std::vector<std::vector<int>>& children, int id, float exposure) {
  const rt::RayTreeNode& n = tree.nodes[size_t(id)];
  const bool shadow = n.kind == rt::RayKind::shadow;
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_SpanFullWidth;
  if (children[size_t(id)].empty()) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
  ImGui::PushStyleColor(ImGuiCol_Text, colour_of(n.kind, shadow && n.hit));
  const bool open = ImGui::TreeNodeEx(reinterpret_cast<void*>(intptr_t(id)), flags, "%s", kind_label(n.kind));
  ImGui::PopStyleColor();
  ImGui::TableNextColumn();
  ImGui::Text("%d", n.depth);
  ImGui::TableNextColumn();
  if (shadow) ImGui::Text(tr("light %d: %s"), n.light, n.hit ? tr("blocked") : tr("lit"));
  else if (n.hit) ImGui::TextUnformatted(n.mesh.c_str());
  else dim_text("%s", tr("background"));
  if (ImGui::IsItemHovered())  // the hit cell: the ray itself
    ImGui::SetTooltip(tr("origin %.3f %.3f %.3f\ndirection %.3f %.3f %.3f\nt %.4g (%s)\nweight %s\nradiance %s"),
                      n.origin.x, n.origin.y, n.origin.z, n.direction.x, n.direction.y, n.direction.z, n.t,
                      n.material.c_str(), rgb(n.weight).c_str(), rgb(n.radiance).c_str());
  ImGui::TableNextColumn();
  if (!shadow && n.hit) swatch("local", n.local, exposure);
  ImGui::TableNextColumn();
  swatch("contribution", n.contribution, exposure);
  if (open && !children[size_t(id)].empty()) {
    for (int child : children[size_t(id)]) node_row(tree, children, child, exposure);
    ImGui::TreePop();
  }
}

void ray_tree(ViewerState& state, TracedView& view) {
  if (!ImGui::TreeNodeEx(tr("ray tree (slide 24)"), ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (!view.ray_tree()) {
    dim_text("%s", tr("click a pixel: its rays are drawn over the scene"));
    ImGui::TreePop();
    return;
  }
  const rt::RayTree& tree = *view.ray_tree();
  ImGui::Text(tr("pixel (%d, %d): %zu rays, L = %s"), tree.x, tree.y, tree.nodes.size(), rgb(tree.pixel).c_str());
  if (ImGui::SmallButton(tr("clear [X]"))) view.requests.clear_tree = true;
  name_widget("clear [X]");
  std::vector<std::vector<int>> children(tree.nodes.size());
  for (const rt::RayTreeNode& n : tree.nodes)
    if (n.parent >= 0) children[size_t(n.parent)].push_back(n.id);
  // Each column as wide as its text (the tree's indentation included): a panel narrower than
  // the table scrolls it sideways rather than cutting "light 0: blocked".
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_ScrollX |
                                ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
  const float height = ImGui::GetTextLineHeightWithSpacing() * float(std::min<size_t>(tree.nodes.size() + 1, 14)) +
                       ImGui::GetStyle().ScrollbarSize;
  // A narrower indent than the panel's: a tree of depth 5 still shows its kinds.
  ImGui::PushStyleVar(ImGuiStyleVar_IndentSpacing, 0.6f * ImGui::GetFontSize());
  if (ImGui::BeginTable("ray tree", 5, flags, ImVec2(0.0f, height))) {
    ImGui::TableSetupScrollFreeze(0, 1);
    for (const char* heading : {tr("ray"), "d", tr("hit"), tr("local"), tr("share")}) ImGui::TableSetupColumn(heading);
    ImGui::TableHeadersRow();
    for (const rt::RayTreeNode& n : tree.nodes)
      if (n.parent < 0) node_row(tree, children, n.id, state.exposure);
    ImGui::EndTable();
  }
  ImGui::PopStyleVar();
  dim_text("%s", view.hybrid() ? tr("local: B/π + Σ Sᵢ ILᵢ·ks·cosⁿ α at the hit")
                               : tr("local: Ia·ka + Σ Sᵢ ILᵢ[...] + Le at the hit"));
  dim_text("%s", tr("share: its contribution to L (hover for numbers)"));
  ImGui::TreePop();
}

}  // namespace

// What Whitted's and the hybrid's sections share: the trace's progress and counters, the ray
// tree of the clicked pixel, and the tracer's switches.
void traced_section(ViewerState& state, TracedView& view) {
  ImGui::Spacing();
  progress_and_counters(view);
  ImGui::Spacing();
  ray_tree(state, view);
  if (ImGui::TreeNodeEx(tr("tracer switches"), ImGuiTreeNodeFlags_DefaultOpen)) {
    options(state, view.hybrid());
    ImGui::TreePop();
  }
}

}  // namespace luz::app
