#include "app/cli/render_grid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "app/common/i18n.h"
#include "app/common/model_registry.h"
#include "core/error.h"
#include "io/gltf_loader.h"
#include "io/image_io.h"

namespace luz::app {
namespace {

// A flag given for one model must reach at least one pane; else it is the same usage error as
// with a single model (its group is taken by no pane's model).
void check_flags(const RenderSettings& settings, const std::vector<const ModelEntry*>& models) {
  if (settings.ray_tree) throw Error(ErrorKind::usage, tr("--ray-tree: only with a single --model whitted or hybrid"));
  for (const RenderSettings::GivenFlag& given : settings.given_flags) {
    const bool taken = std::any_of(models.begin(), models.end(), [&](const ModelEntry* m) {
      return std::any_of(m->flag_groups.begin(), m->flag_groups.end(), [&](const char* g) { return given.group == g; });
    });
    if (!taken)
      throw Error(ErrorKind::usage, trf("{}: only when a pane is {}", given.flag, models_accepting(given.group)));
  }
  if (settings.local.fog.mode == FogMode::linear && !(settings.local.fog.far > settings.local.fog.near))
    throw Error(ErrorKind::usage, trf("--fog linear: --fog-far ({}) must be beyond --fog-near ({})",
                                      settings.local.fog.far, settings.local.fog.near));
}

// One pane: exactly what `luz render --model MODEL` computes for the same flags and size; the
// flags of groups this model does not take are dropped (another pane took them).
Image render_pane(const Scene& scene, const Camera& camera, int width, int height, const ModelEntry& model,
                  RenderSettings pane) {
  pane.model = model.name;
  std::erase_if(pane.given_flags, [&](const RenderSettings::GivenFlag& given) {
    return std::none_of(model.flag_groups.begin(), model.flag_groups.end(),
                        [&](const char* g) { return given.group == g; });
  });
  return model.render(scene, camera, width, height, pane).image;
}

}  // namespace

bool is_model_list(const std::string& text) { return text.find(',') != std::string::npos; }

std::vector<std::string> parse_model_list(const std::string& text) {
  std::vector<std::string> models;
  for (size_t start = 0;;) {
    const size_t comma = text.find(',', start);
    models.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  for (const std::string& model : models)
    if (!find_model(model))
      throw Error(ErrorKind::usage, trf("--model {}: unknown model \"{}\" ({})", text, model, model_names()));
  if (models.size() != 2 && models.size() != 4)
    throw Error(ErrorKind::usage, trf("--model {}: side by side takes 2 or 4 models, not {}", text,
                                      models.size()));
  return models;
}

std::string model_option_problem(const std::string& text) {
  if (is_model_list(text)) {
    try {
      parse_model_list(text);
    } catch (const Error& error) {
      return error.what();
    }
    return "";
  }
  if (find_model(text)) return "";
  return trf("unknown model \"{}\" ({}, or 2 or 4 of them separated by commas)", text, model_names());
}

GridLayout grid_layout(size_t panes) { return panes <= 2 ? GridLayout{int(panes), 1} : GridLayout{2, 2}; }

// Big enough to read on a printed page, whatever the pane's size.
float label_pixel_height(int pane_height) { return std::max(12.0f, float(pane_height) / 16.0f); }

LabelBox label_box(const LabelFont& font, const std::string& label, int pane_height) {
  const float size = label_pixel_height(pane_height);
  const LabelFont::Extent extent = font.measure(label, size);
  const int pad = int(std::ceil(0.3f * size));
  return {0, 0, extent.width + 2 * pad, extent.ascent + extent.descent + 2 * pad};
}

void draw_label(Image& pane, const LabelFont& font, const std::string& label, float exposure) {
  const LabelBox box = label_box(font, label, pane.height);
  for (int y = box.y; y < std::min(box.y + box.height, pane.height); ++y)
    for (int x = box.x; x < std::min(box.x + box.width, pane.width); ++x) pane.at(x, y) *= 0.25f;
  // The PNG multiplies by 2^exposure: this radiance comes out white.
  const Rgb white(std::exp2(-exposure));
  const float size = label_pixel_height(pane.height);
  const int pad = int(std::ceil(0.3f * size));
  font.draw(pane, box.x + pad, box.y + pad, label, size, white);
}

namespace {

// True when two panes or more show a radiosity solution: they share one solve.
bool shares_radiosity(const std::vector<std::string>& models) {
  return std::count_if(models.begin(), models.end(),
                       [](const std::string& m) { return m == "radiosity" || m == "hybrid"; }) > 1;
}

}  // namespace

Sheet render_sheet(const RenderSettings& settings, const Scene& scene, const Camera& camera,
                   const std::vector<std::string>& models) {
  Sheet sheet;
  sheet.layout = grid_layout(models.size());
  const float aspect = camera.aspect > 0.0f ? camera.aspect : 4.0f / 3.0f;
  int width = settings.width, height = settings.height;
  if (width <= 0) {
    sheet.pane_height = kDefaultPaneHeight;
    sheet.pane_width = std::max(1, int(std::lround(float(kDefaultPaneHeight) * aspect)));
    width = sheet.pane_width * sheet.layout.columns;
    height = sheet.pane_height * sheet.layout.rows;
  } else {
    sheet.pane_width = std::max(1, width / sheet.layout.columns);
    sheet.pane_height = std::max(1, height / sheet.layout.rows);
  }
  RenderSettings shared = settings;
  if (!shared.radiosity_solution && shares_radiosity(models))
    shared.radiosity_solution = find_model("radiosity")->solve(scene, settings);

  std::vector<Image> panes;
  for (const std::string& name : models)
    panes.push_back(render_pane(scene, camera, sheet.pane_width, sheet.pane_height, *find_model(name), shared));
  sheet.image = Image(width, height, Rgb(0.0f));
  const auto assemble = [&] {
    for (size_t i = 0; i < panes.size(); ++i) {
      const int left = int(i) % sheet.layout.columns * sheet.pane_width;
      const int top = int(i) / sheet.layout.columns * sheet.pane_height;
      for (int y = 0; y < sheet.pane_height; ++y)
        std::copy_n(&panes[i].at(0, y), sheet.pane_width, &sheet.image.at(left, top + y));
    }
  };
  // One exposure for all the panes, so that they compare (with --exposure auto the scene's, as
  // each model alone gets it), chosen before the labels go on.
  assemble();
  sheet.exposure = chosen_exposure(settings, scene, camera, sheet.image);
  if (models.size() > 1) {
    const LabelFont font;
    for (size_t i = 0; i < panes.size(); ++i) draw_label(panes[i], font, model_label(models[i]), sheet.exposure);
    assemble();
  }
  return sheet;
}

int run_render_grid(const RenderSettings& settings) {
  try {
    const std::vector<std::string> models = parse_model_list(settings.model);
    std::vector<const ModelEntry*> entries;
    for (const std::string& name : models) entries.push_back(find_model(name));
    check_flags(settings, entries);
    if (!io::is_supported_output(settings.out))
      throw Error(ErrorKind::usage, trf("--out {}: the output must end in .png or .exr", settings.out));
    LabelFont{};  // a missing font is found before the panes are rendered
    io::LoadedScene loaded = io::load_gltf(settings.scene);
    for (const std::string& warning : loaded.warnings) fmt::print(stderr, "{}\n", trf("warning: {}", warning));
    const Scene& scene = loaded.scene;
    const Camera& camera = chosen_camera(settings, scene);

    const auto start = std::chrono::steady_clock::now();
    const Sheet sheet = render_sheet(settings, scene, camera, models);
    io::write_image(sheet.image, settings.out, sheet.exposure);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!settings.quiet)
      fmt::print("{}\n", trf("{}: {} {}x{} panes ({}x{} each), camera \"{}\", exposure {:+g} EV, {:.3f} s", settings.out,
                              model_labels(settings.model), sheet.layout.columns, sheet.layout.rows, sheet.pane_width,
                              sheet.pane_height, camera.name, sheet.exposure, seconds));
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
