#version 330 core
// Gouraud shading: the vertex colours arrive interpolated; the kd texture is applied here, per
// fragment, as fixed-function GL's GL_MODULATE did (per vertex it would blur to nothing).
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in vec3 v_colour;
in vec3 v_ambient;
in vec3 v_front_diffuse;
in vec3 v_front_specular;
in vec3 v_back_diffuse;
in vec3 v_back_specular;
in vec3 v_front_mirror;
in vec3 v_back_mirror;

void main() {
  bool back = viewer_sees_back(v_position, v_normal);  // two-sided lighting
  // Per component: GLSL ES forbids ?: on structures.
  Terms terms = Terms(v_ambient, back ? v_back_diffuse : v_front_diffuse, back ? v_back_specular : v_front_specular);
  kd_colour = v_colour;
  write_fragment(terms, v_uv, gl_FrontFacing, back ? v_back_mirror : v_front_mirror, v_position);
}
