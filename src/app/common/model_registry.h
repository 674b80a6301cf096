#pragma once
// The illumination models, one entry each: the name `luz render --model` and the script take,
// the panel's label, the digit key, the command-line flag groups it accepts, its headless render
// and its viewer view. `luz render`, `main`'s --help, the script's `model` verb, the panel's
// radio buttons, F1 and the keys all read this table, so adding a model is one file pair (its
// render function and its ModelView) and one line in model_registry.cpp.
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "core/scene.h"

namespace luz::app {

struct RenderSettings;
struct RadiositySolution;
struct ScriptVerb;
struct KeyBinding;
class ModelView;
class ViewerServices;

// What a headless render makes: the picture and what `luz render` prints or writes beside it.
struct Rendered {
  Image image;
  std::string summary;                  // printed after the picture's line (counters, shots)
  std::optional<std::string> ray_tree;  // JSON, written beside the image when --ray-tree was given
};

struct ModelEntry {
  const char* name;    // `luz render --model NAME`, `model NAME` in a script
  const char* label;   // the panel's radio button, the status line
  int key;             // the digit that shows it (1 .. 9)
  const char* help;    // F1's line and --help's
  // The flag groups of `luz render` it takes: each options table row names its group
  // (options_tables.h: "terms", "ambient-emission", "textures", "local", "whitted", "sampling",
  // "path", "radiosity", "radiosity-display", "time"); a flag of
  // another group is a usage error naming the models that take it.
  std::span<const char* const> flag_groups;
  // Headless (OSMesa or CPU): makes its own GL context when it needs one.
  Rendered (*render)(const Scene& scene, const Camera& camera, int width, int height, const RenderSettings& settings);
  // The viewer's view; the scene and the GL context are the viewer's.
  std::unique_ptr<ModelView> (*make_view)(ViewerServices& viewer);
  std::span<const ScriptVerb> verbs;  // its script verbs (script.h), beside the common ones
  // The view-independent solution its pictures show, solved once for several panes of a sheet
  // (radiosity's, which the hybrid shows too); nullptr for a model that has none.
  std::shared_ptr<const RadiositySolution> (*solve)(const Scene& scene, const RenderSettings& settings);
  // Its keys, each bound to a line of its verbs (key_binding.h): F1 lists them, pressed they
  // run that line.
  std::span<const KeyBinding> keys = {};
};

std::span<const ModelEntry> models();
// The difference view's reference: the model that solves slide 14's equation itself.
const ModelEntry& reference_model();
// The lecture's comparisons side by side (slide 44), as lists of model names.
std::span<const std::vector<std::string>> lecture_comparisons();
const ModelEntry* find_model(std::string_view name);  // nullptr when there is none
const ModelEntry* model_on_key(int digit);            // nullptr when no model has that key
// "flat, gouraud or phong": the models that accept a flag group, for messages.
std::string models_accepting(std::string_view flag_group);
// "flat, gouraud, phong, ...": every model's name.
std::string model_names(const char* separator = ", ");
// The model's label (its entry's, translated) for the name `luz render --model` takes; the name
// itself when no model has it.
std::string model_label(const std::string& name);

}  // namespace luz::app
