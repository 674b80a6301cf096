#version 330 core
// Writes patch ID + 1 (0 = nothing seen). A patch seen from behind writes 0 but still fills
// the depth buffer: patches emit and receive only on their front side, and the back of a wall
// must still hide what lies behind it (culling back faces instead would let light through).
out uint frag_id;

void main() {
  frag_id = gl_FrontFacing ? uint(gl_PrimitiveID) + 1u : 0u;
}
