// Copies a depth target into colour, so a test reads the depth a mesh pass wrote.
#include "common/image_pass.glsl"

uniform sampler2D u_depth;

void main() {
  float d = read_image(u_depth, image_pixel()).x;
  frag_out = vec4(d, d, d, 1.0);
}
