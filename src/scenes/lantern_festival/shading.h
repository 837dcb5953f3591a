#pragma once
// Lantern materials of seed 000. Every material gets the moon (directional) and its own candle
// (point light, 1/d^2), Lambert plus Phong; paper is lit through (|n.l|, the seed's translucency)
// and textured with the generated normal-noise and value-noise maps in cylindrical UVs.
#include <glm/glm.hpp>

#include "scenes/common/texture.h"
#include "scenes/lantern_festival/grid.h"
#include "sdf/lanes.h"

namespace sdfreel::lantern_festival {

struct LightFrame {
  glm::vec3 moon_dir{0.0f, 1.0f, 0.0f};  // towards the moon
  glm::vec3 moon_light{0.0f};            // colour * intensity
  glm::vec3 ambient{0.0f};               // sky fill light
  glm::vec3 candle_color{1.0f};          // colour * intensity
  glm::vec3 candle_local{0.0f};          // candle position in the lantern frame
  float flicker_time = 0.0f;             // TIME * flicker_speed, wrapped to [0, FLICKER_PERIOD)
  float flicker_strength = 1.0f;         // 0 steady, 1 the seed's flicker
  glm::vec3 paper_albedo{1.0f}, metal_albedo{0.5f}, wood_albedo{0.5f};
  const Texture* paper_normal = nullptr;
  const Texture* paper_noise = nullptr;
};

// Everything a material needs about the hit.
struct LanternHit {
  glm::vec3 p;       // world position
  glm::vec3 n;       // world normal (unit)
  glm::vec3 view;    // unit vector from the hit towards the eye
  glm::vec3 local;   // position in the lantern frame (lantern units)
  LanternCell cell;  // the lantern that was hit
};

// The seed's flicker: a sum of three cosines in [0.15, 0.85]. The three run as lanes of one
// dm::cos (each lane the scalar function's bits): a lantern hit's candle costs one.
inline float flickerValue(float t) {
  const F8 c = dm::cos(
      F8{t * 2.0f * dm::PI, t * 3.0f * dm::PI, t * 2.5f * dm::PI, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f});
  return (c[0] + 2.0f) * 0.15f + (c[1] + 1.0f) * 0.1f + (c[2] + 1.0f) * 0.1f;
}

// The seed's lightStrength *= mix(0.3, 0.8, flickerValue), blended towards its middle (0.55) as
// flicker_strength goes to 0.
float candleStrength(const LightFrame& L, const LanternCell& cell);

// The seed's cylindrical UVs (longitude with pi in place of the seed's 3.141, so u tiles exactly).
inline glm::vec2 calcCylindricalUVs(const glm::vec2& dir, const glm::vec3& p) {
  const float longitude = dm::atan2(-dir.y, dir.x);  // [-pi, pi]
  return glm::vec2((longitude / dm::PI) * 0.5f + 0.5f, (p.y * 0.5f) + 0.5f);
}

// normalize(p.xz), with a fixed direction on the lantern axis where it is undefined.
inline glm::vec2 radialDirection(const glm::vec3& p) {
  const float len2 = p.x * p.x + p.z * p.z;
  if (!(len2 > 1e-20f)) return glm::vec2(1.0f, 0.0f);
  return glm::vec2(p.x, p.z) / dm::sqrt(len2);
}

glm::vec3 shadePaper(const LightFrame& L, const GridFrame& g, const LanternHit& h);
glm::vec3 shadeMetal(const LightFrame& L, const GridFrame& g, const LanternHit& h);
glm::vec3 shadeWood(const LightFrame& L, const GridFrame& g, const LanternHit& h);

// The seed's material choice (nearestPart) and dispatch.
glm::vec3 shadeLantern(const LightFrame& L, const GridFrame& g, const LanternHit& h);

}  // namespace sdfreel::lantern_festival
