#version 330 core
// Radiosity item buffer: the patches seen from a hemicube face (or a light's cube face).
// Patches are drawn as one triangle list, patch i = triangle i, so the fragment
// shader names the patch by gl_PrimitiveID and no ID attribute is needed.
layout(location = 0) in vec3 a_position;

uniform mat4 u_view_projection;

void main() {
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
