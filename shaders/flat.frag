#version 330 core
// Flat shading: the triangle's one colour, computed in flat.vert, times the textures at this
// fragment (the fog, a matter of the distance to the eye, per fragment too).
flat in vec3 v_ambient;
flat in vec3 v_diffuse;
flat in vec3 v_specular;
in vec2 v_uv;
flat in vec3 v_colour;
flat in vec3 v_mirror;  // R at the centroid
in vec3 v_position;
#if LUZ_DISPLAY_OUTPUT
flat in vec3 v_displayed_front;  // without fog, what the window shows: flat.vert's
flat in vec3 v_displayed_back;
#endif

void main() {
  kd_colour = v_colour;
  write_fragment(Terms(v_ambient, v_diffuse, v_specular), v_uv, gl_FrontFacing, v_mirror, v_position);
#if LUZ_DISPLAY_OUTPUT
  if (fog_mode == FOG_OFF && !has_kd_texture && !has_emission_texture)
    frag_display = vec4(gl_FrontFacing ? v_displayed_front : v_displayed_back, 1.0);
#endif
}
