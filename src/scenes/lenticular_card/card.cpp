#include "scenes/lenticular_card/card.h"

#include "scenes/common/surface_output.h"
#include "scenes/lenticular_card/card_shading.h"
#include "scenes/lenticular_card/optics.h"
#include "sdf/det_math.h"
#include "sdf/lanes.h"

namespace sdfreel::lenticular_card {
namespace {

using glm::vec2;
using glm::vec3;

float dot3(const vec3& a, const vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

vec3 normalize3(const vec3& v) {
  return v * (1.0f / dm::sqrt(dot3(v, v)));
}

vec3 matte(const vec3& albedo, const vec3& n, const vec3& light) {
  return albedo * (AMBIENT + KEY * dm::max(dot3(n, light), 0.0f));
}

// What the glossy sheet reflects: a dark floor below, a bright room above.
vec3 environment(const vec3& r) {
  return dm::mix(ENV_LOW, ENV_HIGH, dm::smoothstep(-0.1f, 0.5f, r.y));
}

// The sheet's normal: the lens profile across each lens plus the stretched noise map.
vec3 ridgeNormal(float lens_coord, float across, float y, const CardUniforms& u,
                 const CardTextures& tex) {
  return normalize3(ridge_tilt(lens_coord, across, y, u, tex));
}

}  // namespace

vec3 to_local_point(const glm::mat4& m, const vec3& p) {
  return vec3(m[0][0] * p.x + m[1][0] * p.y + m[2][0] * p.z + m[3][0],
              m[0][1] * p.x + m[1][1] * p.y + m[2][1] * p.z + m[3][1],
              m[0][2] * p.x + m[1][2] * p.y + m[2][2] * p.z + m[3][2]);
}

vec3 to_local_direction(const glm::mat4& m, const vec3& d) {
  return vec3(m[0][0] * d.x + m[1][0] * d.y + m[2][0] * d.z,
              m[0][1] * d.x + m[1][1] * d.y + m[2][1] * d.z,
              m[0][2] * d.x + m[1][2] * d.y + m[2][2] * d.z);
}

bool hitBox(const vec3& o, const vec3& d, const vec3& c, const vec3& h, float& t, int& axis) {
  float t_near = -BIG, t_far = BIG;
  axis = -1;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0f) {  // parallel to this slab: inside it or never
      if (dm::abs(o[i] - c[i]) > h[i]) return false;
      continue;
    }
    float t0 = (c[i] - h[i] - o[i]) / d[i], t1 = (c[i] + h[i] - o[i]) / d[i];
    if (t0 > t1) {
      const float s = t0;
      t0 = t1;
      t1 = s;
    }
    if (t0 > t_near) t_near = t0, axis = i;
    if (t1 < t_far) t_far = t1;
  }
  t = t_near;
  return axis >= 0 && t_near <= t_far && t_near > 0.0f;
}

vec3 frontColour(const vec3& p, const vec3& d, const CardUniforms& u, const CardTextures& tex) {
  const float lenses = float(u.lenses), views = float(u.views), rows = float(u.view_height);
  const float lens_coord = (p.x + CARD_HALF_WIDTH) * (lenses / (2.0f * CARD_HALF_WIDTH));
  const float lens = dm::clamp(dm::floor(lens_coord), 0.0f, lenses - 1.0f);
  const float across = lens_coord - lens - 0.5f;
  // The viewing angle across the lenses: the view direction projected on the xz plane.
  const float vx = -d.x, vz = -d.z;
  const float len = dm::sqrt(vx * vx + vz * vz);
  const float sin_theta = len > 0.0f ? vx / len : 0.0f;
  const float x = seen_print_position(lens + 0.5f, sin_theta, u.ior, u.thickness);
  const float column = dm::clamp(dm::floor(x * views), 0.0f, lenses * views - 1.0f);
  const float down = (CARD_CENTRE_Y + CARD_HALF_HEIGHT - p.y) * (0.5f / CARD_HALF_HEIGHT);
  const float row = dm::floor((down + u.scroll) * rows);
  const vec3 albedo = vec3(print_texel(tex, u.views, column, row));
  const vec3 n = ridgeNormal(lens_coord, across, p.y, u, tex);
  const vec3 v = normalize3(-d);
  const vec3 diffuse = albedo * (AMBIENT + KEY * dm::max(u.light.z, 0.0f));
  const float cos_v = dm::max(dot3(n, v), 0.0f);
  const float m = 1.0f - cos_v, m2 = m * m;
  const float fresnel = F0 + (1.0f - F0) * (m2 * m2 * m);
  const vec3 r = n * (2.0f * dot3(n, v)) - v;
  const vec3 h = normalize3(u.light + v);
  const float spec = SPECULAR * KEY * dm::pow(dm::max(dot3(n, h), 0.0f), SHININESS);
  return diffuse * (1.0f - fresnel) + (environment(r) * fresnel + vec3(spec)) * u.gloss;
}

M8 may_hit_card(const RayPacket& rays, const CardUniforms& u) {
  const glm::mat4& m = u.world_to_local;
  const vec3 o = to_local_point(m, rays.origin);
  const V3x8& w = rays.dir;
  const V3x8 d(m[0][0] * w.x + m[1][0] * w.y + m[2][0] * w.z,
               m[0][1] * w.x + m[1][1] * w.y + m[2][1] * w.z,
               m[0][2] * w.x + m[1][2] * w.y + m[2][2] * w.z);
  // The card's and the stand's boxes together, grown by 1 cm plus 1e-5 of the origin's distance.
  const float margin = 0.01f + 1e-5f * dm::max(dm::abs(o.x), dm::max(dm::abs(o.y), dm::abs(o.z)));
  const vec3 lo(-CARD_HALF_WIDTH - margin, -margin, -BASE_HALF_DEPTH - margin);
  const vec3 hi(CARD_HALF_WIDTH + margin, CARD_CENTRE_Y + CARD_HALF_HEIGHT + margin,
                BASE_HALF_DEPTH + margin);
  F8 t_near = splat(-BIG), t_far = splat(BIG);
  const F8 dir[3] = {d.x, d.y, d.z};
  for (int i = 0; i < 3; ++i) {
    // Division by 0 gives infinities of one sign when the origin is outside the slab (a miss);
    // NaN (origin on the slab's face) fails every comparison below, so the lane is kept.
    const F8 t0 = (lo[i] - o[i]) / dir[i], t1 = (hi[i] - o[i]) / dir[i];
    t_near = dm::max(t_near, dm::min(t0, t1));
    t_far = dm::min(t_far, dm::max(t0, t1));
  }
  return ~((t_near > t_far) | (t_far < 0.0f));
}

bool shadeCard(const Ray& ray, const CardUniforms& u, const CardTextures& tex, vec3& colour,
               float& t) {
  const vec3 o = to_local_point(u.world_to_local, ray.origin);
  const vec3 d = to_local_direction(u.world_to_local, ray.dir);
  float t_card = BIG, t_base = BIG;
  int a_card = -1, a_base = -1;
  const bool card =
      hitBox(o, d, vec3(0.0f, CARD_CENTRE_Y, 0.0f),
             vec3(CARD_HALF_WIDTH, CARD_HALF_HEIGHT, CARD_HALF_THICKNESS), t_card, a_card);
  const bool base =
      hitBox(o, d, vec3(0.0f, BASE_HALF_HEIGHT, 0.0f),
             vec3(BASE_HALF_WIDTH, BASE_HALF_HEIGHT, BASE_HALF_DEPTH), t_base, a_base);
  if (!card && !base) return false;
  const bool on_card = card && (!base || t_card <= t_base);
  t = on_card ? t_card : t_base;
  const int axis = on_card ? a_card : a_base;
  vec3 n(0.0f);
  n[axis] = d[axis] < 0.0f ? 1.0f : -1.0f;
  if (u.surface != SURFACE_COLOUR) {  // the local axis's normal in the world: a row of the inverse
    const glm::mat4& m = u.world_to_local;
    colour = surfaceOutput(u.surface, t, n[axis] * vec3(m[0][axis], m[1][axis], m[2][axis]));
    return true;
  }
  if (u.hit_mask) {
    colour = vec3(u.hit_id_base + (on_card ? HIT_ID_CARD : HIT_ID_STAND));
  } else if (!on_card) {
    colour = matte(WOOD, n, u.light);
  } else if (axis == 2 && n.z > 0.0f) {
    colour = frontColour(o + d * t, d, u, tex);
  } else {
    colour = matte(axis == 2 ? PAPER : EDGE, n, u.light);
  }
  return true;
}

}  // namespace sdfreel::lenticular_card
