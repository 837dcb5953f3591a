#include "broken_lib_ok.glsl"
#include "undeclared_lib.glsl"
out vec4 frag;
void main() { frag = vec4(uses_undeclared(1.0)); }
