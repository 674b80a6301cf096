#version 330 core
// Flat shading: the triangle's one colour, computed in flat.geom (flat.vert in GLSL ES), times the
// textures at this fragment (the fog, a matter of the distance to the eye, per fragment too).
flat in vec3 g_ambient;
flat in vec3 g_diffuse;
flat in vec3 g_specular;
in vec2 g_uv;
flat in vec3 g_colour;
flat in vec3 g_mirror;  // R at the centroid
in vec3 g_position;
#if LUZ_DISPLAY_OUTPUT
flat in vec3 g_displayed_front;  // without fog, what the window shows: flat.geom's
flat in vec3 g_displayed_back;
#endif

void main() {
  kd_colour = g_colour;
  write_fragment(Terms(g_ambient, g_diffuse, g_specular), g_uv, gl_FrontFacing, g_mirror, g_position);
#if LUZ_DISPLAY_OUTPUT
  if (fog_mode == FOG_OFF && !has_kd_texture && !has_emission_texture)
    frag_display = vec4(gl_FrontFacing ? g_displayed_front : g_displayed_back, 1.0);
#endif
}
