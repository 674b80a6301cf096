#pragma once
// A key of the viewer bound to a line of the script language, as F3D binds its keys to command
// strings: pressing the key runs the line through the same verb a script or a lesson step runs,
// so the three do the same thing the same way. The viewer's own keys are one table
// (viewer/shortcuts.cpp); a model's keys come with its registry entry (model_registry.h).
namespace luz::app {

struct KeyBinding {
  // The key as `key NAME` takes it (shortcuts.h's parse_key: "U", "Shift+A", "space", "Ctrl+minus").
  const char* key;
  // As F1 and the docs show it; a message id where it has words (N_("Space")); nullptr: `key`.
  const char* shown;
  // The script line it runs (script.h); nullptr for a key listed for help only (held keys: flying).
  const char* line;
  const char* what;  // F1's description, a message id
};

}  // namespace luz::app
