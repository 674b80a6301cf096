// Sections: [the formula] [slide 19's switches] [model sections] [lights] [material] [scene]
//           [the panel]
#include "app/viewer/panel.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/trigonometric.hpp>
#include <imgui.h>

#include "app/viewer/difference_window.h"
#include "app/classroom/classroom_ui.h"
#include "app/common/i18n.h"
#include "app/common/model_registry.h"
#include "app/viewer/overlays.h"
#include "app/common/options_tables.h"
#include "app/viewer/panes.h"
#include "core/resources.h"

namespace luz::app {
namespace {

// ---- [the formula] -----------------------------------------------------------------------------
// One colour per term, the same in the formula and in the term switches, so the class can match
// the picture's change to the symbol that was switched.
const ImVec4 ambient_colour(0.55f, 0.75f, 1.0f, 1.0f);
const ImVec4 diffuse_colour(0.55f, 0.95f, 0.55f, 1.0f);
const ImVec4 specular_colour(1.0f, 0.85f, 0.4f, 1.0f);
const ImVec4 emission_colour(1.0f, 0.6f, 0.8f, 1.0f);
const ImVec4 shadow_colour(0.8f, 0.7f, 1.0f, 1.0f);
const ImVec4 reflection_colour(0.6f, 0.95f, 0.95f, 1.0f);
const ImVec4 transparency_colour(0.75f, 0.85f, 1.0f, 1.0f);
const ImVec4 fog_colour(0.8f, 0.8f, 0.8f, 1.0f);

// A piece of formula on the current line: coloured when its term is on, greyed when off.
void piece(const char* text, bool on, const ImVec4& colour) {
  ImGui::SameLine(0.0f, 0.0f);
  if (on) ImGui::TextColored(colour, "%s", text);
  else ImGui::TextDisabled("%s", text);
}

void plain(const char* text) {
  ImGui::SameLine(0.0f, 0.0f);
  ImGui::TextUnformatted(text);
}

bool any_classroom_attenuation(const Scene& scene) {
  return std::any_of(scene.lights.begin(), scene.lights.end(),
                     [](const Light& l) { return l.attenuation.classroom; });
}

// A checkbox in the colour of its term; `label` in English (its widget's name), shown translated.
bool term_checkbox(const char* label, bool* value, const ImVec4& colour) {
  ImGui::PushStyleColor(ImGuiCol_CheckMark, colour);
  const bool changed = ImGui::Checkbox(tr(label), value);
  name_widget(label);
  ImGui::PopStyleColor();
  return changed;
}

// ---- [slide 19's switches] ---------------------------------------------------------------------
// "Otras posibilidades": each a switch with its parameters, the same LocalOptions `luz render`
// fills from --fog, --shadows, --transparency and --reflection-map. Distance attenuation and
// non-uniform lights belong to each light (the Lights section below).
void effects_section(LocalOptions& o) {
  if (!ImGui::TreeNodeEx(tr("slide 19: other possibilities"), ImGuiTreeNodeFlags_DefaultOpen)) return;

  // Atmospheric attenuation.
  int fog = int(o.fog.mode);
  ImGui::PushStyleColor(ImGuiCol_Text, o.fog.mode != FogMode::off ? fog_colour : ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextUnformatted(tr("atmospheric attenuation (fog)  [G]"));
  ImGui::PopStyleColor();
  ImGui::RadioButton(tr("off##fog"), &fog, int(FogMode::off));
  name_widget("off##fog");
  ImGui::SameLine();
  ImGui::RadioButton(tr("linear"), &fog, int(FogMode::linear));
  name_widget("linear");
  ImGui::SameLine();
  ImGui::RadioButton(tr("exponential"), &fog, int(FogMode::exponential));
  name_widget("exponential");
  o.fog.mode = FogMode(fog);
  if (o.fog.mode != FogMode::off) {
    ImGui::ColorEdit3(tr("fog colour"), &o.fog.colour.r, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    name_widget("fog colour");
    if (o.fog.mode == FogMode::linear) {
      const SliderRange near = slider_range(local_table(), "fog-near"), far = slider_range(local_table(), "fog-far");
      ImGui::DragFloatRange2(tr("near, far (m)"), &o.fog.near, &o.fog.far, 0.05f, near.low, far.high, "%.2f");
      name_widget("near, far (m)");
      dim_text("%s", tr("f = (far - d) / (far - near), clamped"));
    } else {
      const SliderRange density = slider_range(local_table(), "fog-density");
      ImGui::DragFloat(tr("density (1/m)"), &o.fog.density, 0.002f, density.low, density.high, "%.3f");
      name_widget("density (1/m)");
      dim_text("%s", tr("f = exp(-density d)"));
    }
    dim_text("%s", tr("I' = f I + (1 - f) C_fog"));
  }

  // Blocking of the sources by occlusion.
  term_checkbox(N_("shadows S_i (shadow maps)  [H]"), &o.shadows.on, shadow_colour);
  if (o.shadows.on) {
    const SliderRange bias = slider_range(local_table(), "shadow-bias"), slope = slider_range(local_table(), "shadow-slope-bias"),
                      offset = slider_range(local_table(), "shadow-normal-offset");
    ImGui::DragFloat(tr("bias (m)"), &o.shadows.constant_bias, 0.0002f, bias.low, bias.high, "%.4f");
    name_widget("bias (m)");
    ImGui::DragFloat(tr("slope (texels)"), &o.shadows.slope_bias, 0.02f, slope.low, slope.high, "%.2f");
    name_widget("slope (texels)");
    ImGui::DragFloat(tr("offset (texels)"), &o.shadows.normal_offset, 0.02f, offset.low, offset.high, "%.2f");
    name_widget("offset (texels)");
    int size_index = std::clamp(int(std::lround(std::log2(float(o.shadows.map_size)))) - 8, 0, 4);
    ImGui::Combo(tr("map size"), &size_index, "256\0" "512\0" "1024\0" "2048\0" "4096\0");
    name_widget("map size");
    o.shadows.map_size = 256 << size_index;
    dim_text("%s", tr("bias + slope·texel·tan θ; lookup moved offset texels along N"));
    dim_text("%s", tr("point lights, emitters: cube maps; spots, sun: one map"));
  }

  // Non-refractive transparency.
  term_checkbox(N_("transparency kt·It (non-refractive)  [O]"), &o.transparency.on, transparency_colour);
  if (o.transparency.on) dim_text("%s", tr("I + kt · (what lies behind), drawn back to front"));

  // Reflection maps.
  term_checkbox(N_("reflection map kr·Ir  [M]"), &o.reflection.on, reflection_colour);
  if (o.reflection.on) {
    int size_index = std::clamp(int(std::lround(std::log2(float(o.reflection.resolution)))) - 6, 0, 4);
    ImGui::Combo(tr("cube face size"), &size_index, "64\0" "128\0" "256\0" "512\0" "1024\0");
    name_widget("cube face size");
    o.reflection.resolution = 64 << size_index;
    dim_text("%s", tr("a cube map from the centre of each object with kr > 0"));
    if (!o.reflection.environment.empty())
      dim_text(tr("environment: %s"), o.reflection.environment.c_str());
  }
  ImGui::TreePop();
}

// ---- [model sections] --------------------------------------------------------------------------
// The radio buttons of the registry's models, three to a row, then the shown model's section.
void model_header(ViewerState& state, ModelView& shown, DifferenceView& difference) {
  const bool section_open = ImGui::CollapsingHeader(tr("Model"), ImGuiTreeNodeFlags_DefaultOpen);
  name_widget("Model");  // a script folds a section to reach the ones below
  if (!section_open) return;
  int column = 0;
  for (const ModelEntry& m : models()) {
    const std::string label = fmt::format("{} [{}]", tr(m.label), m.key);
    if (ImGui::RadioButton(label.c_str(), state.model == m.name) && state.model != m.name)
      state.panel_lines.push_back(fmt::format("model {}", m.name));
    name_widget(fmt::format("{} [{}]", m.label, m.key));  // named in English, as every widget
    if (++column % 3 != 0) ImGui::SameLine();
  }
  difference.panel();  // on the radio buttons' last row when it has room
  shown.panel();
}

// ---- [lights] ----------------------------------------------------------------------------------
const char* light_type_label(LightType type) {
  switch (type) {
    case LightType::point: return tr("point");
    case LightType::spot: return tr("spot");
    case LightType::directional: return tr("directional");
  }
  return "?";
}

void lights_header(ViewerState& state) {
  Scene& scene = *state.scene;
  const bool section_open = ImGui::CollapsingHeader(tr("Lights"), ImGuiTreeNodeFlags_DefaultOpen);
  name_widget("Lights");  // a script folds a section to reach the ones below
  if (!section_open) return;
  if (scene.lights.empty()) dim_text("%s", tr("no punctual lights"));
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    Light& light = scene.lights[i];
    LightEdit& edit = state.light_edits[i];
    ImGui::PushID(int(i));
    // One light's widgets are named "its name/label": "key_light/colour".
    const auto named = [&light](const char* label) { name_widget(light.name + "/" + label); };
    ImGui::Checkbox("##on", &light.enabled);
    named("on");
    ImGui::SameLine();
    const bool open = ImGui::TreeNode("light", "%s (%s)", light.name.c_str(), light_type_label(light.type));
    named("light");
    if (open) {
      bool changed = ImGui::ColorEdit3(tr("colour"), &edit.colour.r);
      named("colour");
      const char* intensity = light.type == LightType::directional ? "E (W/m²)" : "I (W/sr)";
      changed |= ImGui::DragFloat(intensity, &edit.intensity, 0.1f + 0.01f * edit.intensity, 0.0f, 1e6f, "%.3g");
      named(intensity);
      if (changed) light.intensity = edit.colour * edit.intensity;
      if (light.type != LightType::directional) {
        ImGui::DragFloat3(tr("position"), &light.position.x, 0.01f, 0.0f, 0.0f, "%.3f");
        named("position");
        int mode = light.attenuation.classroom ? 1 : 0;
        ImGui::Combo("f_att", &mode, "1/d²\0" "1/(c0 + c1 d + c2 d²)\0");
        named("f_att");
        light.attenuation.classroom = mode == 1;
        ImGui::BeginDisabled(!light.attenuation.classroom);
        ImGui::DragFloat3("c0 c1 c2", &light.attenuation.c.x, 0.01f, 0.0f, 100.0f, "%.3f");
        named("c0 c1 c2");
        light.attenuation.c = glm::max(light.attenuation.c, glm::vec3(0.0f));
        if (light.attenuation.c == glm::vec3(0.0f)) light.attenuation.c.x = 1e-3f;  // f_att finite
        ImGui::EndDisabled();
      }
      if (light.type == LightType::spot) {  // slide 19: lights with a non-uniform distribution
        int warn = light.warn_exponent > 0.0f ? 1 : 0;
        const char* distributions[] = {tr("smooth cone"), tr("Warn's cos^p")};
        ImGui::Combo(tr("distribution"), &warn, distributions, 2);
        named("distribution");
        float outer = glm::degrees(light.outer_cone), inner = glm::degrees(light.inner_cone);
        if (warn == 1) {
          if (light.warn_exponent <= 0.0f) light.warn_exponent = 10.0f;
          ImGui::DragFloat("p", &light.warn_exponent, 0.2f, 0.01f, 1000.0f, "%.1f");
          named("p");
          ImGui::DragFloat(tr("cut-off (°)"), &outer, 0.2f, 0.1f, 90.0f, "%.1f");
          named("cut-off (°)");
        } else {
          light.warn_exponent = 0.0f;
          ImGui::DragFloatRange2(tr("inner, outer (°)"), &inner, &outer, 0.2f, 0.0f, 90.0f, "%.1f");
          named("inner, outer (°)");
          light.inner_cone = glm::radians(std::clamp(inner, 0.0f, outer));
        }
        light.outer_cone = glm::radians(std::clamp(outer, 0.1f, 90.0f));
      }
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  if (!scene.area_lights.empty())
    dim_text(tr("%zu emissive triangles light the scene (their Le: Material)"),
                        scene.area_lights.size());
}

// ---- [material] --------------------------------------------------------------------------------
void material_header(ViewerState& state) {
  Scene& scene = *state.scene;
  const bool section_open = ImGui::CollapsingHeader(tr("Material"), ImGuiTreeNodeFlags_DefaultOpen);
  name_widget("Material");  // a script folds a section to reach the ones below
  if (!section_open) return;
  if (state.selected_material < 0 || size_t(state.selected_material) >= scene.materials.size()) {
    dim_text("%s", tr("click an object in the picture"));
    return;
  }
  Material& m = scene.materials[size_t(state.selected_material)];
  const bool choosing = ImGui::BeginCombo("##material", m.name.c_str());
  name_widget("material");
  if (choosing) {
    for (size_t i = 0; i < scene.materials.size(); ++i)
      if (ImGui::Selectable(scene.materials[i].name.c_str(), int(i) == state.selected_material))
        state.selected_material = int(i);
    ImGui::EndCombo();
  }
  const ImGuiColorEditFlags hdr = ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR;
  ImGui::ColorEdit3("ka", &m.ka.r, ImGuiColorEditFlags_Float);
  name_widget("ka");
  ImGui::ColorEdit3("kd", &m.kd.r, ImGuiColorEditFlags_Float);
  name_widget("kd");
  ImGui::ColorEdit3("ks", &m.ks.r, ImGuiColorEditFlags_Float);
  name_widget("ks");
  ImGui::DragFloat("n", &m.shininess, 0.5f + 0.02f * m.shininess, 1.0f, 10000.0f, "%.1f",
                   ImGuiSliderFlags_Logarithmic);
  name_widget("n");
  ImGui::ColorEdit3("kr", &m.kr.r, ImGuiColorEditFlags_Float);
  name_widget("kr");
  ImGui::ColorEdit3("kt", &m.kt.r, ImGuiColorEditFlags_Float);
  name_widget("kt");
  ImGui::DragFloat("ior", &m.ior, 0.005f, 1.0f, 3.0f, "%.3f");
  name_widget("ior");
  if (ImGui::ColorEdit3("Le", &m.emission.r, hdr)) state.emitters_changed = true;
  name_widget("Le");
  dim_text("%s", tr("kr: reflection map [M]; kt: transparency [O]; ior: Whitted's model"));
}

// ---- [scene] -----------------------------------------------------------------------------------
// The shipped scenes (core/resources.h's folder), read once; the scene shown is the menu's title.
// In the page they are the scenes packed with it; a scene of another folder stays the title.
const std::vector<std::filesystem::path>& shipped_scenes() {
  static const std::vector<std::filesystem::path> scenes = [] {
    std::vector<std::filesystem::path> found;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(scene_dir(), error))
      if (entry.path().extension() == ".gltf") found.push_back(entry.path());
    std::sort(found.begin(), found.end());
    return found;
  }();
  return scenes;
}

void scene_menu(ViewerState& state) {
  const std::string shown = state.scene_path.filename().string();
  const bool choosing = ImGui::BeginCombo(tr("scene"), shown.c_str());
  name_widget("scene");
  if (!choosing) return;
  for (const std::filesystem::path& scene : shipped_scenes())
    if (ImGui::Selectable(scene.filename().string().c_str(), scene.filename() == state.scene_path.filename()))
      state.panel_lines.push_back("load \"" + scene.string() + "\"");
  ImGui::EndCombo();
}

constexpr PanelButton buttons[] = {
    {"fit the exposure [K]", "set exposure auto"},
    {"scene camera [C]", "camera"},
    {"reload [R]", "reload"},
};

// A button of `buttons`, by its widget's name: drawn with its translated label; pressed, its line
// is queued for the loop.
void line_button(ViewerState& state, std::string_view widget) {
  const PanelButton& b = *std::find_if(std::begin(buttons), std::end(buttons),
                                       [&](const PanelButton& p) { return widget == p.widget; });
  if (ImGui::Button(tr(b.widget))) state.panel_lines.push_back(b.line);
  name_widget(b.widget);
}

void scene_header(ViewerState& state) {
  Scene& scene = *state.scene;
  const bool section_open = ImGui::CollapsingHeader(tr("Scene"), ImGuiTreeNodeFlags_DefaultOpen);
  name_widget("Scene");  // a script folds a section to reach the ones below
  if (!section_open) return;
  const ImGuiColorEditFlags hdr = ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR;
  ImGui::ColorEdit3(tr("ambient Ia"), &scene.ambient.r, hdr);
  name_widget("ambient Ia");
  ImGui::ColorEdit3(tr("background"), &scene.background.r, hdr);
  name_widget("background");
  // Files from elsewhere may need -10 EV (Blender's lights in candela): core/exposure.h.
  ImGui::SliderFloat(tr("exposure (EV)"), &state.exposure, -12.0f, 12.0f, "%+.1f");
  name_widget("exposure (EV)");
  line_button(state, "fit the exposure [K]");
  const Camera& current = scene.cameras[size_t(state.scene_camera)];
  const std::string preview = state.free_camera ? trf("(moved from {})", current.name) : current.name;
  const bool choosing = ImGui::BeginCombo(tr("camera"), preview.c_str());
  name_widget("camera");
  if (choosing) {
    for (size_t i = 0; i < scene.cameras.size(); ++i)
      if (ImGui::Selectable(scene.cameras[i].name.c_str(), !state.free_camera && int(i) == state.scene_camera))
        state.panel_lines.push_back(fmt::format("camera {}", i));
    ImGui::EndCombo();
  }
  line_button(state, "scene camera [C]");
  ImGui::SameLine();
  line_button(state, "reload [R]");
  scene_menu(state);
}

}  // namespace

// Flat, Gouraud and Phong share the formula and its switches; they differ in where it is
// evaluated, which the section says.
void local_section(ViewerState& state) {
  LocalOptions& o = state.local;
  const char* where = o.shading == Shading::flat      ? tr("once per triangle, at its centroid, face normal")
                      : o.shading == Shading::gouraud ? tr("per vertex, colours interpolated")
                                                      : tr("per pixel, normals interpolated");
  dim_text(tr("evaluated %s"), where);
  ImGui::Spacing();
  draw_local_formula(o, *state.scene);
  ImGui::Spacing();
  term_checkbox(N_("ambient I_A  [A]"), &o.terms.ambient, ambient_colour);
  term_checkbox(N_("diffuse I_D  [D]"), &o.terms.diffuse, diffuse_colour);
  term_checkbox(N_("specular I_S  [S]"), &o.terms.specular, specular_colour);
  term_checkbox(N_("emission Le  [E]"), &o.terms.emission, emission_colour);
  ImGui::Checkbox(tr("kd texture  [T]"), &o.terms.textures);
  name_widget("kd texture  [T]");
  int blinn = o.terms.blinn ? 1 : 0;
  ImGui::TextUnformatted(tr("cos(α):"));
  ImGui::SameLine();
  ImGui::RadioButton(tr("Phong R·V"), &blinn, 0);
  name_widget("Phong R·V");
  ImGui::SameLine();
  ImGui::RadioButton(tr("Blinn N·H  [B]"), &blinn, 1);
  name_widget("Blinn N·H  [B]");
  o.terms.blinn = blinn == 1;
  ImGui::Spacing();
  effects_section(o);
}


void dim_text(const char* format, ...) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  va_list args;
  va_start(args, format);
  ImGui::TextWrappedV(format, args);
  va_end(args);
  ImGui::PopStyleColor();
}

void draw_local_formula(const LocalOptions& o, const Scene& scene) {
  // I = Ia ka + sum_i S_i IL_i [kd cos(theta) + ks cos^n(alpha)] + Le + kr Ir + kt It
  ImGui::TextUnformatted("I =");
  piece(" Ia·ka", o.terms.ambient, ambient_colour);
  plain(" + Σᵢ");
  piece(" Sᵢ", o.shadows.on, shadow_colour);
  plain(" ILᵢ[");
  piece("kd·cos θ", o.terms.diffuse, diffuse_colour);
  plain(" + ");
  piece(o.terms.blinn ? "ks(N·H)ⁿ" : "ks(R·V)ⁿ", o.terms.specular, specular_colour);
  plain("]");
  piece(" + Le", o.terms.emission, emission_colour);
  piece(" + kr·Ir", o.reflection.on, reflection_colour);
  piece(" + kt·It", o.transparency.on, transparency_colour);
  if (o.fog.mode != FogMode::off) ImGui::TextColored(fog_colour, tr("then I' = f·I + (1 - f)·C_fog (%s fog)"), tr(to_string(o.fog.mode)));
  dim_text(tr("ILᵢ = Iᵢ·f_att(dᵢ)/π,  f_att = %s"),
                      any_classroom_attenuation(scene) ? "1/(c0 + c1 d + c2 d²)" : "1/d²");
}

// ---- [the panel] -------------------------------------------------------------------------------
void draw_panel(ViewerState& state, ModelView& shown, DifferenceView& difference, float width, float height) {
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  begin_frame_window("Luz", glm::vec2(0.0f), glm::vec2(width, height), flags, Edge::right);
  // Widgets take 58 % of the width, their labels the rest: a label is never cut at the edge.
  ImGui::PushItemWidth(-0.42f * width);
  model_header(state, shown, difference);
  lights_header(state);
  material_header(state);
  scene_header(state);
  panes_section(state);  // last: the sections above keep their places
  // Last, so that no widget above moves for it (a prepared demo clicks them by position).
  ImGui::Separator();
  draw_language_switch();  // the next frame speaks the language chosen
  ImGui::PopItemWidth();
  ImGui::End();
}

std::span<const PanelButton> panel_buttons() { return buttons; }

}  // namespace luz::app
