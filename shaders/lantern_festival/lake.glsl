// The lake of seed 000: the twin of src/scenes/lantern_festival/lake.h (same names and order).
// The per-frame LakeFrame arrives as the uniform u_lake; functions read it directly instead of
// taking it as an argument.
#include "common/sdf.glsl"

const int WAVE_COUNT = 5;
// sdPlane(p, (0,1,0), 1): the undisturbed water level is y = -1.
const float WATER_PLANE_OFFSET = 1.0;

struct LakeFrame {
  vec2 dir[WAVE_COUNT];
  float amp[WAVE_COUNT];
  float freq[WAVE_COUNT];
  float phase[WAVE_COUNT];  // TIME * wave_speed, wrapped to [0, 2pi) in double on the host
  vec2 rough_dir;
  float rough_amp, rough_freq, rough_phase;
  float lipschitz;   // sum amp * freq >= |grad waterHeightAt|
  float max_height;  // sum amp >= |waterHeightAt|
  float step_scale;
};

uniform LakeFrame u_lake;

float waterHeightAt(vec2 p) {
  precise float displacement = 0.0;
  for (int i = 0; i < WAVE_COUNT; ++i) {
    precise float arg = dm_dot(u_lake.dir[i], p) * u_lake.freq[i] + u_lake.phase[i];
    displacement += u_lake.amp[i] * dm_sin(arg);
  }
  return displacement;
}

float waterHeightRoughAt(vec2 p) {
  precise float arg = dm_dot(u_lake.rough_dir, p) * u_lake.rough_freq + u_lake.rough_phase;
  precise float h = u_lake.rough_amp * dm_sin(arg);
  return h;
}

// Normal of the rough water surface (the seed's gradientWaterRough, analytic), normalised.
vec3 normalWaterRough(vec2 p) {
  precise float arg = dm_dot(u_lake.rough_dir, p) * u_lake.rough_freq + u_lake.rough_phase;
  precise float slope = u_lake.rough_amp * u_lake.rough_freq * dm_cos(arg);
  precise vec3 g = vec3(u_lake.rough_dir.x * slope, 1.0, u_lake.rough_dir.y * slope);
  return safe_normalize(g);
}

// Vertical gap above the water surface (not a true distance: marchers scale it).
float sdfWater(vec3 p) {
  precise float gap = sdPlane(p, vec3(0.0, 1.0, 0.0), WATER_PLANE_OFFSET) +
                      waterHeightAt(vec2(p.x, p.z));
  return gap;
}

// Water surface height (world y) at p: where sdfWater is 0.
float waterSurfaceY(vec2 p) {
  precise float y = -WATER_PLANE_OFFSET - waterHeightAt(p);
  return y;
}
