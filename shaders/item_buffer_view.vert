#version 330 core
// The item-buffer overlay: one triangle that covers the viewport, no vertex buffer needed
// (vertex ids 0, 1, 2 -> (-1,-1), (3,-1), (-1,3)), as in display.vert.
void main() {
  vec2 corner = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  gl_Position = vec4(corner, 0.0, 1.0);
}
