// Exhibit 4's occlusion: 1 where nothing was drawn (depth still 1: the sky), the twin of
// occlusion_pass() in src/scenes/museum/atmosphere.cpp.
#include "common/image_pass.glsl"

uniform sampler2D u_depth;

void main() {
  float v = read_image(u_depth, image_pixel()).x >= 1.0 ? 1.0 : 0.0;
  frag_out = vec4(v, v, v, 1.0);
}
