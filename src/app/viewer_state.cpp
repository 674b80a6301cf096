#include "app/viewer_state.h"

namespace luz::app {
namespace {

// The hybrid is being written in its own issue; it flips
// `available` when they land (and add their section in panel.cpp).
constexpr ModelInfo table[] = {
    {Model::flat, "flat", "flat", true},
    {Model::gouraud, "gouraud", "Gouraud", true},
    {Model::phong, "phong", "Phong", true},
    {Model::whitted, "whitted", "Whitted", true},
    {Model::radiosity, "radiosity", "radiosity", true},
    {Model::hybrid, "hybrid", "hybrid", false},
};

}  // namespace

std::span<const ModelInfo> models() { return table; }

const ModelInfo& info(Model model) { return table[int(model)]; }

}  // namespace luz::app
