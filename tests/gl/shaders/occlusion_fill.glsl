// tests/passes/plan_fixture.h occlusion_fill: uniform u_value, or the integer checker pattern.
#include "common/image_pass.glsl"

uniform float u_pattern;
uniform float u_value;

void main() {
  ivec2 p = image_pixel();
  float v = u_pattern > 0.5 ? float(((p.x / 5) + (p.y / 3)) % 2) : u_value;
  frag_out = vec4(v, v, v, 1.0);
}
