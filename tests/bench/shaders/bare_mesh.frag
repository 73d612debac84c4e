in float lit;
out vec4 colour;
void main() { colour = vec4(vec3(lit), 1.0); }
