#version 450 core
in float stroke_opacity;
uniform vec4 ink;
out vec4 colour;
void main() { colour = vec4(ink.rgb, ink.a * stroke_opacity); }
