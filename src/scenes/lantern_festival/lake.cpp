#include "scenes/lantern_festival/lake.h"

namespace sdfreel::lantern_festival {

LakeFrame make_lake_frame(double time, float amplitude, float speed) {
  LakeFrame k;
  const double two_pi = 6.283185307179586;
  float a = amplitude;
  float w = SEED_WAVE_FREQUENCY;
  for (int i = 0; i < WAVE_COUNT; ++i) {
    a *= WAVE_AMPLITUDE_DECAY;
    w *= WAVE_FREQUENCY_GROWTH;
    k.dir[i] = glm::vec2(WAVE_DIRS[i][0], WAVE_DIRS[i][1]);
    k.amp[i] = a;
    k.freq[i] = w;
    // Wrapped in double: a float TIME moves in steps of 1/16 s at 1e6 s and 64 s at 1e9 s
    // (tests/hard_cases/lantern_festival/time_1e6, time_1e9). Every wave of the seed shares TIME
    // * 2.5; one wrapped phase per wave keeps the door open for per-wave speeds and mirrors the
    // GLSL uniform array.
    k.phase[i] = dm::wrap_phase(time * double(speed), two_pi);
    k.lipschitz += a * w;
    k.max_height += a;
  }
  k.rough_dir = k.dir[0];
  k.rough_amp = amplitude;
  k.rough_freq = SEED_WAVE_FREQUENCY;
  k.rough_phase = dm::wrap_phase((time - ROUGH_WAVE_TIME_OFFSET) * double(speed), two_pi);
  // Float rounding of the sines and their sum can exceed the exact bound by a few ulps.
  k.lipschitz *= LIPSCHITZ_ROUNDING_MARGIN;
  k.step_scale = 1.0f / dm::sqrt(1.0f + k.lipschitz * k.lipschitz);
  return k;
}

}  // namespace sdfreel::lantern_festival
