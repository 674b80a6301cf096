#version 330 core
// The viewer's pick pass (the inspector): the same world-space triangles as the local models.
layout(location = 0) in vec3 a_position;

uniform mat4 u_view_projection;

void main() { gl_Position = u_view_projection * vec4(a_position, 1.0); }
