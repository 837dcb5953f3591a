#include "broken_lib.glsl"
out vec4 frag;
void main() { frag = vec4(broken(1.0)); }
