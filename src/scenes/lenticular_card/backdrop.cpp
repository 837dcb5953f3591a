#include "scenes/lenticular_card/backdrop.h"

#include "scenes/common/surface_output.h"
#include "sdf/det_math.h"

namespace sdfreel::lenticular_card {
namespace {

const glm::vec3 FLOOR(0.30f, 0.27f, 0.24f), WALL_LOW(0.06f, 0.06f, 0.07f),
    WALL_HIGH(0.015f, 0.018f, 0.025f);
constexpr float FLOOR_FADE = 4.0f;      // metres: the floor fades into the backdrop
constexpr float SHADOW_RADIUS = 0.35f;  // the stand's soft contact shadow
constexpr float SHADOW_DEPTH = 0.55f;

V3x8 mix3(const V3x8& x, const V3x8& y, F8 a) {
  return x * (1.0f - a) + y * a;
}

// The depth and normal passes: the floor where the ray meets it, nothing above the horizon.
glm::vec3 floorSurface(const Ray& ray, int surface) {
  if (!(ray.dir.y < 0.0f) || !(ray.origin.y > 0.0f)) return noSurface(surface);
  return surfaceOutput(surface, -ray.origin.y / ray.dir.y, glm::vec3(0.0f, 1.0f, 0.0f));
}

}  // namespace

glm::vec3 backdrop(const Ray& ray, const glm::vec3& light, bool hit_mask, int surface) {
  if (hit_mask) return glm::vec3(0.0f);
  if (surface != SURFACE_COLOUR) return floorSurface(ray, surface);
  const glm::vec3 wall = dm::mix(WALL_LOW, WALL_HIGH, dm::smoothstep(-0.1f, 0.6f, ray.dir.y));
  if (!(ray.dir.y < 0.0f) || !(ray.origin.y > 0.0f)) return wall;
  const float t = -ray.origin.y / ray.dir.y;
  const float x = ray.origin.x + ray.dir.x * t, z = ray.origin.z + ray.dir.z * t;
  const float r = dm::sqrt(x * x + z * z);
  const float shadow = 1.0f - SHADOW_DEPTH * (1.0f - dm::smoothstep(0.0f, SHADOW_RADIUS, r));
  const glm::vec3 lit = FLOOR * ((0.3f + 0.9f * dm::max(light.y, 0.0f)) * shadow);
  return dm::mix(lit, wall, dm::smoothstep(0.0f, FLOOR_FADE, r));
}

V3x8 backdrop(const RayPacket& rays, const glm::vec3& light, bool hit_mask, int surface) {
  if (hit_mask) return V3x8(glm::vec3(0.0f));
  if (surface != SURFACE_COLOUR) {
    V3x8 out(glm::vec3(0.0f));
    for (int i = 0; i < LANES; ++i) out.set_lane(i, floorSurface(rays.ray(i), surface));
    return out;
  }
  const V3x8& d = rays.dir;
  const glm::vec3& o = rays.origin;
  const F8 a = dm::smoothstep(-0.1f, 0.6f, d.y);
  const V3x8 wall = WALL_LOW * (1.0f - a) + WALL_HIGH * a;
  if (!(o.y > 0.0f)) return wall;
  const M8 floor = d.y < 0.0f;
  if (!any(floor)) return wall;
  const F8 t = -o.y / d.y;
  const F8 x = o.x + d.x * t, z = o.z + d.z * t;
  const F8 r = dm::sqrt(x * x + z * z);
  const F8 shadow = 1.0f - SHADOW_DEPTH * (1.0f - dm::smoothstep(0.0f, SHADOW_RADIUS, r));
  const V3x8 lit = FLOOR * ((0.3f + 0.9f * dm::max(light.y, 0.0f)) * shadow);
  return select(floor, mix3(lit, wall, dm::smoothstep(0.0f, FLOOR_FADE, r)), wall);
}

}  // namespace sdfreel::lenticular_card
