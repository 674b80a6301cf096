#version 330 core
// The last shot's hemicube (slide 37) unfolded into a cross, its five item-buffer faces in false
// colours: one colour per patch ID, black where no patch (or a patch's back) was seen.
//
// The cross is 4 x 4 units of the top face's coordinates: the top face (half-width 1) in the
// middle, each half side face folded out from the edge it shares with the top face, with its
// horizon (height z = 0) at the outer edge. For a point (X, Y) of the cross we find the direction
// d it shows, in the hemicube's frame (t, b, n), then where d lands in that face's viewport of the
// atlas (Hemicube::face_rect), using the faces' cameras as hemicube.cpp sets them up:
//   face  forward  up   right = forward x up
//   0     n        b    -t
//   1     t        n    -b
//   2     -t       n    b
//   3     b        n    t
//   4     -b       n    -t
// The top face's right is -t, so +t is on the cross's left: X < -1 is face 1, X > 1 face 2,
// Y > 1 face 3 (+b, the top face's up), Y < -1 face 4.
uniform usampler2D u_items;  // the atlas, IDs + 1 (GL_R32UI, row 0 at the bottom)
uniform vec4 u_faces[5];     // face_rect(k): x, y, width, height in atlas pixels (whole numbers)
uniform vec2 u_size;         // the output's size, pixels

layout(location = 0) out vec4 frag_colour;

// A well-mixed integer hash (Chris Wellons' "lowbias32"), so neighbouring IDs get unrelated
// colours and the patches stand apart.
uint hash(uint x) {
  x ^= x >> 16; x *= 0x7feb352du;
  x ^= x >> 15; x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

vec3 false_colour(uint id) {
  uint h = hash(id);
  vec3 c = vec3(float(h & 255u), float((h >> 8) & 255u), float((h >> 16) & 255u)) / 255.0;
  return 0.25 + 0.75 * c;  // never near black, which means "nothing"
}

void main() {
  vec2 XY = gl_FragCoord.xy / u_size * 4.0 - 2.0;  // the cross, -2 .. 2 across
  float X = XY.x, Y = XY.y;
  int face;
  vec3 d;  // the direction shown, in (t, b, n)
  if (abs(X) <= 1.0 && abs(Y) <= 1.0) { face = 0; d = vec3(-X, Y, 1.0); }
  else if (abs(Y) <= 1.0 && X < -1.0) { face = 1; d = vec3(1.0, Y, X + 2.0); }
  else if (abs(Y) <= 1.0 && X > 1.0)  { face = 2; d = vec3(-1.0, Y, 2.0 - X); }
  else if (abs(X) <= 1.0 && Y > 1.0)  { face = 3; d = vec3(-X, 1.0, 2.0 - Y); }
  else if (abs(X) <= 1.0 && Y < -1.0) { face = 4; d = vec3(-X, -1.0, Y + 2.0); }
  else { frag_colour = vec4(0.0); return; }  // the corners of the cross: no face

  const vec3 forward[5] = vec3[5](vec3(0, 0, 1), vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0));
  const vec3 right[5] = vec3[5](vec3(-1, 0, 0), vec3(0, -1, 0), vec3(0, 1, 0), vec3(1, 0, 0), vec3(-1, 0, 0));
  const vec3 up[5] = vec3[5](vec3(0, 1, 0), vec3(0, 0, 1), vec3(0, 0, 1), vec3(0, 0, 1), vec3(0, 0, 1));
  // The face's image coordinates: -1 .. 1 across; up -1 .. 1 on the top face, 0 .. 1 (z) on a side.
  float along = dot(d, forward[face]);
  vec2 image = vec2(dot(d, right[face]), dot(d, up[face])) / along;
  ivec4 r = ivec4(u_faces[face]);
  vec2 unit = face == 0 ? (image + 1.0) * 0.5 : vec2((image.x + 1.0) * 0.5, image.y);
  ivec2 texel = ivec2(r.xy) + clamp(ivec2(unit * vec2(r.zw)), ivec2(0), r.zw - 1);
  uint id = texelFetch(u_items, texel, 0).r;
  vec3 colour = id == 0u ? vec3(0.0) : false_colour(id);
  // A thin grey line where the side faces fold from the top face.
  vec2 pixel = 4.0 / u_size;
  if (abs(abs(X) - 1.0) < pixel.x && abs(Y) <= 1.0 || abs(abs(Y) - 1.0) < pixel.y && abs(X) <= 1.0)
    colour = vec3(0.6);
  frag_colour = vec4(colour, 1.0);
}
