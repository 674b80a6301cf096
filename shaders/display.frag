#version 330 core
// The viewer's display pass: the float radiance the local models drew, shown exactly as a PNG
// of `luz render` encodes it: radiance x 2^exposure, the sRGB transfer curve (srgb.glsl),
// clamped. Pixel for pixel: texelFetch, no filter.
uniform sampler2D u_radiance;
uniform vec2 u_origin;   // the viewport's lower-left corner in the window, whole pixels
uniform float u_scale;   // 2^exposure

layout(location = 0) out vec4 frag_colour;

void main() {
  vec3 L = texelFetch(u_radiance, ivec2(gl_FragCoord.xy - u_origin), 0).rgb * u_scale;
  frag_colour = vec4(srgb_encode(L), 1.0);
}
