#version 330 core
// The viewer's pick pass (the inspector): the same world-space triangles as the local models,
// unindexed (gl/face_buffers.h), so that vertex i belongs to triangle i / 3: the triangle's
// number without gl_PrimitiveID, which GLSL ES (the page's) lacks.
layout(location = 0) in vec3 a_position;

uniform mat4 u_view_projection;

flat out int v_triangle;

void main() {
  v_triangle = gl_VertexID / 3;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
