// The fur strand hash (shaders/fur/strand_hash.glsl) per pixel, for the bit-for-bit comparison
// with src/scenes/fur/strand_hash.h in fur_hash_glsl_test.cpp: pixel (x, y) hashes the cell
// u_origin + (x, y) * u_stride, and writes both 32-bit words as 16-bit halves (exact floats) and
// strand_random.
#include "fur/strand_hash.glsl"

uniform ivec2 u_origin;
uniform ivec2 u_stride;
layout(location = 0) out vec4 frag;

void main() {
  ivec2 cell = u_origin + ivec2(gl_FragCoord.xy) * u_stride;
  uvec2 h = pcg2d(uvec2(cell));
  frag = vec4(float(h.x >> 16u), float(h.x & 65535u), float(h.y >> 16u), strand_random(cell));
}
