#version 330 core
// Writes patch ID + 1 (0 = nothing seen). A patch seen from behind writes 0 but still fills
// the depth buffer: patches emit and receive only on their front side, and the back of a wall
// must still hide what lies behind it (culling back faces instead would let light through).
#ifdef LUZ_GLSL_ES
flat in uint v_patch;  // item_buffer.vert's gl_VertexID / 3 of the unindexed list
#endif

out uint frag_id;

uint patch_index() {
#ifdef LUZ_GLSL_ES
  return v_patch;
#else
  return uint(gl_PrimitiveID);
#endif
}

void main() {
  frag_id = gl_FrontFacing ? patch_index() + 1u : 0u;
}
