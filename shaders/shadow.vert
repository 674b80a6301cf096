#version 330 core
// Shadow maps (local/shadow_maps.h): the scene's triangles as one light sees them. Meshes are
// already in world space.
layout(location = 0) in vec3 a_position;

uniform mat4 u_view_projection;  // world -> this map's clip space

out vec3 v_position;

void main() {
  v_position = a_position;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
