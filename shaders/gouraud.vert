#version 330 core
// Gouraud shading: the formula per vertex, with the vertex normal; the rasteriser interpolates
// the resulting colours. Both sides of the surface are lit here (with N and -N) because only the
// fragment knows which side of its triangle the viewer sees (two-sided lighting).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec3 a_colour;  // COLOR_0 (white without)

uniform mat4 u_view_projection;

out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
out vec3 v_colour;
out vec3 v_ambient;        // I_A
out vec3 v_front_diffuse;  // I_D, I_S on the side the normal points to
out vec3 v_front_specular;
out vec3 v_back_diffuse;   // I_D, I_S on the other side
out vec3 v_back_specular;
out vec3 v_front_mirror;   // R per vertex, interpolated (as fixed-function GL's reflection texgen)
out vec3 v_back_mirror;

void main() {
  vec3 N = normalize(a_normal);
  Terms front = local_model(a_position, N);
  Terms back = local_model(a_position, -N);
  v_ambient = front.ambient;
  v_front_diffuse = front.diffuse;
  v_front_specular = front.specular;
  v_back_diffuse = back.diffuse;
  v_back_specular = back.specular;
  v_front_mirror = mirror_direction(a_position, N);
  v_back_mirror = mirror_direction(a_position, -N);

  v_position = a_position;
  v_normal = a_normal;
  v_uv = a_uv;
  v_colour = a_colour;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
