#pragma once
// The inspector: for the pixel the teacher clicked, each term of the local formula (I_A, and I_D,
// I_S per light with theta, alpha, d and f_att) and their sum, computed on the CPU by
// local/local_terms.h the way the active shading model computes it, beside the value the GPU
// drew there.
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "app/viewer/picking.h"
#include "app/common/patch_reading.h"
#include "core/scene.h"
#include "local/local_options.h"
#include "local/local_terms.h"

namespace luz::app {

struct InspectorReading {
  Pick pick;
  Shading shading = Shading::phong;
  std::string where;              // how the shading model evaluates this pixel, one sentence
  glm::vec3 normal{0.0f};         // the normal the formula used, turned toward the viewer
  TermValues terms;
  Rgb kd_texture{1.0f};           // kd's texture factor at the pixel (1 without a texture)
  Rgb vertex_colour{1.0f};        // COLOR_0 where the shading model reads it (1 without one)
  bool emitting_side = false;     // the front side of the triangle faces the viewer
  glm::vec3 mirror{0.0f};         // R, the mirror direction the reflection map is read along
  bool transparent = false;       // kt > 0 with transparency on: the GPU adds kt * (pixel behind)
  Rgb sum{0.0f};                  // I = I_A + I_D * texture * COLOR_0 + I_S (+ Le) + kr Ir, fogged
  Rgb gl_pixel{0.0f};             // what the GPU drew at the pixel (linear radiance)
};

// What the renderer's last draw looked up besides the formula: its shadow maps (nullptr when
// shadows were off) and the picked object's reflection (LocalRenderer::shadow_lookup(),
// reflection_lookup()).
struct DrawnLookups {
  const ShadowLookup* shadows = nullptr;
  ReflectionLookup reflection;
};

// Evaluates the terms at `pick` as `options.shading` does (Phong: at the pixel; Gouraud: at the
// triangle's vertices, interpolated; flat: once at the centroid with the face normal).
InspectorReading read_terms(const Scene& scene, std::span<const AreaLight> area_lights,
                            const Pick& pick, const LocalOptions& options,
                            const DrawnLookups& lookups = {});

nlohmann::json to_json(const Scene& scene, const InspectorReading& reading);

// The inspector window (Dear ImGui). `open` goes false when the user closes it.
void draw_inspector(const Scene& scene, const InspectorReading& reading, bool& open);

// Radiosity's inspector: the clicked patch's E, rho, area, radiosity, unshot, B and B/pi.
void draw_patch_inspector(const Scene& scene, const PatchReading& reading, bool& open);

}  // namespace luz::app
