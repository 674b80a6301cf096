#version 330 core
// A patch has radiosity only on its front side; its back shows black. With u_outline set, the
// patch edges are drawn in one colour (the second, wireframe pass).
in vec3 v_radiance;
in vec2 v_uv;
flat in int v_element;  // radiosity.vert's gl_VertexID / 3: the element's index in the mesh

uniform bool u_outline;
uniform vec3 u_outline_colour;
// The solver gave the patch its kd texture's mean texel; the picture puts the texture's detail
// back, texel / mean (radiosity/texture_detail.h).
uniform bool u_textured;
uniform sampler2D u_kd_texture;
uniform vec3 u_inverse_mean;
// A shooting patch to show in u_highlight_colour (the shooter): its elements are primitives
// u_highlight_first .. + u_highlight_count of the elements (count 0 for none).
uniform int u_highlight_first;
uniform int u_highlight_count;
uniform vec3 u_highlight_colour;

layout(location = 0) out vec4 frag_radiance;

void main() {
  if (u_outline) {
    frag_radiance = vec4(u_outline_colour, 1.0);
    return;
  }
  if (v_element >= u_highlight_first && v_element < u_highlight_first + u_highlight_count) {
    frag_radiance = vec4(u_highlight_colour, 1.0);
    return;
  }
  vec3 detail = u_textured ? texture(u_kd_texture, v_uv).rgb * u_inverse_mean : vec3(1.0);
  frag_radiance = vec4(gl_FrontFacing ? v_radiance * detail : vec3(0.0), 1.0);
}
