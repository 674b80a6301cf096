#include "radiosity/radiosity_options.h"

#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "core/i18n.h"

namespace luz {

const char* to_string(FormFactorMethod method) {
  switch (method) {
    case FormFactorMethod::hemicube: return "hemicube";
    case FormFactorMethod::analytic: return "analytic";
    case FormFactorMethod::rays: return "rays";
  }
  return "?";
}

const char* to_string(Meshing meshing) {
  return meshing == Meshing::adaptive ? "adaptive" : "uniform";
}

std::string RadiosityOptions::to_string() const {
  const std::string patches = patch_size > 0.0f ? fmt::format("patch size {:.4g} m", patch_size)
                                                : fmt::format("~{} patches", target_patches);
  std::string mesh = fmt::format("{}, {}x{} elements each", patches, elements_per_edge,
                                 elements_per_edge);
  if (meshing == Meshing::adaptive)
    mesh += fmt::format(", adaptive ({:g}, {} cuts)", refine_threshold, refine_levels);
  const std::string stop = max_shots > 0 ? fmt::format("{} shots", max_shots)
                                         : fmt::format("until unshot < {:.3g}", converge);
  return fmt::format("RadiosityOptions [{}, hemicube {}{}{}{}, {} form factors, {}{}{}{}{}{}]", mesh,
                     hemicube_res, random_rotation ? " rotated" : "",
                     hemicube_passes == HemicubePasses::one ? " in one pass" : "",
                     hemicube_sums == HemicubeSums::gpu ? " summed on the GPU" : "",
                     form_factors == FormFactorMethod::rays
                         ? fmt::format("rays ({} per element)", visibility_rays)
                         : luz::to_string(form_factors),
                     stop,
                     overshoot != 1.0f ? fmt::format(", overshoot {:g}", overshoot) : "",
                     ambient_estimate ? ", ambient estimate" : "", flat_patches ? ", flat" : "",
                     outlines ? ", outlines" : "", textures ? "" : ", no textures");
}

void RadiosityOptions::validate() const {
  using i18n::trf;
  const auto refuse = [](const std::string& what) {
    throw Error(ErrorKind::bad_value, trf("radiosity: {}", what));
  };
  if (!std::isfinite(patch_size) || patch_size < 0.0f)
    refuse(trf("patch size {} must be a finite length in metres (0 = automatic)", patch_size));
  if (target_patches < 1) refuse(trf("target of {} patches must be at least 1", target_patches));
  if (elements_per_edge < 1 || elements_per_edge > kMaxElementsPerEdge)
    refuse(trf("{} elements per patch edge, expected 1 .. {}", elements_per_edge, kMaxElementsPerEdge));
  if (!std::isfinite(refine_threshold) || !(refine_threshold > 0.0f))
    refuse(trf("refinement threshold {} must be a positive fraction of the mean irradiance (0 "
               "would cut every element down to the last level)", refine_threshold));
  if (refine_levels < 1 || refine_levels > kMaxRefineLevels)
    refuse(trf("{} refinement levels, expected 1 .. {}", refine_levels, kMaxRefineLevels));
  if (refine_budget < 0 || refine_budget > kMaxRefineBudget)
    refuse(trf("refinement budget of {} elements, expected 0 .. {}", refine_budget, kMaxRefineBudget));
  if (hemicube_res < kMinHemicubeRes || hemicube_res > kMaxHemicubeRes || hemicube_res % 2 != 0)
    refuse(trf("hemicube resolution {} must be even and in {} .. {}", hemicube_res, kMinHemicubeRes,
               kMaxHemicubeRes));
  if (visibility_rays < 1 || visibility_rays > kMaxVisibilityRays)
    refuse(trf("{} visibility rays per element, expected 1 .. {}", visibility_rays, kMaxVisibilityRays));
  const int root = int(std::lround(std::sqrt(double(pixel_samples))));
  if (pixel_samples < 1 || pixel_samples > kMaxPixelSamples || root * root != pixel_samples)
    refuse(trf("{} samples per pixel, expected a square in 1 .. {}", pixel_samples, kMaxPixelSamples));
  if (!std::isfinite(work_budget) || work_budget < 0.0 || work_budget > kMaxWorkBudget)
    refuse(trf("work budget of {} element-shots, expected 0 .. {:g}", work_budget, kMaxWorkBudget));
  if (max_shots < 0) refuse(trf("{} shots must not be negative", max_shots));
  if (!std::isfinite(converge) || converge < 0.0f || converge >= 1.0f)
    refuse(trf("convergence threshold {} must be in [0, 1) (0 = run until --shots)", converge));
  if (converge == 0.0f && max_shots == 0)
    refuse(i18n::tr("a convergence threshold of 0 with no shot limit would never stop"));
  if (!std::isfinite(overshoot) || overshoot < kMinOvershoot || overshoot > kMaxOvershoot)
    refuse(trf("overshoot factor {} must be in {} .. {}", overshoot, kMinOvershoot, kMaxOvershoot));
}

}  // namespace luz
