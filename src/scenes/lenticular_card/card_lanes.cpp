#include "scenes/lenticular_card/card_lanes.h"

#include "scenes/lenticular_card/card_shading.h"

namespace sdfreel::lenticular_card {
namespace {

using glm::vec3;

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

}  // namespace

M8 shadeCard_lanes(const RayPacket& rays, const CardUniforms& u, const CardTextures& tex,
                   V3x8& colour, F8& t) {
  const glm::mat4& m = u.world_to_local;
  const vec3 o = to_local_point(m, rays.origin);
  const V3x8 d = to_local_direction(m, rays.dir);
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
  if (any(front)) c = select(front, front_colour<V3x8, F8>(o + d * t, d, u, tex), c);
  colour = c;
  return card | base;
}

}  // namespace sdfreel::lenticular_card
