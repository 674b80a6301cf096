#version 330 core
// Flat shading: the triangle's one colour, computed in flat.geom.
flat in vec3 g_ambient;
flat in vec3 g_diffuse;
flat in vec3 g_specular;
flat in vec2 g_uv;

layout(location = 0) out vec4 frag_radiance;

void main() {
  frag_radiance = vec4(radiance(Terms(g_ambient, g_diffuse, g_specular), g_uv, gl_FrontFacing), 1.0);
}
