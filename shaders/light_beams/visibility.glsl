// light_beams: how much of a light a point sees, the twin of src/scenes/light_beams/
// visibility.cpp (the Monte Carlo check stays on the CPU). Reads u_beams directly.

const float FAR_AWAY = 1e30;

struct LightView {
  vec2 n;
  vec2 span;
};

LightView viewOf(vec2 p, Shape light) {
  precise vec2 v = corePoint(p, light) - p;
  precise float len = lengthv(v);
  LightView lv;
  lv.n = len > 0.0 ? v / len : vec2(1.0, 0.0);
  lv.span = angularSpan(p, lv.n, light);
  return lv;
}

vec2 turn(vec2 n, float a) {
  precise float c = dm_cos(a);
  precise float s = dm_sin(a);
  return vec2(n.x * c - n.y * s, n.x * s + n.y * c);
}

vec2 hiddenSpan(vec2 p, LightView lv, Shape light, Shape other) {
  precise vec2 o = angularSpan(p, lv.n, other);
  precise float lo = dm_max(lv.span.x, o.x);
  precise float hi = dm_min(lv.span.y, o.y);
  if (!(lo < hi)) return vec2(0.0, 0.0);
  precise vec2 dir = turn(lv.n, 0.5 * (lo + hi));
  precise float t_other = hitShape(p, dir, other);
  precise float t_light = hitShape(p, dir, light);
  if (t_other == NO_HIT || (t_light != NO_HIT && t_light < t_other)) return vec2(0.0, 0.0);
  return vec2(lo, hi);
}

float nearestDist(vec2 p, int skip, inout RayStats stats) {
  precise float d = FAR_AWAY;
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == skip) continue;
    stats.sdf_evals += 1u;
    d = dm_min(d, shapeSDF(p, u_beams.shapes[j]));
  }
  return d;
}

float seedShadow(vec2 p, int light, float dist_to_light, inout RayStats stats) {
  precise vec2 v = closestPoint(p, u_beams.shapes[light]) - p;
  precise float len = lengthv(v);
  precise vec2 dir = len > 0.0 ? v / len : vec2(1.0, 0.0);
  precise float t = 0.0;
  for (int i = 0; i < u_beams.shadow_steps; ++i) {
    stats.steps += 1u;
    precise float h = nearestDist(p + dir * t, light, stats);
    if (h <= u_beams.min_hit_dist) return 0.0;
    t += dm_clamp(h, u_beams.min_hit_dist, u_beams.max_trace_dist);
    if (t > dist_to_light || t > u_beams.max_trace_dist) break;
  }
  return 1.0;
}

float penumbraVisibility(vec2 p, int light, inout RayStats stats) {
  Shape l = u_beams.shapes[light];
  LightView lv = viewOf(p, l);
  precise float width = lv.span.y - lv.span.x;
  if (!(width > 0.0)) return 1.0;
  precise float vis = 1.0;
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == light) continue;
    stats.sdf_evals += 1u;
    if (shapeSDF(p, u_beams.shapes[j]) <= 0.0) return 0.0;
    precise vec2 h = hiddenSpan(p, lv, l, u_beams.shapes[j]);
    if (h.x < h.y) vis *= 1.0 - (h.y - h.x) / width;
  }
  return dm_max(vis, 0.0);
}

float exactVisibility(vec2 p, int light, inout RayStats stats) {
  Shape l = u_beams.shapes[light];
  LightView lv = viewOf(p, l);
  precise float width = lv.span.y - lv.span.x;
  if (!(width > 0.0)) return 1.0;
  precise vec2 hidden[SHAPE_COUNT];
  int count = 0;
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == light) continue;
    stats.sdf_evals += 1u;
    if (shapeSDF(p, u_beams.shapes[j]) <= 0.0) return 0.0;
    precise vec2 h = hiddenSpan(p, lv, l, u_beams.shapes[j]);
    if (!(h.x < h.y)) continue;
    int k = count;
    while (k > 0 && hidden[k - 1].x > h.x) {
      hidden[k] = hidden[k - 1];
      --k;
    }
    hidden[k] = h;
    ++count;
  }
  precise float covered = 0.0;
  precise float reach = lv.span.x;
  for (int k = 0; k < count; ++k) {
    precise float lo = dm_max(hidden[k].x, reach);
    if (hidden[k].y > lo) {
      covered += hidden[k].y - lo;
      reach = hidden[k].y;
    }
  }
  return dm_clamp(1.0 - covered / width, 0.0, 1.0);
}

float lightVisibility(vec2 p, int light, float dist_to_light, inout RayStats stats) {
  if (u_beams.estimator == ESTIMATOR_SEED_RAY) return seedShadow(p, light, dist_to_light, stats);
  if (u_beams.estimator == ESTIMATOR_PENUMBRA) return penumbraVisibility(p, light, stats);
  return exactVisibility(p, light, stats);
}
