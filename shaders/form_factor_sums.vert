#version 330 core
// The hemicube's sums on the GPU: one point per atlas pixel (no vertex attributes; the vertex ID
// is the pixel). A pixel showing element j lands on texel j of the sums target, where additive
// blending adds its delta form factor to what the element's other pixels brought: F_ij.
uniform usampler2D u_items;   // element ID + 1 per pixel, 0 = nothing
uniform sampler2D u_weights;  // the pixel's delta form factor
uniform int u_sums_width;     // texels per row of the sums target
uniform vec2 u_sums_size;

flat out float v_delta_form_factor;

void main() {
  ivec2 atlas = textureSize(u_items, 0);
  ivec2 pixel = ivec2(gl_VertexID % atlas.x, gl_VertexID / atlas.x);
  uint id = texelFetch(u_items, pixel, 0).r;
  v_delta_form_factor = texelFetch(u_weights, pixel, 0).r;
  if (id == 0u) {
    gl_Position = vec4(2.0, 2.0, 0.0, 1.0);  // outside the view: the point is dropped
    return;
  }
  int j = int(id - 1u);
  vec2 texel_centre = vec2(j % u_sums_width, j / u_sums_width) + 0.5;
  gl_Position = vec4(2.0 * texel_centre / u_sums_size - 1.0, 0.0, 1.0);
}
