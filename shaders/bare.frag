#version 330 core
// `luz bench local`'s limit: one constant colour, the cheapest fragment there is.
layout(location = 0) out vec4 frag_radiance;

void main() { frag_radiance = vec4(0.5, 0.5, 0.5, 1.0); }
