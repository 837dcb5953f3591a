// A mesh pass's fragment: the instance's data as its colour (tests/gl/plan_runner_test.cpp).
#include "common/mesh_fragment.glsl"

vec4 shade(MeshFragment f) {
  return f.instance_data;
}
