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

int pairIndex(int i, int j) { return i < j ? i * SHAPE_COUNT + j : j * SHAPE_COUNT + i; }

bool inFront(vec2 p, vec2 n, float a, Shape light, Shape other) {
  precise vec2 dir = turn(n, a);
  precise float t_other = hitShape(p, dir, other);
  precise float t_light = hitShape(p, dir, light);
  return !(t_other == NO_HIT || (t_light != NO_HIT && t_light < t_other));
}

bool mayBeInFront(vec2 p, int light, int j) {
  int pair = pairIndex(light, j);
  int mode = u_beams.pair_mode[pair];
  if (mode == PAIR_APART) {
    precise vec4 line = u_beams.pair_line[pair];
    precise float side = (p.x - line.x) * line.z + (p.y - line.y) * line.w;
    return j > light ? side > 0.0 : side < 0.0;
  }
  if (mode == PAIR_CROSSING) return true;
  return mode == (light < j ? PAIR_FIRST_INSIDE : PAIR_SECOND_INSIDE);
}

// The pair's cut angles (crossings.h) clamped to [lo, hi], sorted into cuts; returns how many.
int pairCuts(vec2 p, LightView lv, int pair, float lo, float hi,
             inout float cuts[MAX_PAIR_CROSSINGS]) {
  int n = 0;
  for (int k = u_beams.crossing_first[pair]; k < u_beams.crossing_first[pair + 1]; ++k) {
    precise float a = dm_clamp(angleFrom(lv.n, u_beams.crossings[k] - p), lo, hi);
    int m = n++;
    for (; m > 0 && cuts[m - 1] > a; --m) cuts[m] = cuts[m - 1];
    cuts[m] = a;
  }
  return n;
}

// hiddenParts without keeping the parts (the penumbra product needs only their width).
float hiddenWidth(vec2 p, LightView lv, int light, int j) {
  if (!mayBeInFront(p, light, j)) return 0.0;
  Shape l = u_beams.shapes[light];
  Shape other = u_beams.shapes[j];
  precise vec2 o = angularSpan(p, lv.n, other);
  precise float lo = dm_max(lv.span.x, o.x);
  precise float hi = dm_min(lv.span.y, o.y);
  if (!(lo < hi)) return 0.0;
  int pair = pairIndex(light, j);
  if (u_beams.pair_mode[pair] != PAIR_CROSSING) return hi - lo;
  float cuts[MAX_PAIR_CROSSINGS];
  int n = pairCuts(p, lv, pair, lo, hi, cuts);
  precise float hidden_width = 0.0;
  precise float start = lo;
  for (int k = 0; k <= n; ++k) {
    precise float end = k < n ? cuts[k] : hi;
    if (start < end && inFront(p, lv.n, 0.5 * (start + end), l, other)) hidden_width += end - start;
    start = end;
  }
  return hidden_width;
}

float nearestDist(vec2 p, int skip, inout RayStats stats) {
  precise float d = FAR_AWAY;
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == skip || !castsShadow(j)) continue;
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
    if (j == light || !castsShadow(j)) continue;
    stats.sdf_evals += 1u;
    if (shapeSDF(p, u_beams.shapes[j]) <= 0.0) return 0.0;
    vis *= 1.0 - hiddenWidth(p, lv, light, j) / width;
  }
  return dm_max(vis, 0.0);
}

float exactVisibility(vec2 p, int light, inout RayStats stats) {
  Shape l = u_beams.shapes[light];
  LightView lv = viewOf(p, l);
  precise float width = lv.span.y - lv.span.x;
  if (!(width > 0.0)) return 1.0;
  // hiddenParts of visibility.cpp, written out here: the parts go straight into the sorted list.
  vec2 hidden[SHAPE_COUNT - 1 + MAX_CROSSINGS];
  int count = 0;
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == light || !castsShadow(j)) continue;
    stats.sdf_evals += 1u;
    if (shapeSDF(p, u_beams.shapes[j]) <= 0.0) return 0.0;
    if (!mayBeInFront(p, light, j)) continue;
    Shape other = u_beams.shapes[j];
    precise vec2 o = angularSpan(p, lv.n, other);
    precise float lo = dm_max(lv.span.x, o.x);
    precise float hi = dm_min(lv.span.y, o.y);
    if (!(lo < hi)) continue;
    int pair = pairIndex(light, j);
    float cuts[MAX_PAIR_CROSSINGS];
    int n = u_beams.pair_mode[pair] != PAIR_CROSSING ? 0 : pairCuts(p, lv, pair, lo, hi, cuts);
    precise float start = lo;
    for (int k = 0; k <= n; ++k) {
      precise float end = k < n ? cuts[k] : hi;
      if (start < end &&
          (u_beams.pair_mode[pair] != PAIR_CROSSING || inFront(p, lv.n, 0.5 * (start + end), l, other))) {
        int m = count++;
        for (; m > 0 && hidden[m - 1].x > start; --m) hidden[m] = hidden[m - 1];
        hidden[m] = vec2(start, end);
      }
      start = end;
    }
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
