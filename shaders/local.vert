#version 330 core
// Phong shading: pass the world-space vertex on; the lighting happens per fragment in
// phong.frag. Meshes are already in world space.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec3 a_colour;  // COLOR_0 (white without)

uniform mat4 u_view_projection;

out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
out vec3 v_colour;

void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_uv = a_uv;
  v_colour = a_colour;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
