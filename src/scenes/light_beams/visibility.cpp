#include "scenes/light_beams/visibility.h"

namespace sdfreel::light_beams {
namespace {

constexpr float FAR_AWAY = 1e30f;  // nearestDist with no other shape

// Unit direction from p toward the light's core, and the light's span around it.
struct LightView {
  vec2 n;
  vec2 span;
};

LightView viewOf(vec2 p, const Shape& light) {
  const vec2 v = corePoint(p, light) - p;
  const float len = lengthv(v);
  LightView lv;
  lv.n = len > 0.0f ? v / len : vec2(1.0f, 0.0f);
  lv.span = angularSpan(p, lv.n, light);
  return lv;
}

// n turned by angle a (counter-clockwise).
vec2 turn(vec2 n, float a) {
  const float c = dm::cos(a), s = dm::sin(a);
  return vec2(n.x * c - n.y * s, n.x * s + n.y * c);
}

// The part of the light's span that shape j hides from p, as (lo, hi); lo >= hi: nothing. Two
// shapes that do not overlap keep one order along every ray that meets both, so the first hits
// along the middle of the common span say which is in front for all of it.
vec2 hiddenSpan(vec2 p, const LightView& lv, const Shape& light, const Shape& other) {
  const vec2 o = angularSpan(p, lv.n, other);
  const float lo = dm::max(lv.span.x, o.x), hi = dm::min(lv.span.y, o.y);
  if (!(lo < hi)) return vec2(0.0f, 0.0f);
  const vec2 dir = turn(lv.n, 0.5f * (lo + hi));
  const float t_other = hitShape(p, dir, other);
  const float t_light = hitShape(p, dir, light);
  if (t_other == NO_HIT || (t_light != NO_HIT && t_light < t_other)) return vec2(0.0f, 0.0f);
  return vec2(lo, hi);
}

}  // namespace

float nearestDist(vec2 p, int skip, const BeamsUniforms& u, RayStats& stats) {
  float d = FAR_AWAY;
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == skip) continue;
    stats.sdf_evals += 1;
    d = dm::min(d, shapeSDF(p, u.shapes[j]));
  }
  return d;
}

float seedShadow(vec2 p, int light, float dist_to_light, const BeamsUniforms& u, RayStats& stats) {
  const vec2 v = closestPoint(p, u.shapes[light]) - p;
  const float len = lengthv(v);
  const vec2 dir = len > 0.0f ? v / len : vec2(1.0f, 0.0f);
  float t = 0.0f;
  for (int i = 0; i < u.shadow_steps; ++i) {
    stats.steps += 1;
    const float h = nearestDist(p + dir * t, light, u, stats);
    if (h <= u.min_hit_dist) return 0.0f;
    t += dm::clamp(h, u.min_hit_dist, u.max_trace_dist);
    if (t > dist_to_light || t > u.max_trace_dist) break;
  }
  return 1.0f;
}

float penumbraVisibility(vec2 p, int light, const BeamsUniforms& u, RayStats& stats) {
  const Shape& l = u.shapes[light];
  const LightView lv = viewOf(p, l);
  const float width = lv.span.y - lv.span.x;
  if (!(width > 0.0f)) return 1.0f;
  float vis = 1.0f;
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == light) continue;
    stats.sdf_evals += 1;
    // Inside another shape the seed's march stops at once: nothing of the light is seen.
    if (shapeSDF(p, u.shapes[j]) <= 0.0f) return 0.0f;
    const vec2 h = hiddenSpan(p, lv, l, u.shapes[j]);
    if (h.x < h.y) vis *= 1.0f - (h.y - h.x) / width;
  }
  return dm::max(vis, 0.0f);
}

float exactVisibility(vec2 p, int light, const BeamsUniforms& u, RayStats& stats) {
  const Shape& l = u.shapes[light];
  const LightView lv = viewOf(p, l);
  const float width = lv.span.y - lv.span.x;
  if (!(width > 0.0f)) return 1.0f;
  // The hidden intervals, kept sorted by their start (insertion sort: at most SHAPE_COUNT - 1).
  vec2 hidden[SHAPE_COUNT];
  int count = 0;
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == light) continue;
    stats.sdf_evals += 1;
    if (shapeSDF(p, u.shapes[j]) <= 0.0f) return 0.0f;
    const vec2 h = hiddenSpan(p, lv, l, u.shapes[j]);
    if (!(h.x < h.y)) continue;
    int k = count;
    while (k > 0 && hidden[k - 1].x > h.x) {
      hidden[k] = hidden[k - 1];
      --k;
    }
    hidden[k] = h;
    ++count;
  }
  // Length of their union.
  float covered = 0.0f;
  float reach = lv.span.x;  // end of the union so far
  for (int k = 0; k < count; ++k) {
    const float lo = dm::max(hidden[k].x, reach);
    if (hidden[k].y > lo) {
      covered += hidden[k].y - lo;
      reach = hidden[k].y;
    }
  }
  return dm::clamp(1.0f - covered / width, 0.0f, 1.0f);
}

float lightVisibility(vec2 p, int light, float dist_to_light, const BeamsUniforms& u,
                      RayStats& stats) {
  if (u.estimator == ESTIMATOR_SEED_RAY) return seedShadow(p, light, dist_to_light, u, stats);
  if (u.estimator == ESTIMATOR_PENUMBRA) return penumbraVisibility(p, light, u, stats);
  return exactVisibility(p, light, u, stats);
}

float monteCarloVisibility(vec2 p, int light, const BeamsUniforms& u, int rays) {
  const Shape& l = u.shapes[light];
  for (int j = 0; j < SHAPE_COUNT; ++j)
    if (j != light && shapeSDF(p, u.shapes[j]) <= 0.0f) return 0.0f;
  const LightView lv = viewOf(p, l);
  int seen = 0;
  for (int k = 0; k < rays; ++k) {
    const float a = lv.span.x + (lv.span.y - lv.span.x) * ((float(k) + 0.5f) / float(rays));
    const vec2 dir = turn(lv.n, a);
    const float t_light = hitShape(p, dir, l);
    if (t_light == NO_HIT) continue;  // grazing the light's outline: counts as unseen
    bool blocked = false;
    for (int j = 0; j < SHAPE_COUNT && !blocked; ++j) {
      if (j == light) continue;
      const float t = hitShape(p, dir, u.shapes[j]);
      blocked = t != NO_HIT && t < t_light;
    }
    if (!blocked) ++seen;
  }
  return float(seen) / float(rays);
}

}  // namespace sdfreel::light_beams
