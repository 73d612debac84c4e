in vec2 corner;
out vec4 colour;
void main() { colour = vec4(0.45, 0.3, 0.2, 0.6 * clamp(1.0 - length(corner), 0.0, 1.0)); }
