#version 330 core
// Flat shading: the triangle's one colour, computed in flat.geom (the fog, a matter of the
// distance to the eye, per fragment).
flat in vec3 g_ambient;
flat in vec3 g_diffuse;
flat in vec3 g_specular;
flat in vec2 g_uv;
flat in vec3 g_colour;
flat in vec3 g_mirror;  // R at the centroid
in vec3 g_position;

void main() {
  kd_colour = g_colour;
  write_fragment(Terms(g_ambient, g_diffuse, g_specular), g_uv, gl_FrontFacing, g_mirror, g_position);
}
