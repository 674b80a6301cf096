#include "app/models/hybrid/hybrid_view.h"

#include <fmt/format.h>
#include <imgui.h>

#include "app/common/i18n.h"
#include "app/viewer/panel.h"
#include "app/models/whitted/render_whitted.h"

namespace luz::app {

HybridView::HybridView(ViewerServices& viewer, RadiosityView& radiosity)
    : TracedView(viewer), radiosity_(radiosity) {
  // The radiosity solution goes (a remesh, an edited Le): first the trace that reads it (a trace
  // still ending keeps the diffuse part it reads).
  radiosity_.on_drop([this] {
    cancel_trace();
    set_diffuse_source(nullptr);
    diffuse_.reset();
  });
  radiosity_.shown_through(*this);
}

HybridView::~HybridView() { cancel_trace(); }

void HybridView::hidden() {
  TracedView::hidden();
  radiosity_.hidden();
}

void HybridView::scene_changed() {
  TracedView::scene_changed();
  diffuse_.reset();
}

// The radiosity picture, stepping as in model 5 (the first time, meshed and run to the stopping
// rule: "computed first when there is none"). It shows B/pi as the trace will read it, so model
// 5's heat map and shooter highlight are left out here.
void HybridView::draw_untraced(const Camera& camera, const Viewport& viewport, gl::Framebuffer& picture) {
  RadiosityState& r = radiosity_.state();
  const bool first = radiosity_.solution() == nullptr;
  const bool solved = radiosity_.step_and_draw(camera, viewport, picture, {.heat_map = false, .shooter = false});
  if (first && solved && !radiosity_.solution()->solver().done()) r.drive.running = true;
}

// The hybrid traces over the viewer's radiosity solution: while the solver is still running to
// its stopping rule (the first solve, or a run asked for), the trace waits for it. The diffuse
// part takes the solution as it is now, only while no trace runs or ends (one reads it): a trace
// asked for while a cancelled one ends waits for its end.
std::optional<rt::WhittedOptions> HybridView::options_for_trace(std::string& why) {
  const RadiositySession* solution = radiosity_.solution();
  if (!solution) {
    why = tr("hybrid: no radiosity solution yet to trace with");
    return std::nullopt;
  }
  if (radiosity_.state().drive.running) return std::nullopt;  // the hint says it waits
  if (!tracer_idle()) {
    // A trace running reads the diffuse part as it is, and a click's ray tree traces with it too;
    // one ending after a cancel is waited for, so that the next trace takes the solution as it is.
    if (tracing() && diffuse_) return current_options();
    return std::nullopt;
  }
  if (diffuse_) diffuse_->update(RadianceField::of(solution->solver()));
  else diffuse_ = std::make_shared<hybrid::RadiosityDiffuse>(solution->mesh(), RadianceField::of(solution->solver()));
  set_diffuse_source(diffuse_);
  return current_options();
}

rt::WhittedOptions HybridView::current_options() const {
  const ViewerState& state = viewer_.state();
  return tracer_options(state.whitted, state.local);
}

std::string HybridView::hint() const {
  const RadiosityState& r = radiosity_.state();
  if (requests.trace)
    // xgettext:no-c-format (a fmt string, where "% u" is not a printf directive)
    return trf("hybrid: solving radiosity first (shot {}, {:.2f} % unshot); the trace starts when it stops",
                       r.status.shots, 100.0 * r.status.unshot_fraction);
  return tr("hybrid: the radiosity picture. Press Enter / click Render to trace its highlights");
}

std::string HybridView::status() const {
  std::string s = TracedView::status();
  if (progress().phase == TracePhase::raster) {
    const std::string solver = radiosity_.status();
    if (!solver.empty()) s += " " + solver;
  }
  return s;
}

void HybridView::panel() {
  ViewerState& state = viewer_.state();
  dim_text("%s", tr("radiosity's diffuse light + ray-traced highlights (slides 41-43)"));  // wrapped
  ImGui::TextWrapped("%s", tr("I = B/π + Σᵢ Sᵢ ILᵢ·ks·cosⁿ α + kr·Ir + kt·It"));
  // Which radiosity solution the trace reads: model 5's, as it left it.
  const RadiosityStatus& r = radiosity_.state().status;
  if (!r.built) dim_text("%s", tr("radiosity: not solved yet (solved to the stopping rule first)"));
  else
    ImGui::TextWrapped(tr("radiosity: %zu patches, %d shots, %.2f %% unshot%s"), r.patches, r.shots, 100.0 * r.unshot_fraction,
                       radiosity_.state().drive.running ? tr(", running") : r.done ? tr(", done") : tr(", paused"));
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("%s", tr("model 5 [5] steps, resets and remeshes it; a trace reads it as it is"));
  ImGui::PopStyleColor();
  traced_section(state, *this);
}

}  // namespace luz::app
