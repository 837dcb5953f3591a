// Exhibit 1's reflection probe: the twin of sample_probe() in src/scenes/museum/probe.cpp (cube
// faces +x, -x, +y, -y, +z, -z stacked vertically in u_probe, bilinear within a face).
#include "common/det_math.glsl"

const int PROBE_SIZE = 128;
uniform sampler2D u_probe;

vec3 probe_texel(int face, float x, float y) {
  int xi = int(dm_clamp(x, 0.0, float(PROBE_SIZE - 1)));
  int yi = int(dm_clamp(y, 0.0, float(PROBE_SIZE - 1)));
  return texelFetch(u_probe, ivec2(xi, face * PROBE_SIZE + yi), 0).rgb;
}

vec3 sample_probe(vec3 d) {
  precise float ax = abs(d.x), ay = abs(d.y), az = abs(d.z);
  int face;
  precise float s, t;
  if (ax >= ay && ax >= az) {
    face = d.x > 0.0 ? 0 : 1;
    s = d.x > 0.0 ? -d.z / ax : d.z / ax;
    t = -d.y / ax;
  } else if (ay >= az) {
    face = d.y > 0.0 ? 2 : 3;
    s = d.x / ay;
    t = d.y > 0.0 ? d.z / ay : -d.z / ay;
  } else {
    face = d.z > 0.0 ? 4 : 5;
    s = d.z > 0.0 ? d.x / az : -d.x / az;
    t = -d.y / az;
  }
  precise float fx = (s * 0.5 + 0.5) * float(PROBE_SIZE) - 0.5;
  precise float fy = (t * 0.5 + 0.5) * float(PROBE_SIZE) - 0.5;
  precise float x0 = floor(fx), y0 = floor(fy);
  precise float wx = fx - x0, wy = fy - y0;
  precise vec3 top = dm_mix(probe_texel(face, x0, y0), probe_texel(face, x0 + 1.0, y0), wx);
  precise vec3 bottom =
      dm_mix(probe_texel(face, x0, y0 + 1.0), probe_texel(face, x0 + 1.0, y0 + 1.0), wx);
  return dm_mix(top, bottom, wy);
}
