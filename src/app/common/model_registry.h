#pragma once
// The illumination models, one entry each: the name `luz render --model` and the script take,
// the panel's label, the digit key, the command-line flag groups it accepts, its options tables,
// its headless render and its viewer view. `luz render` (its flags and --help), `main`'s --help,
// the script's `model` and `set` verbs, dump-state, the lessons, the panel's radio buttons, F1
// and the keys all read these entries, so adding a model is one folder, one line in the
// catalogue (models/model_catalogue.cpp) and one CMake line (docs/adding-a-model.md).
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/common/option_row.h"
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

// An options table of a model's, by the function that holds it (options_tables.h, a model's own).
using OptionTableOf = const OptionTable& (*)();

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
  // The options tables it takes (option_row.h): their rows are its flags, its `set` names, its
  // panel's ranges, its lessons' keys and its part of dump-state's settings.
  std::span<const OptionTableOf> options;
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

// Every model: the catalogue's, in its order, then those registered (ModelRegistration).
std::span<const ModelEntry> models();
// The program's own table (models/model_catalogue.cpp; a program of the command line alone
// writes its own).
std::span<const ModelEntry> catalogue();
// A model added to the catalogue's by a program that links it (a test's model, a plug-in): a
// namespace-scope `const ModelRegistration toy{entry};` adds it before main, after the
// catalogue's. A name or key already taken is a programmer's error (the program stops).
struct ModelRegistration {
  explicit ModelRegistration(const ModelEntry& entry);
};

// Every options table the models take, each once, in the models' order.
std::vector<const OptionTable*> option_tables();
// The row of a script name: "spp" (the first table's, in option_tables()' order, that has it) or
// "TABLE.NAME" ("path.spp": that table's). Empty when there is none.
struct FoundOption {
  const OptionTable* table;
  const OptionRow* row;
};
std::optional<FoundOption> find_option(std::string_view name);
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
// model_label of each name in a comma-separated list ("radiosity,hybrid"), joined by ", ": the
// models a run summary names, in the user's language.
std::string model_labels(const std::string& names);

}  // namespace luz::app
