#pragma once
// The window: the scene in a local model, on the scene's camera. Returns the exit code.
#include <string>

namespace luz::app {

int run_viewer(const std::string& scene);

}  // namespace luz::app
