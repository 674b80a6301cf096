#version 330 core
// Phong shading: the normals are interpolated and the formula is evaluated per fragment.
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in vec3 v_colour;

void main() {
  vec3 N = normalize(v_normal);  // interpolation shortens it
  if (viewer_sees_back(v_position, N)) N = -N;  // two-sided lighting
  kd_colour = v_colour;
  write_fragment(local_model(v_position, N), v_uv, gl_FrontFacing, mirror_direction(v_position, N),
                 v_position);
}
