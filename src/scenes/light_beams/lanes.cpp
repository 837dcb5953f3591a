#include "scenes/light_beams/lanes.h"

#include "scenes/light_beams/crossings.h"
#include "scenes/light_beams/render.h"
#include "scenes/light_beams/visibility.h"
#include "sdf/lanes_exp_log.h"

namespace sdfreel::light_beams {
namespace {

// Constants of render.cpp (kept in step with it and with the GLSL twin).
constexpr float AA_PIXELS = 1.5f;
constexpr float FRAME_X_SCALE = 0.5625f;
constexpr float FADE_INNER = 0.35f;
constexpr float FADE_OUTER = 1.4f;
constexpr float EMPTY_SLOT = 3.0e38f;  // start of an unused interval slot: sorts after all others

struct P8 {
  F8 x, y;
};

P8 sub(P8 a, vec2 b) {
  return {a.x - b.x, a.y - b.y};
}
P8 sub(vec2 a, P8 b) {
  return {a.x - b.x, a.y - b.y};
}
F8 dot8(P8 a, P8 b) {
  return a.x * b.x + a.y * b.y;
}
F8 dot8(P8 a, vec2 b) {
  return a.x * b.x + a.y * b.y;
}
F8 cross8(P8 a, P8 b) {
  return a.x * b.y - a.y * b.x;
}
F8 length8(P8 v) {
  return dm::sqrt(dot8(v, v));
}
P8 select8(M8 m, P8 a, P8 b) {
  return {select(m, a.x, b.x), select(m, a.y, b.y)};
}

F8 smoothstep8(F8 e1, F8 x) {  // dm::smoothstep(0, e1, x)
  const F8 t = dm::clamp((x - 0.0f) / (e1 - 0.0f), 0.0f, 1.0f);
  const F8 s = t * t * (3.0f - 2.0f * t);
  return select(e1 == 0.0f, select(x < 0.0f, splat(0.0f), splat(1.0f)), s);
}

// ---- shapes.h ----
F8 segmentParam8(P8 p, vec2 a, vec2 b) {
  const vec2 ba = b - a;
  const P8 pa = sub(p, a);
  const float bb = dotv(ba, ba);
  if (!(bb > 0.0f)) return splat(0.0f);
  return dm::clamp(dot8(pa, ba) / bb, 0.0f, 1.0f);
}

F8 shapeSDF8(P8 p, const Shape& s) {
  if (s.type == SHAPE_CIRCLE) return length8(sub(p, s.a)) - s.r;
  const F8 h = segmentParam8(p, s.a, s.b);
  const P8 pa = sub(p, s.a);
  const vec2 ba = s.b - s.a;
  return length8(P8{pa.x - ba.x * h, pa.y - ba.y * h}) - s.r;
}

P8 corePoint8(P8 p, const Shape& s) {
  if (s.type == SHAPE_CIRCLE) return P8{splat(s.a.x), splat(s.a.y)};
  const F8 h = segmentParam8(p, s.a, s.b);
  const vec2 ba = s.b - s.a;
  return P8{s.a.x + ba.x * h, s.a.y + ba.y * h};
}

F8 angleFrom8(P8 n, P8 v) {
  return dm::atan2(cross8(n, v), dot8(n, v));
}

P8 discSpan8(P8 p, P8 n, vec2 c, float r) {
  const P8 v = sub(c, p);
  const F8 phi = angleFrom8(n, v);
  const F8 half = dm::asin(dm::min(r / length8(v), 1.0f));
  return P8{phi - half, phi + half};
}

// What angularSpan (shapes.h) computes of a shape at the packet's points whatever the direction n,
// once per packet instead of once per light: its distance, and for a circle c - p and the half
// angle, for a capsule the unit direction m to its core and the hull of its end discs' spans around
// m. spanFrom8 then adds the one angle that depends on n: the same operations, the same bits.
struct ShapeView8 {
  F8 sdf;
  P8 v;       // circle: c - p; capsule: m
  F8 lo, hi;  // circle: -half, +half (unused); capsule: the hull relative to m
};

ShapeView8 shapeView8(P8 p, const Shape& s) {
  ShapeView8 sv;
  sv.sdf = shapeSDF8(p, s);
  if (s.type == SHAPE_CIRCLE) {
    sv.v = sub(s.a, p);
    sv.hi = dm::asin(dm::min(s.r / length8(sv.v), 1.0f));
    sv.lo = -sv.hi;
    return sv;
  }
  const P8 c = corePoint8(p, s);
  const P8 own{c.x - p.x, c.y - p.y};
  const F8 own_len = length8(own);
  // own_len == 0: p on the core, inside the shape; angularSpan's fallback (n) is never used.
  sv.v =
      select8(own_len > 0.0f, P8{own.x / own_len, own.y / own_len}, P8{splat(1.0f), splat(0.0f)});
  const P8 ea = discSpan8(p, sv.v, s.a, s.r), eb = discSpan8(p, sv.v, s.b, s.r);
  sv.lo = dm::min(ea.x, eb.x);
  sv.hi = dm::max(ea.y, eb.y);
  return sv;
}

// angularSpan(p, n, s) in lanes, from the shape's view.
P8 spanFrom8(P8 n, const ShapeView8& sv, const Shape& s) {
  if (s.type == SHAPE_CIRCLE) {
    const F8 phi = angleFrom8(n, sv.v);
    return P8{phi - sv.hi, phi + sv.hi};
  }
  const F8 turn = angleFrom8(n, sv.v);
  return P8{sv.lo + turn, sv.hi + turn};
}

F8 hitDisc8(P8 p, P8 dir, vec2 c, float r) {
  const P8 oc = sub(p, c);
  const F8 b = dot8(oc, dir);
  const P8 q{oc.x - dir.x * b, oc.y - dir.y * b};
  const F8 h = r * r - dot8(q, q);
  const F8 t = -b - dm::sqrt(h);
  return select((h < 0.0f) | ~(t >= 0.0f), splat(NO_HIT), t);
}

F8 nearerHit8(F8 t0, F8 t1) {
  return select(t0 == NO_HIT, t1, select(t1 == NO_HIT, t0, dm::min(t0, t1)));
}

F8 hitShape8(P8 p, P8 dir, const Shape& s) {
  const F8 ta = hitDisc8(p, dir, s.a, s.r);
  if (s.type == SHAPE_CIRCLE) return ta;
  F8 t = nearerHit8(ta, hitDisc8(p, dir, s.b, s.r));
  const vec2 ba = s.b - s.a;
  const float len = lengthv(ba);
  if (len > 0.0f) {
    const vec2 axis = ba / len;
    const vec2 nrm = vec2(-axis.y, axis.x);
    const F8 s0 = dot8(sub(p, s.a), nrm);
    const F8 dn = dot8(dir, nrm);
    const F8 side = select(s0 >= 0.0f, splat(s.r), splat(-s.r));
    const F8 ts = (side - s0) / dn;
    const P8 at{(p.x + dir.x * ts) - s.a.x, (p.y + dir.y * ts) - s.a.y};
    const F8 y = dot8(at, axis);
    const M8 take = (dn != 0.0f) & (ts >= 0.0f) & (y >= 0.0f) & (y <= len);
    t = select(take, nearerHit8(t, ts), t);
  }
  return t;
}

// ---- visibility.cpp ----
struct LightView8 {
  P8 n, span;
};

LightView8 viewOf8(P8 p, const Shape& light, const ShapeView8& sv) {
  const P8 c = corePoint8(p, light);
  const P8 v{c.x - p.x, c.y - p.y};
  const F8 len = length8(v);
  LightView8 lv;
  lv.n = select8(len > 0.0f, P8{v.x / len, v.y / len}, P8{splat(1.0f), splat(0.0f)});
  lv.span = spanFrom8(lv.n, sv, light);
  return lv;
}

P8 turn8(P8 n, F8 a) {
  const F8 c = dm::cos(a), s = dm::sin(a);
  return P8{n.x * c - n.y * s, n.x * s + n.y * c};
}

// inFront for each lane.
M8 inFront8(P8 p, P8 n, F8 a, const Shape& light, const Shape& other) {
  const P8 dir = turn8(n, a);
  const F8 t_other = hitShape8(p, dir, other);
  const F8 t_light = hitShape8(p, dir, light);
  return ~((t_other == NO_HIT) | ((t_light != NO_HIT) & (t_light < t_other)));
}

// mayBeInFront for each lane.
M8 mayBeInFront8(P8 p, int light, int j, const BeamsUniforms& u) {
  const int pair = pairIndex(light, j);
  const int mode = u.pair_mode[pair];
  if (mode == PAIR_APART) {
    const glm::vec4 line = u.pair_line[pair];
    const F8 side = (p.x - line.x) * line.z + (p.y - line.y) * line.w;
    return j > light ? side > 0.0f : side < 0.0f;
  }
  const bool may =
      mode == PAIR_CROSSING || mode == (light < j ? PAIR_FIRST_INSIDE : PAIR_SECOND_INSIDE);
  return splat_mask(may);
}

// hiddenParts for the lanes in `alive` (where mayBeInFront8): returns the hidden width and appends
// slots to slots[n...]
// ((start, end) where hidden, start EMPTY_SLOT where not). A part that no alive lane needs
// (empty, or spans that do not overlap) is not tested, as the scalar code skips it; a part
// hidden in no lane adds no slot (EMPTY_SLOT slots change nothing in the union).
F8 hiddenParts8(P8 p, const LightView8& lv, int light, int j, M8 alive, const BeamsUniforms& u,
                const ShapeView8* views, P8* slots, int& n) {
  const Shape &l = u.shapes[light], &other = u.shapes[j];
  F8 hidden_width = splat(0.0f);
  const P8 o = spanFrom8(lv.n, views[j], other);
  const F8 lo = dm::max(lv.span.x, o.x), hi = dm::min(lv.span.y, o.y);
  alive &= lo < hi;
  if (!any(alive)) return hidden_width;
  const int pair = pairIndex(light, j);
  if (u.pair_mode[pair] != PAIR_CROSSING) {
    if (slots) slots[n++] = P8{select(alive, lo, splat(EMPTY_SLOT)), hi};
    return select(alive, hi - lo, hidden_width);
  }
  F8 cuts[MAX_PAIR_CROSSINGS];
  int cut_count = 0;
  for (int k = u.crossing_first[pair]; k < u.crossing_first[pair + 1]; ++k)
    cuts[cut_count++] = dm::min(dm::max(angleFrom8(lv.n, sub(u.crossings[k], p)), lo), hi);
  // Sorted (odd-even transposition: the same values in the same order as an insertion sort).
  for (int round = 0; round < cut_count; ++round) {
    for (int k = round % 2; k + 1 < cut_count; k += 2) {
      const F8 a = cuts[k], b = cuts[k + 1];
      cuts[k] = dm::min(a, b);
      cuts[k + 1] = dm::max(a, b);
    }
  }
  F8 start = lo;
  for (int k = 0; k <= cut_count; ++k) {
    const F8 end = k < cut_count ? cuts[k] : hi;
    const M8 part = alive & (start < end);
    if (any(part)) {
      const M8 hidden = part & inFront8(p, lv.n, 0.5f * (start + end), l, other);
      hidden_width = select(hidden, hidden_width + (end - start), hidden_width);
      if (slots && any(hidden)) slots[n++] = P8{select(hidden, start, splat(EMPTY_SLOT)), end};
    }
    start = end;
  }
  return hidden_width;
}

// A cone of directions around the light's span, to skip shapes that surely miss it. Only a
// shortcut: a skipped shape is one whose span, computed in full, could not overlap the light's
// for any lane (CULL_MARGIN radians of slack cover the rounding of both), so skipping changes no
// bit.
constexpr float CULL_MARGIN = 1e-3f;
struct LightCone8 {
  P8 mid;       // unit direction of the span's middle
  F8 cos_half;  // of half the span plus the margin
  F8 sin_half;
  M8 usable;  // half span plus margin <= pi/2 (so that half span + a disc's half angle < pi)
};

LightCone8 coneOf8(const LightView8& lv) {
  LightCone8 c;
  c.mid = turn8(lv.n, 0.5f * (lv.span.x + lv.span.y));
  const F8 half = 0.5f * (lv.span.y - lv.span.x) + CULL_MARGIN;
  c.cos_half = dm::cos(half);
  c.sin_half = dm::sin(half);
  c.usable = half <= dm::HALF_PI;
  return c;
}

// True for lanes where the disc (c, r), which holds the whole shape, lies outside the cone.
M8 missesCone8(P8 p, const LightCone8& cone, vec2 c, float r) {
  const P8 w = sub(c, p);
  const F8 dist = length8(w);
  const F8 sin_disc = r / dist;
  const F8 cos_disc = dm::sqrt(dm::max(1.0f - sin_disc * sin_disc, 0.0f));
  const F8 cos_limit = cone.cos_half * cos_disc - cone.sin_half * sin_disc;
  const F8 cos_angle = dot8(cone.mid, w) / dist;
  return cone.usable & (sin_disc < 1.0f) & (cos_angle < cos_limit);
}

// A disc that holds the shape.
void boundOf(const Shape& s, vec2& c, float& r) {
  if (s.type == SHAPE_CIRCLE) {
    c = s.a;
    r = s.r;
    return;
  }
  c = 0.5f * (s.a + s.b);
  r = 0.5f * lengthv(s.b - s.a) + s.r;
}

// penumbraVisibility / exactVisibility for the lanes in `active`.
F8 visibility8(P8 p, int light, M8 active, bool exact, const BeamsUniforms& u,
               const ShapeView8* views, RayStats& stats) {
  const Shape& l = u.shapes[light];
  const LightView8 lv = viewOf8(p, l, views[light]);
  const F8 width = lv.span.y - lv.span.x;
  const M8 wide = width > 0.0f;
  M8 alive = active & wide;
  M8 dark = splat_mask(false);  // inside another shape: 0
  F8 vis = splat(1.0f);
  P8 slots[SHAPE_COUNT - 1 + MAX_CROSSINGS];  // exact: the hidden parts, in the shapes' order
  int n = 0;
  const LightCone8 cone = coneOf8(lv);
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == light || !castsShadow(j, u)) continue;
    if (!any(alive)) break;  // every lane has its answer: no more counts, no more work
    stats.count_evals(alive);
    const M8 in = alive & (views[j].sdf <= 0.0f);
    dark |= in;
    alive &= ~in;
    // Cheap tests first: the side of the pair's separating line, then the cone.
    const M8 may = alive & mayBeInFront8(p, light, j, u);
    if (!any(may)) continue;
    vec2 bc;
    float br;
    boundOf(u.shapes[j], bc, br);
    if (!any(may & ~missesCone8(p, cone, bc, br))) continue;
    const F8 hidden = hiddenParts8(p, lv, light, j, may, u, views, exact ? slots : nullptr, n);
    if (!exact) vis = select(alive, vis * (1.0f - hidden / width), vis);
  }
  if (exact) {
    // Stable sort by start (odd-even transposition, swapping only on >): the scalar insertion
    // sort's order, ties included.
    for (int round = 0; round < n; ++round) {
      for (int k = round % 2; k + 1 < n; k += 2) {
        const M8 swap = slots[k].x > slots[k + 1].x;
        const P8 a = slots[k], b = slots[k + 1];
        slots[k] = select8(swap, b, a);
        slots[k + 1] = select8(swap, a, b);
      }
    }
    F8 covered = splat(0.0f);
    F8 reach = lv.span.x;
    for (int k = 0; k < n; ++k) {
      const M8 used = slots[k].x != EMPTY_SLOT;
      const F8 lo = dm::max(slots[k].x, reach);
      const M8 grow = used & (slots[k].y > lo);
      covered = select(grow, covered + (slots[k].y - lo), covered);
      reach = select(grow, slots[k].y, reach);
    }
    vis = dm::clamp(1.0f - covered / width, 0.0f, 1.0f);
  } else {
    vis = dm::max(vis, 0.0f);
  }
  return select(wide, select(dark, splat(0.0f), vis), splat(1.0f));
}

// The seed's getNearestDist and its one-ray shadow (seedShadow) for the lanes in `active`: each
// lane marches until it hits, passes the light or runs out of steps.
F8 nearestDist8(P8 p, int skip, M8 active, const BeamsUniforms& u, RayStats& stats) {
  F8 d = splat(1e30f);
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == skip || !castsShadow(j, u)) continue;
    stats.count_evals(active);
    d = dm::min(d, shapeSDF8(p, u.shapes[j]));
  }
  return d;
}

F8 seedShadow8(P8 p, int light, F8 dist_to_light, M8 active, const BeamsUniforms& u,
               RayStats& stats) {
  const Shape& l = u.shapes[light];
  // closestPoint
  const P8 c = corePoint8(p, l);
  const P8 pc{p.x - c.x, p.y - c.y};
  const F8 pc_len = length8(pc);
  const P8 q = select8(pc_len > 0.0f, P8{c.x + pc.x * (l.r / pc_len), c.y + pc.y * (l.r / pc_len)},
                       P8{c.x + l.r, c.y + 0.0f});
  const P8 v{q.x - p.x, q.y - p.y};
  const F8 len = length8(v);
  const P8 dir = select8(len > 0.0f, P8{v.x / len, v.y / len}, P8{splat(1.0f), splat(0.0f)});
  F8 t = splat(0.0f);
  F8 res = splat(1.0f);
  for (int i = 0; i < u.shadow_steps && any(active); ++i) {
    stats.steps += count_lanes(active);
    const F8 h = nearestDist8(P8{p.x + dir.x * t, p.y + dir.y * t}, light, active, u, stats);
    const M8 hit = active & (h <= u.min_hit_dist);
    res = select(hit, splat(0.0f), res);
    active &= ~hit;
    t = select(active, t + dm::clamp(h, u.min_hit_dist, u.max_trace_dist), t);
    active &= ~((t > dist_to_light) | (t > u.max_trace_dist));
  }
  return res;
}

F8 cornerFade8(P8 p) {
  const F8 r = length8(P8{p.x * FRAME_X_SCALE, p.y});
  return 1.0f - dm::smoothstep(FADE_INNER, FADE_OUTER, r);
}

}  // namespace

void radiancePacket(const RayPacket& rays, const BeamsUniforms& u, glm::vec3* out,
                    RayStats& stats) {
  if (u.hit_mask) {
    for (int i = 0; i < rays.count; ++i) out[i] = sceneRadiance(rays.ray(i), u, stats);
    return;
  }
  const glm::vec3 o = rays.origin;
  const V3x8& dir = rays.dir;
  const M8 on_plane = (o.z * dir.z) < 0.0f;
  const M8 live = rays.valid() & on_plane;
  const F8 t = -o.z / dir.z;
  const P8 p{o.x + dir.x * t, o.y + dir.y * t};
  const F8 aa_width = AA_PIXELS * (rays.pixel_angle * t);
  const bool exact = u.estimator == ESTIMATOR_EXACT;
  const bool seed = u.estimator == ESTIMATOR_SEED_RAY;
  if (!any(live)) {  // no ray meets the plane: nothing to evaluate, nothing to count
    for (int i = 0; i < rays.count; ++i) out[i] = u.background;
    return;
  }
  ShapeView8 views[SHAPE_COUNT];  // penumbra and exact: every shape's view, shared by the lights
  if (!seed)
    for (int j = 0; j < SHAPE_COUNT; ++j) views[j] = shapeView8(p, u.shapes[j]);
  F8 r = splat(u.background.x), g = splat(u.background.y), b = splat(u.background.z);
  for (int i = 0; i < OCCLUDER; ++i) {
    if (!(u.gain[i] > 0.0f)) continue;
    stats.count_evals(live);
    const F8 d = seed ? shapeSDF8(p, u.shapes[i]) : views[i].sdf;
    const F8 fade = 1.0f * (1.0f - u.fades[i]) + cornerFade8(p) * u.fades[i];
    const F8 gain = u.gain[i] * fade;
    const M8 inside = d <= 0.0f;
    const F8 vis = seed ? seedShadow8(p, i, d, live & ~inside, u, stats)
                        : visibility8(p, i, live & ~inside, exact, u, views, stats);
    const F8 att = 1.0f / (u.glow_constant + u.glow_linear * d + u.glow_quadratic * (d * d));
    const glm::vec3 c = u.color[i];
    const F8 edge = smoothstep8(aa_width, d);
    const F8 k = gain * vis;
    r += select(inside, gain, (1.0f * (1.0f - edge) + (c.x * att) * edge) * k);
    g += select(inside, gain, (1.0f * (1.0f - edge) + (c.y * att) * edge) * k);
    b += select(inside, gain, (1.0f * (1.0f - edge) + (c.z * att) * edge) * k);
  }
  for (int i = 0; i < rays.count; ++i)
    out[i] = lane(on_plane, i) ? glm::vec3(r[i], g[i], b[i]) : u.background;
}

std::vector<DistanceFunction> beamsDistanceFunctions(const BeamsUniforms& u) {
  // The seed's getNearestDist over every shape, at (x, y) of the points (the plane ignores z).
  DistanceFunction nearest{"getNearestDist", nullptr, nullptr};
  nearest.scalar = [u](const float* x, const float* y, const float*, float* d, int n) {
    RayStats ignored;
    for (int i = 0; i < n; ++i) d[i] = nearestDist(vec2(x[i], y[i]), -1, u, ignored);
  };
  nearest.lanes = [u](const float* x, const float* y, const float*, float* d, int n) {
    RayStats ignored;
    for (int i = 0; i < n; i += LANES)
      store8(d + i, nearestDist8(P8{load8(x + i), load8(y + i)}, -1, splat_mask(true), u, ignored));
  };
  return {nearest};
}

}  // namespace sdfreel::light_beams
