// Sections: [methods] [stepping] [the plots] [the window] [json]
#include "app/viewer/solvers_window.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>
#include <imgui.h>

#include "app/common/i18n.h"
#include "app/viewer/overlays.h"
#include "app/cli/solvers_command.h"
#include "core/error.h"

namespace luz::app {

namespace {

// The PNG's colours are for a white page; on ImGui's dark panel they are lifted a third of the
// way to white so the blue and the red still read.
ImU32 on_dark(Method method) {
  const Rgb c = method_colour(method);
  auto lift = [](float v) { return int(std::lround(255.0f * (v + (1.0f - v) / 3.0f))); };
  return IM_COL32(lift(c.r), lift(c.g), lift(c.b), 255);
}

size_t rows_used(const SolverComparison& race, Method m) { return race.curve(m).back().rows; }

size_t fewest_rows(const SolverComparison& race) {
  size_t fewest = SIZE_MAX;
  for (const Method m : kMethods) fewest = std::min(fewest, race.done(m) ? race.max_rows() : rows_used(race, m));
  return fewest;
}

bool all_done(const SolverComparison& race) {
  return std::all_of(kMethods.begin(), kMethods.end(), [&race](Method m) { return race.done(m); });
}

}  // namespace

// ---- [stepping] --------------------------------------------------------------------------------
void SolversWindow::scene_changed(const Scene& scene) {
  race_.reset();
  mesh_.reset();
  scene_ = &scene;
  state_.status = {};
  state_.running = false;
  state_.run_to_rows = 0;
}

bool SolversWindow::busy() const {
  return state_.run_to_rows > 0 || state_.reset || state_.status.phase == SolversState::Phase::building;
}

bool SolversWindow::working() const { return state_.running || busy(); }

void SolversWindow::build() {
  SolversState& state = state_;
  race_.reset();  // the old comparison's GL objects go before the new ones are made
  mesh_.reset();
  SolversState::Status& s = state.status;
  // The hemicube and everything else as `luz solvers` has them, so the window and the command
  // solve the same system for the same settings.
  RadiosityOptions options;
  options.hemicube_res = SolversSettings{}.hemicube_res;
  options.target_patches = state.target_patches;
  options.elements_per_edge = 1;  // the matrix methods solve on the patches themselves
  auto mesh = std::make_unique<PatchMesh>(PatchMesh::build(*scene_, options));
  s.patches = mesh->size();
  if (mesh->size() > kMaxSolverPatches) {
    s.phase = SolversState::Phase::refused;
    s.message = trf("{} patches: the full form-factor matrix grows as the square of that, so this "
                            "window takes at most {}. Ask for fewer patches.", mesh->size(), kMaxSolverPatches);
    return;
  }
  try {
    mesh_ = std::move(mesh);
    race_ = std::make_unique<SolverComparison>(*scene_, *mesh_, options, size_t(state.sweeps) * mesh_->size());
  } catch (const Error& error) {
    race_.reset();
    mesh_.reset();
    s.phase = SolversState::Phase::refused;
    s.message = error.what();
    return;
  }
  s.phase = SolversState::Phase::ready;
  s.message.clear();
  s.max_rows = race_->max_rows();
  s.matrix_seconds = race_->matrix_seconds();
}

void SolversWindow::advance() {
  SolversState& state = state_;
  SolversState::Status& s = state.status;
  s.plot_min = s.plot_max = glm::vec2(0.0f);  // until this frame's draw() draws them
  if (!state.open && state.run_to_rows == 0 && !state.reset) return;
  if (state.reset) {
    state.reset = false;
    state.running = false;
    race_.reset();
    mesh_.reset();
    s = {};
  }
  if (!state.open && state.run_to_rows == 0) return;
  if (s.phase == SolversState::Phase::none) {
    // One frame that says what is coming: the N hemicubes of the matrix take a while.
    s.phase = SolversState::Phase::building;
    s.message = trf("building the form-factor matrix (one hemicube per patch, about {} patches) "
                            "and B* ...", state.target_patches);
    return;
  }
  if (s.phase == SolversState::Phase::building) build();
  if (!race_) {
    state.running = false;
    state.run_to_rows = 0;
    return;
  }

  // The four curves advance together (step() takes the method behind).
  if ((state.running || state.run_to_rows > 0) && !step_for(state.budget_ms)) {
    state.run_to_rows = 0;
    state.running = false;
  }
  s.rows = fewest_rows(*race_);
  s.done = all_done(*race_);
}

bool SolversWindow::step_for(float ms) {
  using clock = std::chrono::steady_clock;
  const auto until = clock::now() + std::chrono::duration<double, std::milli>(std::max(ms, 0.0f));
  for (;;) {
    if (state_.run_to_rows > 0 && fewest_rows(*race_) >= state_.run_to_rows) return false;
    if (!race_->step()) return false;
    if (clock::now() >= until) return true;
  }
}

bool SolversWindow::paced() const {
  const SolversState& s = state_;
  const bool stepping = s.running || s.run_to_rows > 0;
  return race_ && stepping && !s.budget_chosen && !s.reset && (s.open || s.run_to_rows > 0) &&
         !all_done(*race_) && (s.run_to_rows == 0 || fewest_rows(*race_) < s.run_to_rows);
}

void SolversWindow::step_between_frames() {
  if (!paced()) return;
  step_for(state_.budget_ms);
}

// ---- [the plots] -------------------------------------------------------------------------------
namespace {

// One log-log plot under its title: a value of every method's curve against the form-factor rows
// used, from 1 row to max_rows, a faint line at every decade of both axes.
void log_plot(const SolverComparison& race, bool residual, ImVec2 size, glm::vec2& min, glm::vec2& max) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float font = ImGui::GetFontSize();
  const ImVec2 a(origin.x + 3.2f * font, origin.y + 1.4f * font);  // room for the title and the y labels
  const ImVec2 b(origin.x + size.x - 0.5f * font, origin.y + size.y - 1.3f * font);  // and the x labels
  draw->AddRectFilled(a, b, IM_COL32(20, 20, 24, 255));
  draw->AddRect(a, b, IM_COL32(110, 110, 120, 255));
  min = glm::vec2(a.x, a.y);
  max = glm::vec2(b.x, b.y);

  const double x_top = std::log10(double(std::max<size_t>(race.max_rows(), 10)));
  double smallest = 1.0;
  for (const Method m : kMethods)
    for (const SolverSample& s : race.curve(m)) smallest = std::min(smallest, residual ? s.residual : s.error);
  const double y_low = std::max(std::floor(std::log10(std::max(smallest, 1e-12))), -12.0), y_high = std::log10(2.0);
  auto at = [&](double rows, double value) {
    const double x = std::log10(std::max(rows, 1.0)) / x_top;
    const double y = (std::log10(std::max(value, 1e-12)) - y_low) / (y_high - y_low);
    return ImVec2(a.x + float(x) * (b.x - a.x), b.y - float(std::clamp(y, 0.0, 1.0)) * (b.y - a.y));
  };
  const ImU32 grid = IM_COL32(70, 70, 80, 255), label = IM_COL32(170, 170, 180, 255);
  for (int d = 0; d <= int(x_top); ++d) {
    const ImVec2 p = at(std::pow(10.0, d), 1.0);
    draw->AddLine(ImVec2(p.x, a.y), ImVec2(p.x, b.y), grid);
    const std::string text = d == 0 ? "1" : fmt::format("1e{}", d);
    draw->AddText(ImVec2(p.x - 0.3f * font, b.y + 0.1f * font), label, text.c_str());
  }
  const int step = y_high - y_low > 8 ? 2 : 1;
  for (int d = int(y_low); d <= 0; d += step) {
    const ImVec2 p = at(1.0, std::pow(10.0, d));
    draw->AddLine(ImVec2(a.x, p.y), ImVec2(b.x, p.y), grid);
    const std::string text = d == 0 ? "1" : fmt::format("1e{}", d);
    draw->AddText(ImVec2(origin.x, p.y - 0.5f * font), label, text.c_str());
  }
  draw->PushClipRect(a, b, true);
  for (const Method m : kMethods) {
    // A staircase, as `luz solvers` draws it: a method's value holds until its next iteration
    // ends, so a Jacobi sweep shows as nothing changing for N rows, then a drop.
    std::vector<ImVec2> points;
    for (const SolverSample& s : race.curve(m)) {
      const ImVec2 q = at(double(s.rows), residual ? s.residual : s.error);
      if (!points.empty()) points.push_back(ImVec2(q.x, points.back().y));
      points.push_back(q);
    }
    if (points.size() == 1) draw->AddCircleFilled(points[0], 2.5f, on_dark(m));
    else draw->AddPolyline(points.data(), int(points.size()), on_dark(m), 0, 2.0f);
  }
  draw->PopClipRect();
  const char* title = residual ? tr("residual |E - (I - ρF) B| / |E|") : tr("error |B - B*| / |B*|");
  draw->AddText(ImVec2(a.x, origin.y), label, title);
  ImGui::Dummy(size);
}

}  // namespace

// ---- [the window] ------------------------------------------------------------------------------
void SolversWindow::draw(float x, float y, float width, float height, bool pinned) {
  SolversState& state = state_;
  SolversState::Status& s = state.status;
  if (!state.open || !scene_) return;
  const ImGuiCond when = pinned ? ImGuiCond_Always : ImGuiCond_Appearing;
  ImGui::SetNextWindowPos(ImVec2(x, y), when);
  ImGui::SetNextWindowSize(ImVec2(width, height), when);
  // Sideways scrolling rather than a cut: the legend's columns keep the width of their text.
  if (!ImGui::Begin(tr("Slide 36: the system solved four ways  [J]"), &state.open,
                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_HorizontalScrollbar)) {
    ImGui::End();
    return;
  }
  ImGui::TextUnformatted("(I - ρF) B = E:   B_i = E_i + ρ_i Σ_j F_ij B_j");
  if (s.phase == SolversState::Phase::refused) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.4f, 1.0f), "%s", s.message.c_str());
    ImGui::PopTextWrapPos();
  }
  if (s.phase == SolversState::Phase::building) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(s.message.c_str());
    ImGui::PopTextWrapPos();
  }
  if (ImGui::Button(state.running ? tr("pause") : tr("run"), ImVec2(6.0f * ImGui::GetFontSize(), 0.0f)))
    state.running = !state.running;
  ImGui::SameLine();
  if (ImGui::Button(tr("reset"))) state.reset = true;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(6.0f * ImGui::GetFontSize());
  if (ImGui::InputInt(tr("patches (reset)"), &state.target_patches, 100, 400)) state.target_patches = std::max(state.target_patches, 10);

  if (race_) {
    ImGui::Text(tr("%zu patches, matrix in %.2f s; rows %zu / %zu%s"), s.patches, s.matrix_seconds, s.rows, s.max_rows,
                s.done ? tr(" (done)") : "");
    // The legend, with where each method has got: a table, so it fits half the picture.
    if (ImGui::BeginTable("legend", 4, kTextWideTable, ImVec2(0.0f, text_wide_table_height(1 + int(std::size(kMethods)))))) {
      for (const char* heading : {"", tr("rows"), tr("residual"), tr("error")}) ImGui::TableSetupColumn(heading);
      ImGui::TableHeadersRow();
      for (const Method m : kMethods) {
        const SolverSample& last = race_->curve(m).back();
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(on_dark(m)), "%s", method_label(m));
        ImGui::TableNextColumn();
        ImGui::Text("%zu", last.rows);
        ImGui::TableNextColumn();
        ImGui::Text("%.1e", last.residual);
        ImGui::TableNextColumn();
        ImGui::Text("%.1e", last.error);
      }
      ImGui::EndTable();
    }
    // The two plots share what is left of the window, the axes' line and the caption's three
    // lines kept below.
    const ImVec2 room = ImGui::GetContentRegionAvail();
    const float lines = 4.5f * ImGui::GetTextLineHeightWithSpacing();
    const ImVec2 size(room.x, std::max(0.5f * (room.y - lines), 8.0f * ImGui::GetFontSize()));
    glm::vec2 min0, max0, min1, max1;
    log_plot(*race_, true, size, min0, max0);
    log_plot(*race_, false, size, min1, max1);
    s.plot_min = glm::min(min0, min1);
    s.plot_max = glm::max(max0, max1);
    ImGui::TextDisabled("%s", tr("x: form-factor rows used (log), y: log"));
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(tr("Shooting is useful after a few rows; Jacobi / Gauss-Seidel only after full sweeps "
                              "(N rows each, and none before the whole matrix is known)."));
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

// ---- [json] ------------------------------------------------------------------------------------
nlohmann::json to_json(const SolversWindow& window) {
  const SolversState& state = window.state();
  const SolversState::Status& s = state.status;
  nlohmann::json j;
  const char* phases[] = {"none", "building", "ready", "refused"};
  j["phase"] = phases[int(s.phase)];
  j["message"] = s.message;
  j["running"] = state.running;
  j["patches"] = s.patches;
  j["max_rows"] = s.max_rows;
  j["rows"] = s.rows;
  j["done"] = s.done;
  j["plot"] = {s.plot_min.x, s.plot_min.y, s.plot_max.x, s.plot_max.y};
  j["curves"] = nlohmann::json::object();
  if (const SolverComparison* race = window.comparison())
    for (const Method m : kMethods) {
      nlohmann::json curve = nlohmann::json::array();
      for (const SolverSample& p : race->curve(m))
        curve.push_back({{"iteration", p.iteration}, {"rows", p.rows}, {"seconds", p.seconds},
                         {"residual", p.residual}, {"error", p.error}});
      j["curves"][to_string(m)] = std::move(curve);
    }
  return j;
}

}  // namespace luz::app
