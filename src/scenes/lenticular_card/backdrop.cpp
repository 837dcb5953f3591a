#include "scenes/lenticular_card/backdrop.h"

#include "sdf/det_math.h"

namespace sdfreel::lenticular_card {
namespace {

const glm::vec3 FLOOR(0.30f, 0.27f, 0.24f), WALL_LOW(0.06f, 0.06f, 0.07f),
    WALL_HIGH(0.015f, 0.018f, 0.025f);
constexpr float FLOOR_FADE = 4.0f;      // metres: the floor fades into the backdrop
constexpr float SHADOW_RADIUS = 0.35f;  // the stand's soft contact shadow
constexpr float SHADOW_DEPTH = 0.55f;

}  // namespace

glm::vec3 backdrop(const Ray& ray, const glm::vec3& light, bool hit_mask) {
  if (hit_mask) return glm::vec3(0.0f);
  const glm::vec3 wall = dm::mix(WALL_LOW, WALL_HIGH, dm::smoothstep(-0.1f, 0.6f, ray.dir.y));
  if (!(ray.dir.y < 0.0f) || !(ray.origin.y > 0.0f)) return wall;
  const float t = -ray.origin.y / ray.dir.y;
  const float x = ray.origin.x + ray.dir.x * t, z = ray.origin.z + ray.dir.z * t;
  const float r = dm::sqrt(x * x + z * z);
  const float shadow = 1.0f - SHADOW_DEPTH * (1.0f - dm::smoothstep(0.0f, SHADOW_RADIUS, r));
  const glm::vec3 lit = FLOOR * ((0.3f + 0.9f * dm::max(light.y, 0.0f)) * shadow);
  return dm::mix(lit, wall, dm::smoothstep(0.0f, FLOOR_FADE, r));
}

}  // namespace sdfreel::lenticular_card
