#include "app/handout/lesson_picture.h"

#include <algorithm>

#include <fmt/format.h>

#include "app/common/options_tables.h"
#include "app/common/radiosity_drive.h"
#include "app/viewer/viewer_settings.h"
#include "app/viewer/viewer_state.h"
#include "core/error.h"

namespace luz::app {
namespace {

// The window's radiosity solver as the step's commands drive it (radiosity_view.cpp's verbs).
struct SolverDrive {
  bool running = false;
  int shots = 0;
  std::string mesh;  // the settings whose change starts the solution over

  void run(const std::vector<std::string>& a) {
    if (a[0] == "run") running = true;
    if (a[0] == "pause") running = false;
    if (a[0] == "reset") shots = 0;
    if (a[0] == "step") {
      running = false;
      shots += std::stoi(a[1]);
    }
  }
  void wait_shots(int n) {  // runs, then pauses at n shots
    running = false;
    shots = std::max(shots, n);
  }
};

// `radiosity NAME VALUE`: an options row, or the heat map; the rest (the shooter's highlight,
// the item buffer's window, the time budget) is the window's, not the picture's.
void set_radiosity(const std::vector<std::string>& a, RadiosityOptions& options, StepPicture& picture,
                   std::string& mesh) {
  if (a[0] == "heat-map") {
    picture.heat_map = a[1] == "on";
    return;
  }
  const OptionRow* row = find_row(radiosity_table(), a[0]);
  if (!row) return;
  if (const std::optional<double> value = parse_value(*row, a[1])) row->set(&options, *value);
  if (is_radiosity_mesh_setting(a[0])) mesh += a[0] + "=" + a[1] + " ";
}

}  // namespace

bool StepPicture::shows_radiosity() const {
  return std::any_of(models.begin(), models.end(), [](const std::string& m) { return m == "radiosity" || m == "hybrid"; });
}

std::vector<StepPicture> step_pictures(const Lesson& lesson) {
  std::vector<StepPicture> pictures;
  ViewerState state;  // the switches and settings the script's `set` verb changes
  state.model_options = OptionValues(OptionValues::Start::render);  // luz render's defaults
  std::optional<float> exposure;
  bool exposure_auto = false;
  std::string scene;
  SolverDrive drive;
  for (const LessonStep& step : lesson.steps) {
    StepPicture picture;
    RadiosityOptions radiosity;
    std::string mesh;
    for (const ScriptCommand& c : step.commands) {
      const auto& a = c.args;
      std::string error;
      if (c.verb == "load" && a[0] != scene) {
        scene = a[0];
        exposure.reset();  // a scene brings its own exposure
        exposure_auto = false;
      } else if (c.verb == "camera") {
        picture.settings.camera = a[0];
      } else if (c.verb == "model") {
        picture.settings.model = a[0];
      } else if (c.verb == "set" && a[0] == "exposure") {
        exposure_auto = a[1] == "auto";
        if (!exposure_auto) exposure = std::stof(a[1]);
      } else if (c.verb == "set") {
        if (!apply_setting(state, a[0], a[1], error))
          throw Error(ErrorKind::usage, fmt::format("{}:{}: {}", lesson.file.string(), c.line, error));
      } else if (c.verb == "radiosity" && a.size() == 2 && a[0] != "step") {
        set_radiosity(a, radiosity, picture, mesh);
      } else if (c.verb == "radiosity") {
        drive.run(a);
      } else if (c.verb == "panes" && mesh != drive.mesh) {
        // The settings are all given before `panes`, the actions after: a new mesh's solution
        // starts at shot 0 before the actions drive it.
        drive.mesh = mesh;
        drive.shots = 0;
      } else if (c.verb == "wait-shots") {
        drive.wait_shots(std::stoi(a[0]));
      }
    }
    picture.settings.scene = scene;
    picture.settings.local = state.local;
    picture.settings.whitted = state.whitted;
    picture.settings.radiosity = radiosity;
    picture.settings.model_options = state.model_options;
    picture.settings.exposure = exposure;
    picture.settings.exposure_auto = exposure_auto;
    picture.settings.quiet = true;
    picture.models = step.panes.empty() ? std::vector<std::string>{step.model} : step.panes;
    const bool hybrid = std::find(picture.models.begin(), picture.models.end(), "hybrid") != picture.models.end();
    if (!drive.running && !hybrid) picture.radiosity.shots = drive.shots;
    pictures.push_back(std::move(picture));
  }
  return pictures;
}

}  // namespace luz::app
