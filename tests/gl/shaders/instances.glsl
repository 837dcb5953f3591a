// Full-screen pass drawn several times: additive blending sums u_value once per instance.
uniform float u_value;
out vec4 frag;
void main() { frag = vec4(u_value, 2.0 * u_value, 0.0, 0.0); }
