// Sections: [evaluation, as each shading model does it] [json] [the window]
#include "app/viewer/inspector.h"

#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <imgui.h>

#include "app/common/i18n.h"
#include "app/viewer/overlays.h"

namespace luz::app {
namespace {

constexpr float degrees = 57.29577951f;

const Material& material_of(const Scene& scene, const Pick& pick) {
  static const Material fallback;
  const int m = scene.meshes[size_t(pick.mesh)].material;
  return m >= 0 && size_t(m) < scene.materials.size() ? scene.materials[size_t(m)] : fallback;
}

}  // namespace

// ---- [evaluation, as each shading model does it] -----------------------------------------------
InspectorReading read_terms(const Scene& scene, std::span<const AreaLight> area_lights,
                            const Pick& pick, const LocalOptions& options, const DrawnLookups& lookups) {
  InspectorReading reading;
  reading.pick = pick;
  reading.shading = options.shading;
  const Mesh& mesh = scene.meshes[size_t(pick.mesh)];
  const Material& material = material_of(scene, pick);
  const uint32_t* index = &mesh.indices[3 * size_t(pick.triangle)];
  const glm::vec3 eye = pick.eye;
  auto evaluate = [&](const glm::vec3& P, const glm::vec3& N) {
    return evaluate_terms(scene, material, P, N, glm::normalize(eye - P), options, area_lights,
                          lookups.shadows);
  };
  // lighting.glsl mirror_direction(): R = reflect(view ray, N).
  auto mirror = [&](const glm::vec3& P, const glm::vec3& N) { return glm::reflect(glm::normalize(P - eye), N); };
  glm::vec2 uv = pick.uv;
  glm::vec2 barycentric(pick.barycentric.y, pick.barycentric.z);  // where COLOR_0 is read
  // gl_FrontFacing: the triangle's winding is counter-clockwise on screen, i.e. its face normal
  // points to the eye.
  reading.emitting_side = glm::dot(pick.face, eye - pick.P) > 0.0f;

  switch (options.shading) {
    case Shading::phong: {  // phong.frag: N interpolated, turned to the viewer's side
      glm::vec3 N = pick.N;
      if (glm::dot(pick.face, N) * glm::dot(pick.face, eye - pick.P) < 0.0f) N = -N;
      reading.terms = evaluate(pick.P, N);
      reading.normal = N;
      reading.mirror = mirror(pick.P, N);
      reading.where = N_("Phong: the formula at this pixel, with the interpolated normal");
      break;
    }
    case Shading::gouraud: {  // gouraud.vert/.frag: both sides per vertex, interpolated
      const bool back = glm::dot(pick.face, pick.N) * glm::dot(pick.face, eye - pick.P) < 0.0f;
      TermValues at[3];
      for (int i = 0; i < 3; ++i) {
        const glm::vec3 N = glm::normalize(mesh.normals[index[i]]);
        at[i] = evaluate(mesh.positions[index[i]], back ? -N : N);
        at[i].ambient = evaluate(mesh.positions[index[i]], N).ambient;  // the front side's
        // gouraud.vert: R per vertex, interpolated like the colours.
        reading.mirror += pick.barycentric[i] * mirror(mesh.positions[index[i]], back ? -N : N);
      }
      reading.terms = blend(at[0], at[1], at[2], pick.barycentric);
      reading.normal = back ? -pick.N : pick.N;
      reading.where = N_("Gouraud: the formula at the 3 vertices, interpolated (angles too)");
      break;
    }
    case Shading::flat: {  // flat.vert: once at the centroid, face normal toward the eye
      const glm::vec3 middle = (mesh.positions[index[0]] + mesh.positions[index[1]] +
                                mesh.positions[index[2]]) / 3.0f;
      glm::vec3 N = pick.face;
      if (glm::dot(N, eye - middle) < 0.0f) N = -N;
      reading.terms = evaluate(middle, N);
      reading.normal = N;
      reading.mirror = mirror(middle, N);  // flat.vert: once per triangle (the texture per pixel)
      barycentric = glm::vec2(1.0f / 3.0f);  // flat.vert: COLOR_0 at the centroid
      reading.where = N_("flat: the formula once, at the triangle's centroid with its face normal");
      break;
    }
  }
  if (options.terms.textures && scene.shown_texture(mesh, material) >= 0)
    // Bilinear at the finest mip level (the GPU also blends mip levels far away, so there the
    // two differ slightly).
    reading.kd_texture = scene.textures[size_t(material.kd_texture)].sample(uv);
  reading.vertex_colour = mesh.colour_at(size_t(pick.triangle), barycentric);
  // lighting.glsl write_fragment(): + kr Ir, then the fog at this pixel's distance.
  add_reflection_and_fog(reading.terms, material, options, lookups.reflection, reading.mirror,
                         glm::length(pick.P - eye));
  reading.transparent = options.transparency.on && (material.kt.r > 0 || material.kt.g > 0 || material.kt.b > 0);
  reading.sum = radiance(reading.terms, material, options, reading.kd_texture * reading.vertex_colour,
                         reading.emitting_side);
  return reading;
}

// ---- [json] ------------------------------------------------------------------------------------
nlohmann::json to_json(const Scene& scene, const InspectorReading& r) {
  auto rgb = [](const Rgb& c) { return nlohmann::json::array({c.r, c.g, c.b}); };
  const Material& material = material_of(scene, r.pick);
  nlohmann::json lights = nlohmann::json::array();
  for (const LightTerm& t : r.terms.lights)
    lights.push_back({{"name", t.name}, {"lit", t.lit}, {"theta_deg", t.theta * degrees},
                      {"alpha_deg", t.alpha * degrees}, {"d", t.d}, {"f_att", t.f_att},
                      {"spot", t.spot}, {"S", t.S}, {"IL", rgb(t.IL)}, {"I_D", rgb(t.diffuse)},
                      {"I_S", rgb(t.specular)}});
  return {{"pixel", {r.pick.x, r.pick.y}},
          {"mesh", scene.meshes[size_t(r.pick.mesh)].name},
          {"triangle", r.pick.triangle},
          {"material", material.name},
          {"shading", to_string(r.shading)},
          {"P", {r.pick.P.x, r.pick.P.y, r.pick.P.z}},
          {"N", {r.normal.x, r.normal.y, r.normal.z}},
          {"I_A", rgb(r.terms.ambient)},
          {"I_D", rgb(r.terms.diffuse)},
          {"I_S", rgb(r.terms.specular)},
          {"kd_texture", rgb(r.kd_texture)},
          {"vertex_colour", rgb(r.vertex_colour)},
          {"Le", rgb(r.emitting_side ? material.emission : Rgb(0.0f))},
          {"lights", lights},
          {"kr_Ir", rgb(r.terms.reflection)},
          {"fog_factor", r.terms.fog},
          {"transparent", r.transparent},
          {"sum", rgb(r.sum)},
          {"gl_pixel", rgb(r.gl_pixel)}};
}

// ---- [the window] ------------------------------------------------------------------------------
namespace {

void rgb_cell(const Rgb& c) { ImGui::Text("%.4g %.4g %.4g", double(c.r), double(c.g), double(c.b)); }

// A row of a two-column table: a quantity's name and its RGB value.
void row(const char* name, const Rgb& value) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name);
  ImGui::TableNextColumn();
  rgb_cell(value);
}

}  // namespace

void draw_inspector(const Scene& scene, const InspectorReading& r, bool& open) {
  const Mesh& mesh = scene.meshes[size_t(r.pick.mesh)];
  const Material& material = material_of(scene, r.pick);
  ImGui::SetNextWindowSize(ImVec2(0, 0), ImGuiCond_Always);  // fit the table
  if (!ImGui::Begin(tr("Inspector"), &open, ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_HorizontalScrollbar)) {
    ImGui::End();
    return;
  }
  ImGui::Text(tr("pixel (%d, %d): %s, triangle %d, material \"%s\""), r.pick.x, r.pick.y,
              mesh.name.c_str(), r.pick.triangle, material.name.c_str());
  ImGui::Text("P = (%.3f, %.3f, %.3f)   N = (%.3f, %.3f, %.3f)", double(r.pick.P.x),
              double(r.pick.P.y), double(r.pick.P.z), double(r.normal.x), double(r.normal.y),
              double(r.normal.z));
  ImGui::TextDisabled("%s", tr(r.where.c_str()));
  // Each column as wide as its text: a window too narrow for the table scrolls it sideways.
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | kTextWideTable;
  if (ImGui::BeginTable("terms", 8, flags, ImVec2(0.0f, text_wide_table_height(1 + int(r.terms.lights.size()))))) {
    for (const char* heading : {tr("light"), "theta", "alpha", "d", "f_att", "S", "I_D", "I_S"})
      ImGui::TableSetupColumn(heading);
    ImGui::TableHeadersRow();
    for (const LightTerm& t : r.terms.lights) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      if (t.lit) ImGui::TextUnformatted(t.name.c_str());
      else ImGui::TextDisabled(tr("%s (behind)"), t.name.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.1f°", double(t.theta * degrees));
      ImGui::TableNextColumn();
      ImGui::Text("%.1f°", double(t.alpha * degrees));
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", double(t.d));
      ImGui::TableNextColumn();
      ImGui::Text("%.4g", double(t.f_att));
      ImGui::TableNextColumn();
      if (t.S < 1.0f) ImGui::TextColored(ImVec4(0.8f, 0.7f, 1.0f, 1.0f), "%.2g", double(t.S));  // blocked
      else ImGui::TextDisabled("1");
      ImGui::TableNextColumn();
      rgb_cell(t.diffuse);
      ImGui::TableNextColumn();
      rgb_cell(t.specular);
    }
    ImGui::EndTable();
  }
  const int sum_rows = 5 + int(r.kd_texture != Rgb(1.0f)) + int(r.vertex_colour != Rgb(1.0f)) +
                       int(r.emitting_side && material.is_emissive()) + int(r.terms.reflection != Rgb(0.0f)) +
                       int(r.terms.fog < 1.0f) + int(r.transparent);
  if (ImGui::BeginTable("sum", 2, flags, ImVec2(0.0f, text_wide_table_height(sum_rows)))) {
    row("I_A = Ia ka", r.terms.ambient);
    row(tr("sum I_D"), r.terms.diffuse);
    if (r.kd_texture != Rgb(1.0f)) row(tr("kd texture"), r.kd_texture);
    if (r.vertex_colour != Rgb(1.0f)) row(tr("kd vertex colour (COLOR_0)"), r.vertex_colour);
    row(tr("sum I_S"), r.terms.specular);
    if (r.emitting_side && material.is_emissive()) row("Le", material.emission);
    if (r.terms.reflection != Rgb(0.0f)) row(tr("kr Ir (reflection map)"), r.terms.reflection);
    if (r.terms.fog < 1.0f) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(tr("fog f, C_fog"));
      ImGui::TableNextColumn();
      ImGui::Text("%.4g   %.3g %.3g %.3g", double(r.terms.fog), double(r.terms.fog_colour.r),
                  double(r.terms.fog_colour.g), double(r.terms.fog_colour.b));
    }
    row(tr("I (CPU, the formula)"), r.sum);
    row(tr("I (GPU, the pixel)"), r.gl_pixel);
    if (r.transparent) row(tr("f kt It (GPU - CPU: behind)"), r.gl_pixel - r.sum);
    ImGui::EndTable();
  }
  ImGui::End();
}

// Slide 39's quantities of one patch, as the solver holds them: what it emits, reflects, has
// shot and has still to shoot, and what step 3 displays (B = radiosity + unshot, drawn as B/pi).
void draw_patch_inspector(const Scene& scene, const PatchReading& r, bool& open) {
  ImGui::SetNextWindowSize(ImVec2(0, 0), ImGuiCond_Always);  // fit the table
  if (!ImGui::Begin(tr("Inspector: patch"), &open, ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_HorizontalScrollbar)) {
    ImGui::End();
    return;
  }
  ImGui::Text(tr("element %zu of patch %zu (%s), triangle %d, material \"%s\""), r.patch, r.shooter,
              scene.meshes[size_t(r.mesh)].name.c_str(), r.triangle, r.material.c_str());
  ImGui::Text(tr("centre (%.3f, %.3f, %.3f)   N = (%.3f, %.3f, %.3f)"), double(r.centre.x), double(r.centre.y),
              double(r.centre.z), double(r.normal.x), double(r.normal.y), double(r.normal.z));
  ImGui::TextDisabled(tr("after %d shots; exitances in W/m², radiance in W/(m² sr)"), r.shots);
  // Each column as wide as its text: a window too narrow for the table scrolls it sideways.
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | kTextWideTable;
  if (ImGui::BeginTable("patch", 2, flags, ImVec2(0.0f, text_wide_table_height(7)))) {
    row(tr("E = π Le (emitted)"), r.E);
    row("ρ = kd", r.rho);
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(tr("area A"));
    ImGui::TableNextColumn();
    ImGui::Text("%.4g m²", double(r.area));
    row(tr("radiosity (shot)"), r.radiosity);
    row(tr("unshot"), r.unshot);
    row(tr("B = radiosity + unshot"), r.B);
    row(tr("B / π (drawn)"), r.radiance);
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace luz::app
