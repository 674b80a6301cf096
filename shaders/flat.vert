#version 330 core
// Flat shading: the formula evaluated once per triangle, at its centroid with its face
// (geometric) normal; the kd and emissive textures still modulate it per fragment, as
// fixed-function GL_FLAT with a modulating texture did (SCENES.md Units), so uv is interpolated.
// Every vertex carries its whole triangle (gl/face_buffers.h, unindexed), so each of the three
// evaluates the same formula on the same corners and the `flat` outputs are the triangle's one
// colour whichever vertex GL takes them from. GLSL ES 3.00 (the page) has no geometry stage,
// and this needs none.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
layout(location = 4) in vec3 a_corner0;  // the triangle's corners, in its index order
layout(location = 5) in vec3 a_corner1;
layout(location = 6) in vec3 a_corner2;
layout(location = 7) in vec3 a_colour0;  // their COLOR_0 (white without)
layout(location = 8) in vec3 a_colour1;
layout(location = 9) in vec3 a_colour2;

uniform mat4 u_view_projection;

flat out vec3 v_ambient;
flat out vec3 v_diffuse;
flat out vec3 v_specular;
out vec2 v_uv;
flat out vec3 v_colour;  // COLOR_0 at the centroid
flat out vec3 v_mirror;
out vec3 v_position;
#if LUZ_DISPLAY_OUTPUT
// Without fog or a texture the triangle's one colour is one displayed value too, so the sRGB
// curve runs once per vertex instead of once per pixel: for the side that emits and the other
// (an emitter shows its Le on one side only, which the fragment knows).
flat out vec3 v_displayed_front;
flat out vec3 v_displayed_back;
#endif

void main() {
  v_uv = a_uv;
  v_position = a_position;
  gl_Position = u_view_projection * vec4(a_position, 1.0);

  // The centroid (named `middle`: "centroid" is a GLSL keyword).
  vec3 middle = (a_corner0 + a_corner1 + a_corner2) / 3.0;
  vec3 face = cross(a_corner1 - a_corner0, a_corner2 - a_corner0);
  float twice_area = length(face);
  if (twice_area <= 0.0) {  // degenerate: all three vertices land outside the clip volume
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  vec3 N = face / twice_area;
  if (dot(N, u_eye - middle) < 0.0) N = -N;  // two-sided lighting: face the viewer

  Terms terms = local_model(middle, N);
  vec2 uv = a_uv;  // for the displayed value of an untextured triangle (no texture reads it)
  vec3 colour = (a_colour0 + a_colour1 + a_colour2) / 3.0;
  vec3 mirror = mirror_direction(middle, N);
  v_ambient = terms.ambient;
  v_diffuse = terms.diffuse;
  v_specular = terms.specular;
  v_colour = colour;
  v_mirror = mirror;
#if LUZ_DISPLAY_OUTPUT
  v_displayed_front = vec3(0.0);
  v_displayed_back = vec3(0.0);
  if (fog_mode == FOG_OFF && !has_kd_texture && !has_emission_texture) {
    kd_colour = colour;
    v_displayed_front = displayed(surface_radiance(terms, uv, true, mirror));
    v_displayed_back = displayed(surface_radiance(terms, uv, false, mirror));
  }
#endif
}
