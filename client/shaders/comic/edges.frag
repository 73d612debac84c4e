#version 450 core
flat in vec3 edge_colour;
out vec4 colour;
void main() { colour = vec4(edge_colour, 1.0); }
