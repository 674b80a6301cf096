#version 330 core
// Flat shading: the formula evaluated once per triangle, at its centroid with its face
// (geometric) normal; the kd and emissive textures still modulate it per fragment, as
// fixed-function GL_FLAT with a modulating texture did (SCENES.md Units), so uv is interpolated.
// A geometry shader sees the whole triangle, which is what GL 3.3 offers for this.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 v_position[];
in vec3 v_normal[];
in vec2 v_uv[];
in vec3 v_colour[];

flat out vec3 g_ambient;
flat out vec3 g_diffuse;
flat out vec3 g_specular;
out vec2 g_uv;
flat out vec3 g_colour;  // COLOR_0 at the centroid
flat out vec3 g_mirror;
out vec3 g_position;
#if LUZ_DISPLAY_OUTPUT
// Without fog or a texture the triangle's one colour is one displayed value too, so the sRGB
// curve runs once per triangle instead of once per pixel: for the side that emits and the other
// (an emitter shows its Le on one side only, which the fragment knows).
flat out vec3 g_displayed_front;
flat out vec3 g_displayed_back;
#endif

void main() {
  // The centroid (named `middle`: "centroid" is a GLSL keyword).
  vec3 middle = (v_position[0] + v_position[1] + v_position[2]) / 3.0;
  vec3 face = cross(v_position[1] - v_position[0], v_position[2] - v_position[0]);
  float twice_area = length(face);
  if (twice_area <= 0.0) return;  // degenerate: it would cover no pixel anyway
  vec3 N = face / twice_area;
  if (dot(N, u_eye - middle) < 0.0) N = -N;  // two-sided lighting: face the viewer

  Terms terms = local_model(middle, N);
  vec2 uv = (v_uv[0] + v_uv[1] + v_uv[2]) / 3.0;  // for the displayed value of an untextured triangle
  vec3 colour = (v_colour[0] + v_colour[1] + v_colour[2]) / 3.0;
  vec3 mirror = mirror_direction(middle, N);
#if LUZ_DISPLAY_OUTPUT
  vec3 displayed_front = vec3(0.0), displayed_back = vec3(0.0);
  if (fog_mode == FOG_OFF && !has_kd_texture && !has_emission_texture) {
    kd_colour = colour;
    displayed_front = displayed(surface_radiance(terms, uv, true, mirror));
    displayed_back = displayed(surface_radiance(terms, uv, false, mirror));
  }
#endif

  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    g_ambient = terms.ambient;
    g_diffuse = terms.diffuse;
    g_specular = terms.specular;
    g_uv = v_uv[i];
    g_colour = colour;
    g_mirror = mirror;
    g_position = v_position[i];
#if LUZ_DISPLAY_OUTPUT
    g_displayed_front = displayed_front;
    g_displayed_back = displayed_back;
#endif
    EmitVertex();
  }
  EndPrimitive();
}
