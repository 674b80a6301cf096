// The cameras and KHR_lights_punctual lights of glTF nodes (SCENES.md "Cameras", "Lights").
//
// Both take their pose from the node's world matrix: a camera looks down the node's -Z with +Y
// up, a light shines down the node's -Z. Values are checked as the float the program uses.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "io/gltf_internal.h"

namespace luz::io::gltf {

namespace {

float finite_float(const Context& ctx, double value, const std::string& what) {
  const float f = float(value);
  if (!std::isfinite(f)) ctx.fail(ErrorKind::not_finite, trf("{} ({}) is not finite", what, value));
  return f;
}

}  // namespace

// A perspective camera at the node; its matrix loses any scale (Camera::to_world is rigid).
void add_camera(const Context& ctx, const tinygltf::Node& node, const glm::dmat4& to_world,
                Scene& scene) {
  const tinygltf::Camera& source = ctx.model.cameras[size_t(node.camera)];
  const std::string what = describe("camera", size_t(node.camera), source.name);
  if (source.type != "perspective") {
    ctx.warn(trf("{}: {} cameras are not supported; skipped", what, source.type));
    return;
  }
  const tinygltf::PerspectiveCamera& p = source.perspective;
  Camera camera;
  camera.name = !source.name.empty() ? source.name
                : !node.name.empty() ? node.name
                                     : trf("camera {}", scene.cameras.size());
  camera.yfov = finite_float(ctx, p.yfov, what + ": yfov");
  camera.aspect = finite_float(ctx, p.aspectRatio, what + ": aspectRatio");
  camera.znear = finite_float(ctx, p.znear, what + ": znear");
  camera.zfar = finite_float(ctx, p.zfar, what + ": zfar");
  if (!(camera.yfov > 0.0f && camera.yfov < std::numbers::pi_v<float>))
    ctx.fail(ErrorKind::bad_value, trf("{}: yfov {} is not in (0, pi)", what, camera.yfov));
  if (!(camera.znear > 0.0f)) ctx.fail(ErrorKind::bad_value, trf("{}: znear {} is not positive", what, camera.znear));
  if (camera.zfar != 0.0f && !(camera.zfar > camera.znear))
    ctx.fail(ErrorKind::bad_value, trf("{}: zfar {} is not beyond znear {}", what, camera.zfar, camera.znear));
  if (camera.aspect < 0.0f) ctx.fail(ErrorKind::bad_value, trf("{}: aspectRatio {} is negative", what, camera.aspect));

  glm::mat4 m(to_world);
  for (int axis = 0; axis < 3; ++axis) {
    const float length = glm::length(glm::vec3(m[axis]));
    if (!(length > 0.0f) || !std::isfinite(length))
      ctx.fail(ErrorKind::bad_value, trf("{}: its node's transform collapses an axis", what));
    m[axis] = glm::vec4(glm::vec3(m[axis]) / length, 0.0f);
  }
  camera.to_world = m;
  scene.cameras.push_back(camera);
}

// A KHR_lights_punctual light at the node, shining down the node's -Z.
void add_light(const Context& ctx, const tinygltf::Node& node, const std::string& node_what,
               const glm::dmat4& to_world, Scene& scene) {
  const tinygltf::Value* ref = extension(node.extensions, "KHR_lights_punctual");
  if (!ref) return;
  const tinygltf::Value* index_value = member(*ref, "light");
  if (!index_value || !index_value->IsNumber())
    ctx.fail(ErrorKind::bad_value, trf("{}: KHR_lights_punctual has no light index", node_what));
  const double index_number = index_value->GetNumberAsDouble();
  const int index = index_number >= -1.0 && index_number < 2e9 ? int(index_number) : -2;
  ctx.check_index(index, ctx.model.lights.size(), node_what + ": light", "lights");
  const tinygltf::Light& source = ctx.model.lights[size_t(index)];
  const std::string what = describe("light", size_t(index), source.name);

  Light light;
  light.name = !source.name.empty() ? source.name
               : !node.name.empty() ? node.name
                                    : trf("light {}", index);
  if (source.type == "point") light.type = LightType::point;
  else if (source.type == "spot") light.type = LightType::spot;
  else if (source.type == "directional") light.type = LightType::directional;
  else ctx.fail(ErrorKind::bad_value, trf("{}: type \"{}\" is unknown", what, source.type));

  Rgb color(1.0f);
  if (!source.color.empty()) {
    if (source.color.size() != 3) ctx.fail(ErrorKind::bad_value, trf("{}: color needs 3 numbers", what));
    for (int c = 0; c < 3; ++c) color[c] = finite_float(ctx, source.color[size_t(c)], what + ": color");
  }
  const float intensity = finite_float(ctx, source.intensity, what + ": intensity");
  if (intensity < 0.0f || color.r < 0.0f || color.g < 0.0f || color.b < 0.0f)
    ctx.fail(ErrorKind::bad_value, trf("{}: color and intensity must not be negative", what));
  // Candela read as W/sr (point, spot), lux as W/m^2 (directional): SCENES.md "Lights".
  light.intensity = color * intensity;
  if (!is_finite(light.intensity)) ctx.fail(ErrorKind::not_finite, trf("{}: color x intensity is infinite", what));
  if (std::max({light.intensity.r, light.intensity.g, light.intensity.b}) > kMaxEmitted)
    ctx.fail(ErrorKind::bad_value, trf("{}: color x intensity is above {:.0e}; sums of it would "
                                       "overflow", what, kMaxEmitted));

  const glm::mat4 m(to_world);
  light.position = glm::vec3(m[3]);
  const glm::vec3 down = -glm::vec3(m[2]);  // the node's -Z
  if (!(glm::length(down) > 0.0f) || !std::isfinite(glm::length(down)))
    ctx.fail(ErrorKind::bad_value, trf("{}: its transform gives the light no direction", node_what));
  light.direction = glm::normalize(down);

  if (light.type == LightType::spot) {
    light.inner_cone = finite_float(ctx, source.spot.innerConeAngle, what + ": innerConeAngle");
    light.outer_cone = finite_float(ctx, source.spot.outerConeAngle, what + ": outerConeAngle");
    if (!(light.inner_cone >= 0.0f && light.inner_cone <= light.outer_cone &&
          light.outer_cone <= 0.5f * std::numbers::pi_v<float>))
      ctx.fail(ErrorKind::bad_value, trf("{}: cones need 0 <= inner ({}) <= outer ({}) <= "
                                         "pi/2", what, light.inner_cone, light.outer_cone));
  }

  if (const tinygltf::Value* a = member(source.extras, "attenuation")) {
    const std::string field = what + ": extras.attenuation";
    if (!a->IsArray() || a->ArrayLen() != 3) ctx.fail(ErrorKind::bad_value, trf("{} must be [c0, c1, c2]", field));
    glm::vec3 c;
    for (int i = 0; i < 3; ++i) c[i] = read_number(ctx, a->Get(i), field);
    if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f || c.x + c.y + c.z <= 0.0f)
      ctx.fail(ErrorKind::bad_value, trf("{} must be non-negative and not all zero", field));
    light.attenuation.classroom = true;
    light.attenuation.c = c;
  }
  if (const tinygltf::Value* p = member(source.extras, "warn_exponent")) {
    light.warn_exponent = read_number(ctx, *p, what + ": extras.warn_exponent");
    if (light.warn_exponent < 0.0f) ctx.fail(ErrorKind::bad_value, trf("{}: extras.warn_exponent is negative", what));
    if (light.type != LightType::spot) ctx.warn(trf("{}: extras.warn_exponent only shapes spot lights; ignored", what));
  }
  scene.lights.push_back(light);
}

}  // namespace luz::io::gltf
