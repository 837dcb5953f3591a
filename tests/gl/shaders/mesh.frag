in vec3 colour;
out vec4 frag;
void main() { frag = vec4(colour, 1.0); }
