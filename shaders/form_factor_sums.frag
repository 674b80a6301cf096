#version 330 core
flat in float v_delta_form_factor;
out float sum;

void main() { sum = v_delta_form_factor; }
