// Exhibit 1's bound, shared by its camera pass (museum/sdf_exhibit.frag) and its shadow-map pass
// (museum/sdf_exhibit_shadow.frag): box_span() of src/scenes/museum/sdf_exhibit.cpp.
#include "sdf_morph/geometry.glsl"

const float MIN_EPS = 1e-4;  // object units

// (t_enter, t_exit) of the ray o + d t with the box around the object's bounding sphere.
vec2 box_span(vec3 o, vec3 d) {
  precise vec3 c = objectBoundCenter();
  precise float t0 = -1e30, t1 = 1e30;
  for (int k = 0; k < 3; ++k) {
    precise float inv = 1.0 / d[k];
    precise float a = (c[k] - OBJECT_BOUND_RADIUS - o[k]) * inv;
    precise float b = (c[k] + OBJECT_BOUND_RADIUS - o[k]) * inv;
    t0 = dm_max(t0, dm_min(a, b));
    t1 = dm_min(t1, dm_max(a, b));
  }
  return vec2(t0, t1);
}

