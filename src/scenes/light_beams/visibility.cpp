#include "scenes/light_beams/visibility.h"

#include "scenes/light_beams/crossings.h"

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

// Inserts h into hidden[0..count), kept sorted by start; after equal starts (a stable order).
void insertSorted(vec2* hidden, int& count, vec2 h) {
  int k = count++;
  for (; k > 0 && hidden[k - 1].x > h.x; --k) hidden[k] = hidden[k - 1];
  hidden[k] = h;
}

// Whether `other` comes before the light along the ray from p at angle a from n.
bool inFront(vec2 p, vec2 n, float a, const Shape& light, const Shape& other) {
  const vec2 dir = turn(n, a);
  const float t_other = hitShape(p, dir, other);
  const float t_light = hitShape(p, dir, light);
  return !(t_other == NO_HIT || (t_light != NO_HIT && t_light < t_other));
}

// Whether j can come before the light from p, as far as the pair's mode says (crossings.h): j on
// p's side of their separating line, or the light inside j; or the outlines cross.
bool mayBeInFront(vec2 p, int light, int j, const BeamsUniforms& u) {
  const int pair = pairIndex(light, j);
  const int mode = u.pair_mode[pair];
  if (mode == PAIR_APART) {
    const glm::vec4 line = u.pair_line[pair];
    const float side = (p.x - line.x) * line.z + (p.y - line.y) * line.w;
    return j > light ? side > 0.0f : side < 0.0f;
  }
  if (mode == PAIR_CROSSING) return true;
  return mode == (light < j ? PAIR_FIRST_INSIDE : PAIR_SECOND_INSIDE);
}

// The parts of the light's span that shape j hides from p, appended to hidden[count...] (when
// hidden is not null); returns their total width. Where j and the light do not cross, j is in
// front along all the angles they share or along none (mayBeInFront). Where they cross, the
// shared angles are cut at the directions of the crossings (crossings.h), clamped to those
// angles and sorted; in each part one shape is in front all along, and one ray through its
// middle says which.
float hiddenParts(vec2 p, const LightView& lv, int light, int j, const BeamsUniforms& u,
                  vec2* hidden, int& count) {
  if (!mayBeInFront(p, light, j, u)) return 0.0f;
  const Shape &l = u.shapes[light], &other = u.shapes[j];
  const vec2 o = angularSpan(p, lv.n, other);
  const float lo = dm::max(lv.span.x, o.x), hi = dm::min(lv.span.y, o.y);
  if (!(lo < hi)) return 0.0f;
  const int pair = pairIndex(light, j);
  if (u.pair_mode[pair] != PAIR_CROSSING) {
    if (hidden) insertSorted(hidden, count, vec2(lo, hi));
    return hi - lo;
  }
  float cuts[MAX_PAIR_CROSSINGS];
  int n = 0;
  for (int k = u.crossing_first[pair]; k < u.crossing_first[pair + 1]; ++k) {
    const float a = dm::clamp(angleFrom(lv.n, u.crossings[k] - p), lo, hi);
    int m = n++;
    for (; m > 0 && cuts[m - 1] > a; --m) cuts[m] = cuts[m - 1];
    cuts[m] = a;
  }
  float hidden_width = 0.0f;
  float start = lo;
  for (int k = 0; k <= n; ++k) {
    const float end = k < n ? cuts[k] : hi;
    if (start < end && inFront(p, lv.n, 0.5f * (start + end), l, other)) {
      hidden_width += end - start;
      if (hidden) insertSorted(hidden, count, vec2(start, end));
    }
    start = end;
  }
  return hidden_width;
}

}  // namespace

float nearestDist(vec2 p, int skip, const BeamsUniforms& u, RayStats& stats) {
  float d = FAR_AWAY;
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == skip || !castsShadow(j, u)) continue;
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
    if (j == light || !castsShadow(j, u)) continue;
    stats.sdf_evals += 1;
    // Inside another shape the seed's march stops at once: nothing of the light is seen.
    if (shapeSDF(p, u.shapes[j]) <= 0.0f) return 0.0f;
    int none = 0;
    vis *= 1.0f - hiddenParts(p, lv, light, j, u, nullptr, none) / width;
  }
  return dm::max(vis, 0.0f);
}

float exactVisibility(vec2 p, int light, const BeamsUniforms& u, RayStats& stats) {
  const Shape& l = u.shapes[light];
  const LightView lv = viewOf(p, l);
  const float width = lv.span.y - lv.span.x;
  if (!(width > 0.0f)) return 1.0f;
  // The hidden parts, kept sorted by their start: one per other shape, and one more per cut.
  vec2 hidden[SHAPE_COUNT - 1 + MAX_CROSSINGS];
  int count = 0;
  for (int j = 0; j < SHAPE_COUNT; ++j) {
    if (j == light || !castsShadow(j, u)) continue;
    stats.sdf_evals += 1;
    if (shapeSDF(p, u.shapes[j]) <= 0.0f) return 0.0f;
    hiddenParts(p, lv, light, j, u, hidden, count);
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
    if (j != light && castsShadow(j, u) && shapeSDF(p, u.shapes[j]) <= 0.0f) return 0.0f;
  const LightView lv = viewOf(p, l);
  int seen = 0;
  for (int k = 0; k < rays; ++k) {
    const float a = lv.span.x + (lv.span.y - lv.span.x) * ((float(k) + 0.5f) / float(rays));
    const vec2 dir = turn(lv.n, a);
    const float t_light = hitShape(p, dir, l);
    if (t_light == NO_HIT) continue;  // grazing the light's outline: counts as unseen
    bool blocked = false;
    for (int j = 0; j < SHAPE_COUNT && !blocked; ++j) {
      if (j == light || !castsShadow(j, u)) continue;
      const float t = hitShape(p, dir, u.shapes[j]);
      blocked = t != NO_HIT && t < t_light;
    }
    if (!blocked) ++seen;
  }
  return float(seen) / float(rays);
}

}  // namespace sdfreel::light_beams
