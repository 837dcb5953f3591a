#pragma once
// The lake of seed 000: the plane y = -1 displaced by five directional sines (waterHeightAt), and
// the single rough wave the lanterns ride on (waterHeightRoughAt). Per-frame constants live in
// LakeFrame so that per-ray code never touches TIME (a double) or recomputes amplitudes.
#include <glm/glm.hpp>

#include "sdf/det_math.h"
#include "sdf/sdf.h"

namespace sdfreel::lantern_festival {

constexpr int WAVE_COUNT = 5;
// The seed's wave directions (normalised) and its amplitude/frequency recurrence a *= 0.6, w *= 1.4
// starting from a = 0.15, w = 0.4 (applied before each wave is used).
constexpr float WAVE_DIRS[WAVE_COUNT][2] = {{-0.371391f, 0.928477f},
                                            {0.0f, -1.0f},
                                            {-0.624695f, 0.780869f},
                                            {-0.768221f, -0.640184f},
                                            {0.371391f, 0.928477f}};
constexpr float SEED_WAVE_AMPLITUDE = 0.15f;
constexpr float SEED_WAVE_FREQUENCY = 0.4f;
constexpr float WAVE_AMPLITUDE_DECAY = 0.6f;
constexpr float WAVE_FREQUENCY_GROWTH = 1.4f;
// The rough wave lags the real surface by 0.2 s of TIME (seed: (TIME - 0.2) * 2.5).
constexpr double ROUGH_WAVE_TIME_OFFSET = 0.2;
// sdPlane(p, (0,1,0), 1): the undisturbed water level is y = -1.
constexpr float WATER_PLANE_OFFSET = 1.0f;
constexpr float LIPSCHITZ_ROUNDING_MARGIN = 1.001f;

struct LakeFrame {
  glm::vec2 dir[WAVE_COUNT];
  float amp[WAVE_COUNT];
  float freq[WAVE_COUNT];
  float phase[WAVE_COUNT];  // TIME * wave_speed, wrapped to [0, 2pi) in double
  glm::vec2 rough_dir;
  float rough_amp = 0.0f, rough_freq = 0.0f, rough_phase = 0.0f;
  float lipschitz = 0.0f;   // sum amp * freq >= |grad waterHeightAt|
  float max_height = 0.0f;  // sum amp >= |waterHeightAt|
  float step_scale = 1.0f;  // 1 / sqrt(1 + lipschitz^2): sdfWater * step_scale is a distance bound
};

// amplitude: the seed's 0.15 (largest wave before decay); speed: the seed's 2.5 rad per TIME
// second.
LakeFrame make_lake_frame(double time, float amplitude, float speed);

// Templates over the point type (glm::vec2/vec3 or V2x8/V3x8): one source for scalar and lanes.
// vdot(p, dir) has glm::dot(dir, p)'s bits (products commute).
template <class V2>
inline auto waterHeightAt(const LakeFrame& k, const V2& p) {
  auto displacement = decltype(p.x){};  // +0, in every lane
  for (int i = 0; i < WAVE_COUNT; ++i)
    displacement = displacement + k.amp[i] * dm::sin(vdot(p, k.dir[i]) * k.freq[i] + k.phase[i]);
  return displacement;
}

// Analytic gradient of waterHeightAt (for tests and the Lipschitz check).
inline glm::vec2 waterHeightGradientAt(const LakeFrame& k, const glm::vec2& p) {
  glm::vec2 g(0.0f);
  for (int i = 0; i < WAVE_COUNT; ++i)
    g +=
        k.dir[i] * (k.amp[i] * k.freq[i] * dm::cos(glm::dot(k.dir[i], p) * k.freq[i] + k.phase[i]));
  return g;
}

inline float waterHeightRoughAt(const LakeFrame& k, const glm::vec2& p) {
  return k.rough_amp * dm::sin(glm::dot(k.rough_dir, p) * k.rough_freq + k.rough_phase);
}

// Normal of the rough water surface y = -1 - waterHeightRoughAt: the seed's gradientWaterRough,
// computed analytically (the seed's central differences of the same sine), then normalised.
inline glm::vec3 normalWaterRough(const LakeFrame& k, const glm::vec2& p) {
  const float slope =
      k.rough_amp * k.rough_freq * dm::cos(glm::dot(k.rough_dir, p) * k.rough_freq + k.rough_phase);
  return safe_normalize(glm::vec3(k.rough_dir.x * slope, 1.0f, k.rough_dir.y * slope));
}

// Vertical gap above the water surface: the seed's sdPlane(p, (0,1,0), 1) + waterHeightAt(p.xz).
// Not a true distance: |grad| <= 1 / step_scale, so marchers scale it (see lantern_festival/march).
template <class V>
inline auto sdfWater(const LakeFrame& k, const V& p) {
  return sdPlane(p, glm::vec3(0.0f, 1.0f, 0.0f), WATER_PLANE_OFFSET) +
         waterHeightAt(k, vec2_of(p.x, p.z));
}

// Water surface height (world y) at p: where sdfWater is 0.
inline float waterSurfaceY(const LakeFrame& k, const glm::vec2& p) {
  return -WATER_PLANE_OFFSET - waterHeightAt(k, p);
}

}  // namespace sdfreel::lantern_festival
