#include "scenes/museum/paintings.h"

#include "sdf/det_math.h"
#include "sdf/noise.h"

namespace sdfreel::museum {
namespace {

using glm::vec3;

const Painting PAINTINGS[PAINTING_COUNT] = {
    {-3.0f, -1.0f, {0.55f, 0.12f, 0.08f}},  // a red evening
    {0.5f, -1.0f, {0.1f, 0.25f, 0.45f}},    // blue mountains
    {-3.0f, 1.0f, {0.2f, 0.4f, 0.18f}},     // green hills
    {0.5f, 1.0f, {0.6f, 0.45f, 0.1f}},      // an ochre plain
    {3.8f, 1.0f, {0.3f, 0.2f, 0.4f}},       // a violet dusk
};
constexpr uint32_t PAINTING_SEED = 41u;
constexpr float ASPECT = 2.0f * CANVAS_HALF_W / (CANVAS_Y1 - CANVAS_Y0);
constexpr float SUN_U = 0.7f, SUN_V = 0.74f, SUN_R = 0.07f;
const vec3 SUN_PAINT(0.95f, 0.85f, 0.55f);
constexpr int GRAIN_U = 96, GRAIN_V = 72;  // the canvas's weave, cells across and up

// Smooth value noise along u, in [0, 1]: ridge `layer` of painting k.
float ridge(float u, int layer, int k) {
  const float f = u * float(3 + 2 * layer);
  const float i = dm::floor(f);
  const uint32_t seed = PAINTING_SEED + uint32_t(k);
  const float a = hash_to_unit(hash2i(int(i), layer, seed));
  const float b = hash_to_unit(hash2i(int(i) + 1, layer, seed));
  const float s = f - i;
  return a + (b - a) * (s * s * (3.0f - 2.0f * s));
}

}  // namespace

const Painting& painting(int k) {
  return PAINTINGS[k];
}

vec3 painting_albedo(const vec3& p, int k) {
  const Painting& pt = PAINTINGS[k];
  // From the room, the south wall's pictures run towards -x.
  const float along = pt.side > 0.0f ? pt.x + CANVAS_HALF_W - p.x : p.x - (pt.x - CANVAS_HALF_W);
  const float u = dm::clamp(along / (2.0f * CANVAS_HALF_W), 0.0f, 1.0f);
  const float v = dm::clamp((p.y - CANVAS_Y0) / (CANVAS_Y1 - CANVAS_Y0), 0.0f, 1.0f);
  const vec3 horizon = pt.key * 0.2f + vec3(0.6f), zenith = pt.key * 0.5f + vec3(0.3f);
  vec3 c = dm::mix(horizon, zenith, v);
  const float du = (u - SUN_U) * ASPECT, dv = v - SUN_V;
  if (du * du + dv * dv < SUN_R * SUN_R) c = SUN_PAINT;
  // Three ridges, far to near: paler and higher behind, darker and lower in front.
  const vec3 layers[3] = {dm::mix(pt.key, horizon, 0.55f), pt.key * 0.9f, pt.key * 0.45f};
  for (int layer = 0; layer < 3; ++layer) {
    const float h = 0.6f - 0.16f * float(layer) + 0.14f * (ridge(u, layer, k) - 0.5f);
    if (v < h) c = layers[layer];
  }
  const float grain = hash_to_unit(
      hash2i(int(u * float(GRAIN_U)), int(v * float(GRAIN_V)), PAINTING_SEED + 8u + uint32_t(k)));
  return c * (0.92f + 0.08f * grain);
}

}  // namespace sdfreel::museum
