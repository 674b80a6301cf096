#version 330 core
// Gouraud shading: the vertex colours arrive interpolated; the kd texture is applied here, per
// fragment, as fixed-function GL's GL_MODULATE did (per vertex it would blur to nothing).
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in vec3 v_ambient;
in vec3 v_front_diffuse;
in vec3 v_front_specular;
in vec3 v_back_diffuse;
in vec3 v_back_specular;

layout(location = 0) out vec4 frag_radiance;

void main() {
  bool back = viewer_sees_back(v_position, v_normal);  // two-sided lighting
  Terms terms = back ? Terms(v_ambient, v_back_diffuse, v_back_specular)
                     : Terms(v_ambient, v_front_diffuse, v_front_specular);
  frag_radiance = vec4(radiance(terms, v_uv, gl_FrontFacing), 1.0);
}
