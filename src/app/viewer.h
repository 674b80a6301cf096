#pragma once
// The window: the scene in a local model, orbiting camera. Returns the exit code.
#include <string>

namespace luz::app {

bool display_available();
int run_viewer(const std::string& scene);

}  // namespace luz::app
