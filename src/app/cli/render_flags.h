#pragma once
// `luz render`'s flags: the ones every model takes (scene, model, output, size, camera,
// exposure), and the flag groups the registry's models pick from (model_registry.h).
#include <vector>

#include "app/cli/render_command.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace luz::app {

// Adds every flag of `luz render` to `render`; `given` later tells which group flags were given.
struct RenderFlags {
  struct Grouped {
    const char* group;
    CLI::Option* option;
  };
  std::vector<Grouped> grouped;
};
RenderFlags add_render_flags(CLI::App& render, RenderSettings& settings);

// After parsing: the group flags that were given, into settings.given_flags.
void note_given_flags(const RenderFlags& flags, RenderSettings& settings);

}  // namespace luz::app
