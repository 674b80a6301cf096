#version 330 core
// The viewer's pick pass: which mesh (index + 1; 0 is "nothing") and which of its triangles
// covers each pixel. Float channels hold integers exactly up to 2^24.
uniform float u_mesh;

flat in int v_triangle;

layout(location = 0) out vec4 frag_id;

void main() { frag_id = vec4(u_mesh, float(v_triangle), 0.0, 1.0); }
