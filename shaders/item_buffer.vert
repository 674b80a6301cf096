#version 330 core
// Radiosity item buffer: the patches seen from a hemicube face (or a light's cube face).
// Patches are drawn as one triangle list, patch i = triangle i, so no ID attribute is needed:
// on the desktop the list is indexed over the shared vertices and the fragment shader names the
// patch by gl_PrimitiveID; GLSL ES 3.00 (the page) has none, so there the list is unindexed,
// three vertices per patch, and the vertex names it by gl_VertexID / 3 (radiosity/item_buffer.cpp).
layout(location = 0) in vec3 a_position;

uniform mat4 u_view_projection;

#ifdef LUZ_GLSL_ES
flat out uint v_patch;
#endif

void main() {
#ifdef LUZ_GLSL_ES
  v_patch = uint(gl_VertexID / 3);
#endif
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
