#version 330 core
// Radiosity display: the solved radiance B/pi per vertex (Gouraud) or per patch (flat), already
// in the vertex colour; the rasteriser interpolates it (slide 39 step 3). A textured mesh's
// corners carry their texture coordinates. The elements are drawn unindexed, three vertices each
// in element order, so element i is gl_VertexID / 3 (GLSL ES 3.00 has no gl_PrimitiveID).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_radiance;
layout(location = 2) in vec2 a_uv;

uniform mat4 u_view_projection;

out vec3 v_radiance;
out vec2 v_uv;
flat out int v_element;

void main() {
  v_radiance = a_radiance;
  v_uv = a_uv;
  v_element = gl_VertexID / 3;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
