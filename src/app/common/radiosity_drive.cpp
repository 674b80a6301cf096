#include "app/common/radiosity_drive.h"

#include <algorithm>

#include "app/common/i18n.h"

namespace luz::app {
namespace {

constexpr RadiositySwitch switches[] = {
    {"heat-map", nullptr, &RadiosityDrive::heat_map, N_("radiosity heat map")},
    {"outlines", &RadiosityOptions::outlines, nullptr, nullptr},
    {"flat-patches", &RadiosityOptions::flat_patches, nullptr, nullptr},
    {"ambient-estimate", &RadiosityOptions::ambient_estimate, nullptr, N_("radiosity ambient estimate")},
    {"shooter", nullptr, &RadiosityDrive::show_shooter, nullptr},
    {"item-buffer", nullptr, &RadiosityDrive::show_item_buffer, nullptr},
    {"rotation", &RadiosityOptions::random_rotation, nullptr, nullptr},
};

constexpr const char* mesh_settings[] = {"patch-size", "hemicube", "meshing", "form-factors"};

}  // namespace

std::span<const RadiositySwitch> radiosity_switches() { return switches; }

const RadiositySwitch* find_radiosity_switch(std::string_view name) {
  const auto found = std::find_if(std::begin(switches), std::end(switches),
                                  [name](const RadiositySwitch& s) { return name == s.name; });
  return found == std::end(switches) ? nullptr : found;
}

std::span<const char* const> radiosity_mesh_settings() { return mesh_settings; }

bool is_radiosity_mesh_setting(std::string_view name) {
  return std::any_of(std::begin(mesh_settings), std::end(mesh_settings),
                     [name](const char* s) { return name == s; });
}

}  // namespace luz::app
