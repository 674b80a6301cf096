#include "app/models/path/path_options.h"

#include <cstdint>
#include <limits>

#include "app/common/i18n.h"

namespace luz::app {
namespace {

const OptionRow rows[] = {
    {"spp", "--spp", "sampling", OptionKind::integer, N_("path: samples per pixel, any number"), 1, 4096,
     LUZ_OPTION_FIELD(PathSettings, spp)},
    {"depth", "--depth", "sampling", OptionKind::integer,
     N_("path: maximum ray depth as on slide 26 (primary rays have depth 1; 0 is taken as 1)"), 0, 64,
     LUZ_OPTION_FIELD(PathSettings, max_depth)},
    {"seed", "--seed", "path", OptionKind::integer,
     N_("path: seed of the random numbers (the same seed gives the same picture)"), 0,
     double(std::numeric_limits<uint32_t>::max()), LUZ_OPTION_FIELD(PathSettings, seed)},
    file_row("error-out", "--error-out", "path", N_("path: write the per-pixel standard error of the mean to this .exr"),
             LUZ_OPTION_TEXT(PathSettings, error_out)),
};

void viewer_start(void* options) { static_cast<PathSettings*>(options)->spp = kViewerTarget; }

}  // namespace

const OptionTable& path_table() {
  static const OptionTable table = option_table<PathSettings>("path", rows, viewer_start);
  return table;
}

}  // namespace luz::app
