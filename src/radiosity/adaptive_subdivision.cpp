// Adaptive subdivision inside progressive radiosity (slide 40, "Mallado"; Cohen, Greenberg,
// Immel & Brock 1986): find the elements too coarse for the light on them, cut them
// (mesh_bisection.h), and let the new elements gather what has been shot. See shooting.h.
#include <algorithm>
#include <iterator>
#include <numeric>

#include <fmt/format.h>

#include "core/i18n.h"
#include "core/parallel_for.h"
#include "radiosity/mesh_bisection.h"
#include "radiosity/shooting.h"

namespace luz {
namespace {

double mean(const Rgb& c) { return (double(c.r) + double(c.g) + double(c.b)) / 3.0; }

// The rays of a gather draw their points from a stream no shot uses.
constexpr uint32_t kGatherShot = 0xffffff;
// The most elements one cut makes, with the cuts conformity chains to it: the element and the one
// across its longest edge give two, and a chain, whose edges grow along it, rarely more than a
// few more; the budget keeps this margin so that no cut passes it.
constexpr double kElementsPerCut = 16.0;

bool emits(const Patch& p) { return mean(p.emission) > 0.0; }

}  // namespace

RayFormFactors& ProgressiveSolver::rays() {
  if (!rays_) rays_ = std::make_unique<RayFormFactors>(scene_, mesh_);
  return *rays_;
}

bool ProgressiveSolver::refinement_due() const {
  if (options_.meshing != Meshing::adaptive || next_light_ < lights_.size()) return false;
  return next_refinement_ < std::size(kRefineAt) && unshot_fraction() < kRefineAt[next_refinement_];
}

// The candidates whose irradiance differs from the mean of their neighbours' on the same surface
// by more than the threshold times the scene's mean irradiance, and that may still be cut. Gouraud
// shading draws the light as linear between vertices: where it is linear (a smooth falloff), an
// element is its neighbours' mean and needs no cut; along a shadow's edge or into a corner it is
// not. Emitters are left whole: what they show is E.
std::vector<uint32_t> ProgressiveSolver::too_coarse(const MeshBisection& bisection,
                                                    const std::vector<uint32_t>& candidates) const {
  double area = 0.0, arrived = 0.0;
  for (size_t e = 0; e < mesh_.size(); ++e) {
    area += double(mesh_.patches[e].area);
    arrived += mean(irradiance_[e]) * double(mesh_.patches[e].area);
  }
  const double step = area > 0.0 ? double(options_.refine_threshold) * arrived / area : 0.0;
  std::vector<uint32_t> marked, around;
  if (!(step > 0.0)) return marked;
  for (const uint32_t e : candidates) {
    const Patch& p = mesh_.patches[e];
    if (p.level >= options_.refine_levels || emits(p) || !(p.area > 0.0f)) continue;
    around.clear();
    bisection.neighbours(e, around);
    if (around.empty()) continue;
    double neighbours = 0.0;
    for (const uint32_t f : around) neighbours += mean(irradiance_[f]);
    if (std::abs(mean(irradiance_[e]) - neighbours / double(around.size())) > step) marked.push_back(e);
  }
  return marked;
}

// What element j has received so far, per square metre: from every patch i that has shot
// (`senders`, in order), F(j -> i) V_ij times all it sent (its elements' radiosity, seen from j
// as a shot is), and from every light already shot, its flux through the element.
Rgb ProgressiveSolver::gather(uint32_t j, const std::vector<uint32_t>& senders, const std::vector<Rgb>& sent,
                              const std::vector<ShooterEmission>& emissions,
                              const std::vector<std::vector<Rgb>>& parts) const {
  const Patch& element = mesh_.patches[j];
  const size_t m = size_t(options_.visibility_rays);
  uint64_t traced = 0;
  glm::dvec3 arrived(0.0);
  for (const uint32_t i : senders) {
    const ShootingPatch& shooter = mesh_.shooters[i];
    const double F_ij = rays_->element_factor(i, emissions[i], j, m, options_.seed, kGatherShot, traced);
    if (!(F_ij > 0.0)) continue;
    const double F_ji = F_ij * double(shooter.area) / double(element.area);
    arrived += F_ji * glm::dvec3(seen_from(shooter, element, sent[i], parts[i]));
  }
  // A light's shadow edge is where the cuts are: its rays are the most a ray estimate takes.
  for (size_t k = 0; k < next_light_; ++k) {
    const Light& light = scene_.lights[lights_[k]];
    const double value =
        light.type == LightType::directional
            ? rays_->element_sunlit_area(light, j, kMaxVisibilityRays, options_.seed, kGatherShot, traced)
            : rays_->element_solid_angle(light, j, kMaxVisibilityRays, options_.seed, kGatherShot, traced);
    arrived += glm::dvec3(light_flux(light, element, float(value))) / double(element.area);
  }
  return Rgb(arrived);
}

// Cut, gather, and look again at what was cut and its neighbours, until nothing is too coarse
// or the elements are refine_levels cuts deep.
size_t ProgressiveSolver::refine() {
  if (refinement_passes_ == 0) original_ = mesh_;  // for reset()
  // The elements subdivision may add, within what memory allows.
  const double budget = std::min(kMaxElements, double(original_.size()) + double(options_.refine_budget));
  const size_t before = mesh_.size();
  rays();
  MeshBisection bisection(mesh_);
  // What each patch has sent in all its shots, per square metre (its elements' radiosity).
  // Only the patches that have shot: after a few shots of a large model, a few of 100 000.
  std::vector<Rgb> sent(mesh_.shooters.size(), Rgb(0.0f));
  std::vector<uint32_t> senders;
  for (size_t i = 0; i < mesh_.shooters.size(); ++i) {
    sent[i] = patch_sent(i);
    if (mean(sent[i]) != 0.0) senders.push_back(uint32_t(i));
  }

  std::vector<uint32_t> candidates(mesh_.size()), changed;
  std::iota(candidates.begin(), candidates.end(), 0u);
  for (int depth = 0; depth < options_.refine_levels; ++depth) {
    const std::vector<uint32_t> marked = too_coarse(bisection, candidates);
    if (marked.empty()) break;
    std::vector<int> level(marked.size());
    for (size_t k = 0; k < marked.size(); ++k) level[k] = mesh_.patches[marked[k]].level;
    changed.clear();
    bool out_of_budget = false;
    for (size_t k = 0; k < marked.size(); ++k) {  // unless a neighbour's cut already cut it
      // A cut with the cuts conformity chains to it makes a few elements: none is begun that
      // could pass the budget.
      if (double(mesh_.size()) + kElementsPerCut > budget) {
        out_of_budget = true;
        break;
      }
      if (mesh_.patches[marked[k]].level == level[k]) bisection.split(marked[k], changed);
    }

    // A new half starts as a copy of the element it came from (the half that kept the slot),
    // in the order they were made, so a half cut again copies its own values.
    radiosity_.resize(mesh_.size());
    unshot_.resize(mesh_.size());
    irradiance_.resize(mesh_.size());
    for (size_t k = 0; k + 1 < changed.size(); k += 2) {
      const uint32_t kept = changed[k], made = changed[k + 1];
      radiosity_[made] = radiosity_[kept];
      unshot_[made] = unshot_[kept];
      irradiance_[made] = irradiance_[kept];
    }
    std::sort(changed.begin(), changed.end());
    changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
    mesh_.group_by_shooter();
    // What each patch's elements have sent (their radiosity), in members order, once per pass.
    std::vector<std::vector<Rgb>> parts(mesh_.shooters.size());
    std::vector<ShooterEmission> emissions;
    emissions.reserve(mesh_.shooters.size());
    for (size_t i = 0; i < mesh_.shooters.size(); ++i) {
      for (uint32_t k = mesh_.shooters[i].first; k < mesh_.shooters[i].first + mesh_.shooters[i].count; ++k)
        parts[i].push_back(radiosity_[mesh_.members[k]]);
      emissions.emplace_back(mesh_, i, parts[i]);
    }

    std::vector<Rgb> gathered(changed.size());
    // gather's rays and contour integrals let the page's main thread take its share (core/parallel_for.h).
    parallel_for_ranges(
        size_t(0), changed.size(), size_t(16),
        [&](size_t first, size_t end) {
          for (size_t k = first; k != end; ++k) gathered[k] = gather(changed[k], senders, sent, emissions, parts);
        },
        parallel::MainThread::joins);
    for (size_t k = 0; k < changed.size(); ++k) {
      const uint32_t e = changed[k];
      const Patch& p = mesh_.patches[e];
      // The light the coarser element counted wrongly: of it, rho goes to unshot (below), the
      // rest to absorbed, and it came from (or goes back to) what was counted as escaped.
      const Rgb correction = (gathered[k] - irradiance_[e]) * p.area;
      tally_.absorbed += mean((Rgb(1.0f) - p.rho) * correction);
      tally_.escaped -= mean(correction);
      irradiance_[e] = gathered[k];
      unshot_[e] = p.emission + p.rho * gathered[k] - radiosity_[e];  // displayed = E + rho H
    }
    if (out_of_budget) {
      if (!budget_reached_)
        warnings_.push_back(i18n::trf("radiosity: adaptive subdivision stopped at {} elements, its budget "
                                      "of {} more than the {} built (--refine-budget)",
                                      mesh_.size(), options_.refine_budget, original_.size()));
      budget_reached_ = true;
      break;
    }
    candidates = changed;
    for (const uint32_t e : changed) bisection.neighbours(e, candidates);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  }
  patch_unshot_.assign(mesh_.shooters.size(), glm::dvec3(0.0));
  for (size_t e = 0; e < mesh_.size(); ++e)
    patch_unshot_[mesh_.shooter_of[e]] += glm::dvec3(unshot_[e]) * double(mesh_.patches[e].area);
  mesh_.find_display_surfaces();
  revision_ = ++mesh_.revision;
  items_.upload(mesh_);
  ++refinement_passes_;
  while (next_refinement_ < std::size(kRefineAt) && unshot_fraction() < kRefineAt[next_refinement_])
    ++next_refinement_;
  return mesh_.size() - before;
}

}  // namespace luz
