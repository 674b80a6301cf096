#version 330 core
// The ray tree's colours are meant for the screen, but the viewer draws them into the picture's
// radiance, which the display pass then scales by 2^exposure and encodes as sRGB: so the colour
// is decoded and divided by that scale here, to come out on screen as chosen.
uniform float u_scale;      // 2^exposure, as the display pass
uniform float u_dash;       // metres per dash and gap (blocked shadow rays)
uniform float u_dim;        // 1 where the ray is in view, less where a surface hides it

in vec3 v_colour;
flat in float v_dashed;
in float v_along;

layout(location = 0) out vec4 frag_colour;

float srgb_decode(float c) {
  return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

void main() {
  if (v_dashed > 0.5 && fract(v_along / u_dash) > 0.5) discard;
  vec3 c = v_colour * u_dim;
  frag_colour = vec4(vec3(srgb_decode(c.r), srgb_decode(c.g), srgb_decode(c.b)) / u_scale, 1.0);
}
