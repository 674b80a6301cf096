#version 330 core
// The viewer's display pass: the float radiance the local models drew, shown exactly as a PNG
// of `luz render` encodes it (SCENES.md "Image output"): radiance x 2^exposure, the sRGB
// transfer curve (core/image.cpp srgb_encode), clamped. Pixel for pixel: texelFetch, no filter.
uniform sampler2D u_radiance;
uniform vec2 u_origin;   // the viewport's lower-left corner in the window, whole pixels
uniform float u_scale;   // 2^exposure

layout(location = 0) out vec4 frag_colour;

float srgb_encode(float linear) {
  if (!(linear > 0.0)) return 0.0;
  if (linear >= 1.0) return 1.0;
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

void main() {
  vec3 L = texelFetch(u_radiance, ivec2(gl_FragCoord.xy - u_origin), 0).rgb * u_scale;
  frag_colour = vec4(srgb_encode(L.r), srgb_encode(L.g), srgb_encode(L.b), 1.0);
}
