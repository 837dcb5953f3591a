#include "scenes/lenticular_card/card_lanes.h"

#include "scenes/lenticular_card/card_shading.h"
#include "sdf/lanes_exp_log.h"

namespace sdfreel::lenticular_card {
namespace {

using glm::vec3;

V3x8 normalize3(const V3x8& v) {
  return v * (1.0f / dm::sqrt(vdot(v, v)));
}

V3x8 matte(const vec3& albedo, const V3x8& n, const vec3& light) {
  return V3x8(albedo) * (AMBIENT + KEY * dm::max(vdot(n, light), 0.0f));
}

// hitBox on eight lanes: the slab loop's updates as selects; a lane parallel to a slab skips it.
M8 hitBox(const vec3& o, const V3x8& d, const vec3& c, const vec3& h, F8& t, F8& axis) {
  F8 t_near = splat(-BIG), t_far = splat(BIG);
  axis = splat(-1.0f);
  M8 outside_parallel_slab = {};
  const F8 dir[3] = {d.x, d.y, d.z};
  for (int i = 0; i < 3; ++i) {
    const M8 parallel = dir[i] == 0.0f;
    if (dm::abs(o[i] - c[i]) > h[i]) outside_parallel_slab |= parallel;
    const F8 a = (c[i] - h[i] - o[i]) / dir[i], b = (c[i] + h[i] - o[i]) / dir[i];
    const M8 swap = a > b;
    const F8 t0 = select(swap, b, a), t1 = select(swap, a, b);
    const M8 nearer = ~parallel & (t0 > t_near), farther = ~parallel & (t1 < t_far);
    t_near = select(nearer, t0, t_near);
    axis = select(nearer, splat(float(i)), axis);
    t_far = select(farther, t1, t_far);
  }
  t = t_near;
  return ~outside_parallel_slab & (axis >= 0.0f) & (t_near <= t_far) & (t_near > 0.0f);
}

// What the glossy sheet reflects (environment() of card.cpp).
V3x8 environment(const V3x8& r) {
  const F8 s = dm::smoothstep(-0.1f, 0.5f, r.y);
  return V3x8(dm::mix(splat(ENV_LOW.x), splat(ENV_HIGH.x), s),
              dm::mix(splat(ENV_LOW.y), splat(ENV_HIGH.y), s),
              dm::mix(splat(ENV_LOW.z), splat(ENV_HIGH.z), s));
}

V3x8 frontColour(const V3x8& p, const V3x8& d, const CardUniforms& u, const CardTextures& tex) {
  const float lenses = float(u.lenses), views = float(u.views), rows = float(u.view_height);
  const F8 lens_coord = (p.x + CARD_HALF_WIDTH) * (lenses / (2.0f * CARD_HALF_WIDTH));
  const F8 lens = dm::clamp(dm::floor(lens_coord), 0.0f, lenses - 1.0f);
  const F8 across = lens_coord - lens - 0.5f;
  const F8 vx = -d.x, vz = -d.z;
  const F8 len = dm::sqrt(vx * vx + vz * vz);
  const F8 sin_theta = select(len > 0.0f, vx / len, splat(0.0f));
  const F8 s = sin_theta / u.ior;  // seen_print_position(lens + 0.5, ...), written out
  const F8 x = (lens + 0.5f) - u.thickness * (s / dm::sqrt(1.0f - s * s));
  const F8 column = dm::clamp(dm::floor(x * views), 0.0f, lenses * views - 1.0f);
  const F8 down = (CARD_CENTRE_Y + CARD_HALF_HEIGHT - p.y) * (0.5f / CARD_HALF_HEIGHT);
  const F8 row = dm::floor((down + u.scroll) * rows);
  V3x8 albedo, n;
  for (int i = 0; i < LANES; ++i) {  // texel reads: one lane at a time, as shadeCard reads them
    albedo.set_lane(i, vec3(print_texel(tex, u.views, column[i], row[i])));
    n.set_lane(i, ridge_tilt(lens_coord[i], across[i], p.y[i], u, tex));
  }
  n = normalize3(n);
  const V3x8 v = normalize3(-d);
  const V3x8 diffuse = albedo * (AMBIENT + KEY * dm::max(u.light.z, 0.0f));
  const F8 n_dot_v = vdot(n, v);
  const F8 cos_v = dm::max(n_dot_v, 0.0f);
  const F8 m = 1.0f - cos_v, m2 = m * m;
  const F8 fresnel = F0 + (1.0f - F0) * (m2 * m2 * m);
  const V3x8 r = n * (2.0f * n_dot_v) - v;
  const V3x8 h = normalize3(u.light + v);
  const F8 spec = SPECULAR * KEY * dm::pow(dm::max(vdot(n, h), 0.0f), SHININESS);
  return diffuse * (1.0f - fresnel) + (environment(r) * fresnel + V3x8(spec, spec, spec)) * u.gloss;
}

}  // namespace

M8 shadeCard_lanes(const RayPacket& rays, const CardUniforms& u, const CardTextures& tex,
                   V3x8& colour, F8& t) {
  const glm::mat4& m = u.world_to_local;
  const vec3 o = to_local_point(m, rays.origin);
  const V3x8& w = rays.dir;
  const V3x8 d(m[0][0] * w.x + m[1][0] * w.y + m[2][0] * w.z,
               m[0][1] * w.x + m[1][1] * w.y + m[2][1] * w.z,
               m[0][2] * w.x + m[1][2] * w.y + m[2][2] * w.z);
  F8 t_card, t_base, a_card, a_base;
  const M8 card =
      hitBox(o, d, vec3(0.0f, CARD_CENTRE_Y, 0.0f),
             vec3(CARD_HALF_WIDTH, CARD_HALF_HEIGHT, CARD_HALF_THICKNESS), t_card, a_card);
  const M8 base = hitBox(o, d, vec3(0.0f, BASE_HALF_HEIGHT, 0.0f),
                         vec3(BASE_HALF_WIDTH, BASE_HALF_HEIGHT, BASE_HALF_DEPTH), t_base, a_base);
  const M8 on_card = card & (~base | (t_card <= t_base));
  t = select(on_card, t_card, t_base);
  const F8 axis = select(on_card, a_card, a_base);
  // n[axis] = d[axis] < 0 ? 1 : -1, the other components 0.
  const V3x8 facing(select(d.x < 0.0f, splat(1.0f), splat(-1.0f)),
                    select(d.y < 0.0f, splat(1.0f), splat(-1.0f)),
                    select(d.z < 0.0f, splat(1.0f), splat(-1.0f)));
  const V3x8 n(select(axis == 0.0f, facing.x, splat(0.0f)),
               select(axis == 1.0f, facing.y, splat(0.0f)),
               select(axis == 2.0f, facing.z, splat(0.0f)));
  const M8 front = on_card & (axis == 2.0f) & (n.z > 0.0f);
  V3x8 c = select(on_card, select(axis == 2.0f, matte(PAPER, n, u.light), matte(EDGE, n, u.light)),
                  matte(WOOD, n, u.light));
  if (any(front)) c = select(front, frontColour(o + d * t, d, u, tex), c);
  colour = c;
  return card | base;
}

}  // namespace sdfreel::lenticular_card
