#pragma once
// The night sky: a procedural equirectangular environment (gradient, stars, faint clouds) that
// stands in for the seed's HDRI, generated once per seed; the moon (disc and halo) is added
// analytically so that its direction and brightness can be animated; then the seed's height fog.
#include <cstdint>
#include <glm/glm.hpp>

#include "scenes/common/texture.h"
#include "sdf/lanes.h"

namespace sdfreel::lantern_festival {

constexpr int SKY_WIDTH = 2048;
constexpr int SKY_HEIGHT = 1024;
// Reflections read a box-filtered copy (what a GPU's mipmaps would give under the wavy reflected
// directions): stars blur into the water instead of sparkling like snow.
constexpr int SKY_REFLECTION_DOWNSAMPLE = 4;

// Equirect in the seed's convention: u = atan(z, x) / 2pi (repeating), v = acos(y) / pi (0 at the
// zenith, row 0). RGB, linear, before sky_intensity.
Texture make_sky_environment(int width, int height, uint32_t seed);
// Box filter by `factor` in both directions (width and height must be multiples of it).
Texture downsample(const Texture& t, int factor);

struct SkyFrame {
  const Texture* environment = nullptr;
  const Texture* environment_blurred = nullptr;  // for reflections
  float intensity = 1.0f;
  glm::vec3 moon_dir{0.0f, 1.0f, 0.0f};                               // towards the moon, unit
  glm::vec3 moon_right{1.0f, 0.0f, 0.0f}, moon_up{0.0f, 0.0f, 1.0f};  // disc frame
  glm::vec3 moon_disc{0.0f};                                          // radiance of the disc
  glm::vec3 moon_glow{0.0f};                           // radiance of the halo at its centre
  float moon_cos_inner = 1.0f, moon_cos_outer = 1.0f;  // disc edge (cosines of the angles)
  glm::vec3 fog_color{0.0f};
  float horizon_fog = 1.0f;             // 1 = the seed's fog band, 0 = none
  const Texture* moon_noise = nullptr;  // the paper's value-noise map, reused for the moon's maria
};

// direction from elevation/azimuth in degrees (azimuth from +Z towards +X).
glm::vec3 direction_from_angles(double elevation_deg, double azimuth_deg);

SkyFrame make_sky_frame(const Texture& environment, const Texture& environment_blurred,
                        float intensity, const glm::vec3& moon_dir, const glm::vec3& moon_radiance,
                        const glm::vec3& fog_color, float horizon_fog, const Texture& moon_noise);

glm::vec3 moon(const SkyFrame& s, const glm::vec3& dir);
// The seed's sky(): environment (sharp, or the blurred copy for reflections) + moon, then fog.
glm::vec3 skyFrom(const SkyFrame& s, const Texture& environment, glm::vec3 dir);
// skyFrom in lanes: each lane of m gets skyFrom's bits for its direction (the others: anything).
V3x8 skyFrom_lanes(const SkyFrame& s, const Texture& environment, const V3x8& dir, M8 m);
inline glm::vec3 sky(const SkyFrame& s, const glm::vec3& dir) {
  return skyFrom(s, *s.environment, dir);
}
inline glm::vec3 skyReflected(const SkyFrame& s, const glm::vec3& dir) {
  return skyFrom(s, *s.environment_blurred, dir);
}

}  // namespace sdfreel::lantern_festival
