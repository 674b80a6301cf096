#version 330 core
// Shadow maps (local/shadow_maps.h): each texel keeps the nearest surface as the lookup in
// lighting.glsl shadow_factor() measures it: the distance from the light (cube and perspective
// maps), or dot(P, direction) along a directional light's rays (orthographic maps).
const int ORTHOGRAPHIC = 3;  // ShadowKind

uniform int u_kind;
uniform vec3 u_origin;     // the light's position
uniform vec3 u_direction;  // the way a directional light travels

in vec3 v_position;

layout(location = 0) out vec4 frag_distance;

void main() {
  float measured = u_kind == ORTHOGRAPHIC ? dot(v_position, u_direction) : length(v_position - u_origin);
  frag_distance = vec4(measured, 0.0, 0.0, 1.0);
}
