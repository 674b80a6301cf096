#include "radiosity/radiosity_options.h"

#include <fmt/format.h>

namespace luz {

std::string RadiosityOptions::to_string() const {
  const std::string mesh = patch_size > 0.0f ? fmt::format("patch size {:.4g} m", patch_size)
                                             : fmt::format("~{} patches", target_patches);
  const std::string stop = max_shots > 0 ? fmt::format("{} shots", max_shots)
                                         : fmt::format("until unshot < {:.3g}", converge);
  return fmt::format("RadiosityOptions [{}, hemicube {}{}, {}{}{}{}]", mesh, hemicube_res,
                     random_rotation ? " rotated" : "", stop,
                     ambient_estimate ? ", ambient estimate" : "", flat_patches ? ", flat" : "",
                     outlines ? ", outlines" : "");
}

}  // namespace luz
