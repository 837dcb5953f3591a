// The relaxed sphere tracing of a scene's distance (GLSL twin of scenes/common/relaxed_march.h,
// the same operations in the same order): over-relaxation by omega with its fall-back to a plain
// step when the spheres stop overlapping, a hit epsilon that grows with the pixel footprint, and
// only a plain step may leave at tmax. GLSL has no templates, so the including shader defines
// first:
//   RELAXED_MARCH_PARAMS  its extra parameters, among them its uniforms named `u` (with naive,
//                         step_factor, hit_eps), e.g. `bool leaves, LilyUniforms u`
//   RELAXED_MARCH_MAP(p)  its distance at p, counting evaluations in `stats`
// and gets march(ro, rd, tmin, tmax, max_steps, eps_per_t, t_before, <its parameters>, stats).
float march(vec3 ro, vec3 rd, float tmin, float tmax, int max_steps, float eps_per_t,
            precise float t_before, RELAXED_MARCH_PARAMS, inout RayStats stats) {
  precise float t = tmin;
  precise float omega = u.naive != 0 ? 1.0 : u.step_factor;
  precise float prev_d = 0.0;
  precise float step = 0.0;
  for (int i = 0; i < max_steps; ++i) {
    stats.steps += 1u;
    precise float d = RELAXED_MARCH_MAP(ro + rd * t);
    if (omega > 1.0 && abs(d) + prev_d < step) {
      t += prev_d - step;  // back to the previous point plus a plain step
      step = prev_d;
      omega = 1.0;
      continue;
    }
    precise float eps = u.naive != 0 ? u.hit_eps : dm_max(MIN_HIT_EPS, eps_per_t * (t_before + t));
    if (d < eps) return t;
    step = d * omega;
    prev_d = d;
    t += step;
    if (t > tmax) {
      if (omega <= 1.0 || t - step + d > tmax) return NO_HIT;
      t += d - step;  // a relaxed step may have jumped a surface: step back to a plain one
      step = d;
      omega = 1.0;
    }
  }
  stats.capped += 1u;
  return t;
}
