// Scene "fur" (src/scenes/fur/fur.cpp): the background ray pass; the room, the case and the furry
// shapes are mesh passes (fur/case.glsl, fur/shell.vert, fur/shell.glsl).
#include "common/sample_loop.glsl"

vec3 radiance(Ray ray, inout RayStats stats) {
  return vec3(0.018, 0.02, 0.025);
}
