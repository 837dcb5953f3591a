// A copy of one target into another: the twin of copy_pass() in src/scenes/museum/atmosphere.cpp.
#include "common/image_pass.glsl"

uniform sampler2D u_source;

void main() { frag_out = read_image(u_source, image_pixel()); }
