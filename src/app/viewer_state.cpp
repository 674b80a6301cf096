#include "app/viewer_state.h"

namespace luz::app {
namespace {

// Radiosity and the hybrid are being written in their own issues; they flip
// `available` when they land (and add their section in panel.cpp).
constexpr ModelInfo table[] = {
    {Model::flat, "flat", "flat", true},
    {Model::gouraud, "gouraud", "Gouraud", true},
    {Model::phong, "phong", "Phong", true},
    {Model::whitted, "whitted", "Whitted", true},
    {Model::radiosity, "radiosity", "radiosity", false},
    {Model::hybrid, "hybrid", "hybrid", false},
};

}  // namespace

std::span<const ModelInfo> models() { return table; }

const ModelInfo& info(Model model) { return table[int(model)]; }

}  // namespace luz::app
