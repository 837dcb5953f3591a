// Reads two uniforms; a pass that sets only one must be refused.
uniform float u_a;
uniform float u_b;
out vec4 frag;
void main() { frag = vec4(u_a, u_b, 0.0, 1.0); }
