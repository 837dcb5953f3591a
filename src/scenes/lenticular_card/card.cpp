#include "scenes/lenticular_card/card.h"

#include "scenes/common/surface_output.h"
#include "scenes/lenticular_card/card_shading.h"
#include "sdf/det_math.h"
#include "sdf/lanes.h"

namespace sdfreel::lenticular_card {

using glm::vec3;

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

V3x8 to_local_direction(const glm::mat4& m, const V3x8& d) {
  return V3x8(m[0][0] * d.x + m[1][0] * d.y + m[2][0] * d.z,
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
  return front_colour<vec3, float>(p, d, u, tex);
}

M8 may_hit_card(const RayPacket& rays, const CardUniforms& u) {
  const glm::mat4& m = u.world_to_local;
  const vec3 o = to_local_point(m, rays.origin);
  const V3x8 d = to_local_direction(m, rays.dir);
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
