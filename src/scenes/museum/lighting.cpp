#include "scenes/museum/lighting.h"

#include "scenes/museum/paintings.h"
#include "sdf/det_math.h"
#include "sdf/noise.h"

namespace sdfreel::museum {
namespace {

using glm::vec3;

const vec3 SKY_ZENITH(0.12f, 0.26f, 0.6f);
const vec3 SKY_HORIZON(0.55f, 0.6f, 0.68f);
const vec3 GROUND(0.16f, 0.15f, 0.12f);      // outside, below the horizon
const vec3 AMBIENT_UP(0.15f, 0.16f, 0.18f);  // light from above (ceiling, sky through the window)
const vec3 AMBIENT_DOWN(0.07f, 0.06f, 0.05f);
const vec3 WINDOW_FILL(0.12f, 0.13f, 0.15f);          // skylight from the window side
const vec3 FROM_WINDOW(-0.957826f, 0.287348f, 0.0f);  // normalize(-1, 0.3, 0)
constexpr float SUN_DISC_COS0 = 0.9994f, SUN_DISC_COS1 = 0.9997f;
constexpr float SUN_DISC = 40.0f;
constexpr float SUN_GLOW = 0.5f;
constexpr float PENUMBRA_PER_M = 0.0093f;  // the sun's angular diameter, radians
constexpr float PENUMBRA_MIN = 0.002f;
constexpr float SPECULAR_F0 = 0.04f;
constexpr float FLOOR_ROUGHNESS = 0.45f;
constexpr float CANVAS_ROUGHNESS = 0.8f;  // oil on canvas: a broad, faint sheen
constexpr float PLANK_W = 0.2f, PLANK_L = 1.2f, SEAM = 0.03f;
constexpr uint32_t PLANK_SEED = 7u;
constexpr float NORMAL_OFFSET = 0.002f;  // shadow lookups start this far off the surface

// The analytic sun test (the reflection probe's shading). Signed distance into the window's opening
// at q (positive inside glass, negative on the wall or a mullion), in the plane of the wall.
float window_opening(const vec3& q) {
  const float rect =
      dm::min(dm::min(q.y - WINDOW_Y0, WINDOW_Y1 - q.y), dm::min(q.z - WINDOW_Z0, WINDOW_Z1 - q.z));
  const float bars =
      dm::min(dm::abs(q.y - MULLION_Y) - MULLION_HALF, dm::abs(q.z - MULLION_Z) - MULLION_HALF);
  return dm::min(rect, bars);
}

// Through one face (plane x = plane_x) of the west wall: 0..1 with a penumbra growing with the
// distance travelled.
float through_plane(const vec3& p, float plane_x) {
  const float t = dm::max((plane_x - p.x) / TO_SUN.x, 0.0f);
  const vec3 q = p + TO_SUN * t;
  const float w = PENUMBRA_PER_M * t + PENUMBRA_MIN;
  return dm::clamp(0.5f + window_opening(q) / w, 0.0f, 1.0f);
}

// Does the ray from p towards the sun meet the box (slab test)?
bool blocks(const vec3& p, const HallBox& b) {
  float t0 = 0.0f, t1 = 1e30f;
  for (int k = 0; k < 3; ++k) {
    if (TO_SUN[k] == 0.0f) {
      if (p[k] < b.lo[k] || p[k] > b.hi[k]) return false;
      continue;
    }
    const float inv = 1.0f / TO_SUN[k];
    const float a = (b.lo[k] - p[k]) * inv, c = (b.hi[k] - p[k]) * inv;
    t0 = dm::max(t0, dm::min(a, c));
    t1 = dm::min(t1, dm::max(a, c));
  }
  return t0 < t1;
}

// x^(2^k) by squaring: Blinn-Phong lobes with exponents 2..256, no pow.
float power_of_two_power(float x, int k) {
  for (int i = 0; i < k; ++i) x = x * x;
  return x;
}

// Oak planks: rows along x, each plank's tint from an integer hash, dark seams.
vec3 floor_albedo(const vec3& p, const vec3& albedo) {
  const float row = dm::floor(p.z / PLANK_W);
  const float shift = hash_to_unit(hash2i(int(row), 0, PLANK_SEED)) * PLANK_L;
  const float plank = dm::floor((p.x + shift) / PLANK_L);
  const float tint = 0.8f + 0.4f * hash_to_unit(hash2i(int(row), int(plank), PLANK_SEED));
  const float u = p.z / PLANK_W - row, v = (p.x + shift) / PLANK_L - plank;
  const float seam = (u < SEAM || v < SEAM * PLANK_W / PLANK_L) ? 0.55f : 1.0f;
  return albedo * (tint * seam);
}

float analytic_visibility(const vec3& p, const HallLight& light) {
  const float inner = through_plane(p, -ROOM_X);
  if (!(inner > 0.0f)) return 0.0f;
  const float vis = dm::min(inner, through_plane(p, -ROOM_X - WALL));
  for (const HallBox& b : light.occluders)
    if (blocks(p, b)) return 0.0f;
  return vis;
}

}  // namespace

float sun_visibility(const vec3& p, const vec3& n, float ndl, const HallLight& light,
                     const SunMap& map) {
  const vec3 q = p + n * NORMAL_OFFSET;
  return map.image ? sun_map_visibility(*map.image, *map.view, q, ndl, map.windows)
                   : analytic_visibility(q, light);
}

vec3 sky(const vec3& d) {
  vec3 col = dm::mix(SKY_HORIZON, SKY_ZENITH, dm::smoothstep(0.0f, 0.5f, d.y));
  col = dm::mix(GROUND, col, dm::smoothstep(-0.02f, 0.02f, d.y));
  const float c = glm::dot(d, TO_SUN);
  const float glow = power_of_two_power(dm::max(c, 0.0f), 5);
  const float disc = dm::smoothstep(SUN_DISC_COS0, SUN_DISC_COS1, c);
  return col + SUN_RADIANCE * (SUN_GLOW * glow + SUN_DISC * disc);
}

vec3 hall_radiance(const vec3& p, const vec3& normal, const vec3& albedo_in, float material,
                   const HallLight& light, const SunMap& map) {
  const vec3 n = normal / dm::sqrt(glm::dot(normal, normal));
  const bool is_floor = material == MATERIAL_FLOOR;
  const bool is_painting = material >= MATERIAL_PAINTING;
  const vec3 albedo = is_floor      ? floor_albedo(p, albedo_in)
                      : is_painting ? painting_albedo(p, int(material - MATERIAL_PAINTING))
                                    : albedo_in;
  const float roughness = is_floor ? FLOOR_ROUGHNESS : is_painting ? CANVAS_ROUGHNESS : material;
  const vec3 to_eye = light.eye - p;
  const vec3 v = to_eye / dm::sqrt(glm::dot(to_eye, to_eye));
  const float ndl = glm::dot(n, TO_SUN);
  vec3 direct(0.0f);
  if (ndl > 0.0f) {
    const float vis = sun_visibility(p, n, ndl, light, map);
    if (vis > 0.0f) {
      const vec3 hv = TO_SUN + v;
      const vec3 h = hv / dm::sqrt(glm::dot(hv, hv));
      const int k = int(dm::clamp((1.0f - roughness) * 8.0f, 1.0f, 8.0f));
      const float e = float(1 << k);
      const float lobe = power_of_two_power(dm::max(glm::dot(n, h), 0.0f), k);
      const float x = 1.0f - dm::max(glm::dot(h, v), 0.0f);
      const float fresnel = SPECULAR_F0 + (1.0f - SPECULAR_F0) * (x * x * x * x * x);
      const float spec = (e + 8.0f) / (8.0f * dm::PI) * lobe * fresnel;
      direct = SUN_RADIANCE * (vis * ndl) * (albedo + vec3(spec));
    }
  }
  const vec3 ambient = dm::mix(AMBIENT_DOWN, AMBIENT_UP, 0.5f + 0.5f * n.y) +
                       WINDOW_FILL * (0.5f + 0.5f * glm::dot(n, FROM_WINDOW));
  return direct + albedo * ambient;
}

std::vector<ShaderUniform> light_uniforms(const HallLight& light) {
  std::vector<ShaderUniform> u = sun_view_uniforms(sun_view());
  u.push_back({"u_eye", 3, {light.eye.x, light.eye.y, light.eye.z}});
  return u;
}

}  // namespace sdfreel::museum
