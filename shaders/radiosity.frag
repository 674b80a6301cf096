#version 330 core
// A patch has radiosity only on its front side; its back shows black. With u_outline set, the
// patch edges are drawn in one colour (the second, wireframe pass).
in vec3 v_radiance;

uniform bool u_outline;
uniform vec3 u_outline_colour;
// A shooting patch to show in u_highlight_colour (the shooter): its elements are primitives
// u_highlight_first .. + u_highlight_count of the draw (count 0 for none).
uniform int u_highlight_first;
uniform int u_highlight_count;
uniform vec3 u_highlight_colour;

layout(location = 0) out vec4 frag_radiance;

void main() {
  if (u_outline) {
    frag_radiance = vec4(u_outline_colour, 1.0);
    return;
  }
  if (gl_PrimitiveID >= u_highlight_first &&
      gl_PrimitiveID < u_highlight_first + u_highlight_count) {
    frag_radiance = vec4(u_highlight_colour, 1.0);
    return;
  }
  frag_radiance = vec4(gl_FrontFacing ? v_radiance : vec3(0.0), 1.0);
}
