// The pictures' canvases: the twin of src/scenes/museum/paintings.cpp (same table, same
// operations; see there for the landscape).
#include "common/det_math.glsl"
#include "common/noise.glsl"

const int PAINTING_COUNT = 5;
const float CANVAS_HALF_W = 0.6, CANVAS_Y0 = 1.4, CANVAS_Y1 = 2.3;
const float PAINTING_X[PAINTING_COUNT] = float[](-3.0, 0.5, -3.0, 0.5, 3.8);
const float PAINTING_SIDE[PAINTING_COUNT] = float[](-1.0, -1.0, 1.0, 1.0, 1.0);
const vec3 PAINTING_KEY[PAINTING_COUNT] =
    vec3[](vec3(0.55, 0.12, 0.08), vec3(0.1, 0.25, 0.45), vec3(0.2, 0.4, 0.18),
           vec3(0.6, 0.45, 0.1), vec3(0.3, 0.2, 0.4));
const uint PAINTING_SEED = 41u;
const float PAINTING_ASPECT = 2.0 * CANVAS_HALF_W / (CANVAS_Y1 - CANVAS_Y0);
const float PAINTING_SUN_U = 0.7, PAINTING_SUN_V = 0.74, PAINTING_SUN_R = 0.07;
const vec3 SUN_PAINT = vec3(0.95, 0.85, 0.55);
const int GRAIN_U = 96, GRAIN_V = 72;

float ridge(float u, int layer, int k) {
  precise float f = u * float(3 + 2 * layer);
  precise float i = floor(f);
  uint seed = PAINTING_SEED + uint(k);
  precise float a = hash_to_unit(hash2i(int(i), layer, seed));
  precise float b = hash_to_unit(hash2i(int(i) + 1, layer, seed));
  precise float s = f - i;
  precise float r = a + (b - a) * (s * s * (3.0 - 2.0 * s));
  return r;
}

vec3 painting_albedo(vec3 p, int k) {
  vec3 key = PAINTING_KEY[k];
  float x = PAINTING_X[k];
  precise float along =
      PAINTING_SIDE[k] > 0.0 ? x + CANVAS_HALF_W - p.x : p.x - (x - CANVAS_HALF_W);
  precise float u = dm_clamp(along / (2.0 * CANVAS_HALF_W), 0.0, 1.0);
  precise float v = dm_clamp((p.y - CANVAS_Y0) / (CANVAS_Y1 - CANVAS_Y0), 0.0, 1.0);
  precise vec3 horizon = key * 0.2 + vec3(0.6), zenith = key * 0.5 + vec3(0.3);
  precise vec3 c = dm_mix(horizon, zenith, v);
  precise float du = (u - PAINTING_SUN_U) * PAINTING_ASPECT, dv = v - PAINTING_SUN_V;
  if (du * du + dv * dv < PAINTING_SUN_R * PAINTING_SUN_R) c = SUN_PAINT;
  precise vec3 layers[3] = vec3[](dm_mix(key, horizon, 0.55), key * 0.9, key * 0.45);
  for (int layer = 0; layer < 3; ++layer) {
    precise float h = 0.6 - 0.16 * float(layer) + 0.14 * (ridge(u, layer, k) - 0.5);
    if (v < h) c = layers[layer];
  }
  precise float grain = hash_to_unit(hash2i(int(u * float(GRAIN_U)), int(v * float(GRAIN_V)),
                                            PAINTING_SEED + 8u + uint(k)));
  precise vec3 r = c * (0.92 + 0.08 * grain);
  return r;
}
