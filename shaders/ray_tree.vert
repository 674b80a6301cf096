#version 330 core
// Slide 24's ray tree drawn over the scene: each ray a segment from its origin to its hit (or to
// the light, or out of the scene), widened here into a quad a few pixels wide, since a core
// profile draws lines one pixel wide at most. Each segment comes as six vertices (two
// triangles), each knowing both ends, which end it is and which side of the line.
uniform mat4 u_view_projection;
uniform vec2 u_viewport;     // pixels
uniform float u_half_width;  // pixels

layout(location = 0) in vec3 a_from;
layout(location = 1) in vec3 a_to;
layout(location = 2) in vec2 a_end_side;   // x: 0 at a_from, 1 at a_to; y: -1 or +1
layout(location = 3) in vec4 a_colour;     // rgb (display, sRGB-encoded), a: 1 dashed, 0 solid

out vec3 v_colour;
flat out float v_dashed;
out float v_along;  // metres from the ray's origin, for the dashes

void main() {
  vec4 p = u_view_projection * vec4(a_from, 1.0);
  vec4 q = u_view_projection * vec4(a_to, 1.0);
  float length_m = distance(a_from, a_to);
  // A ray that starts at the eye (a primary ray) or behind it has no screen position there:
  // clip the segment to the near plane (z >= -w in clip space) before projecting it.
  float dp = p.z + p.w, dq = q.z + q.w;
  float tp = 0.0, tq = 1.0;
  if (dp < 0.0 && dq < 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // all behind the eye: outside the view
    return;
  }
  if (dp < 0.0) { tp = dp / (dp - dq); p = mix(p, q, tp); }
  if (dq < 0.0) { tq = dp / (dp - dq); q = mix(p, q, tq); }  // only one end can be behind

  vec2 sp = p.xy / p.w * 0.5 * u_viewport, sq = q.xy / q.w * 0.5 * u_viewport;
  vec2 along = sq - sp;
  vec2 dir = length(along) > 1e-6 ? normalize(along) : vec2(1.0, 0.0);
  vec2 normal = vec2(-dir.y, dir.x);
  vec4 here = a_end_side.x < 0.5 ? p : q;
  // Offset in pixels, taken back to clip space (x w / half the viewport).
  here.xy += normal * a_end_side.y * u_half_width / (0.5 * u_viewport) * here.w;
  gl_Position = here;
  v_colour = a_colour.rgb;
  v_dashed = a_colour.a;
  v_along = mix(tp, tq, a_end_side.x) * length_m;
}
