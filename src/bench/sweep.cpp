#include "bench/sweep.h"

#include <cstdio>

#include "bench/adaptive_configs.h"

namespace sdfreel::bench {

namespace {

// The sweep's values. Each is tried with the other parameters of the base preset.
const float HIT_EPS_VALUES[] = {0.05f, 0.1f, 0.25f, 0.5f, 1.0f, 2.0f, 4.0f};
const float STEP_FACTOR_VALUES[] = {1.0f, 1.2f, 1.4f, 1.6f};
const int MAX_STEPS_VALUES[] = {32, 64, 96, 128, 256};
const int SAMPLES_VALUES[] = {1, 2, 4, 8, 16};
const float NORMAL_EPS_VALUES[] = {0.25f, 0.5f, 1.0f};
const float MAX_DIST_VALUES[] = {80.0f, 120.0f, 200.0f};
// The reference preset at fewer samples: the sampling error alone.
const int REFERENCE_SAMPLES_VALUES[] = {4, 8, 16};

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

BenchConfig preset(const char* name, Quality q) {
  return BenchConfig{name, q, march_settings(q), preset_samples(q), true};
}

// One-at-a-time variations of `base`, named "<base>:<parameter>=<value>". A march value equal to
// the base's is left out; the base's own sample count stays, as "<base>:spp=N", which is the
// fixed-sampling point where the preset itself is adaptive (`final` on a small frame).
void sweep_around(BenchConfig base, std::vector<BenchConfig>& out) {
  const std::string prefix = base.name + ":";
  base.named_preset = false;
  for (float e : HIT_EPS_VALUES) {
    if (e == base.march.hit_eps) continue;
    BenchConfig c = base;
    c.march.hit_eps = e;
    c.name = prefix + fmt("eps=%g", e);
    out.push_back(c);
  }
  for (float f : STEP_FACTOR_VALUES) {
    if (f == base.march.step_factor) continue;
    BenchConfig c = base;
    c.march.step_factor = f;
    c.name = prefix + fmt("relax=%g", f);
    out.push_back(c);
  }
  for (int s : MAX_STEPS_VALUES) {
    if (s == base.march.max_steps) continue;
    BenchConfig c = base;
    // Shadow and reflection budgets keep their ratio to the primary budget.
    c.march.shadow_steps = s * base.march.shadow_steps / base.march.max_steps;
    c.march.reflect_steps = s * base.march.reflect_steps / base.march.max_steps;
    c.march.max_steps = s;
    c.name = prefix + fmt("steps=%g", s);
    out.push_back(c);
  }
  for (float e : NORMAL_EPS_VALUES) {
    if (e == base.march.normal_eps) continue;
    BenchConfig c = base;
    c.march.normal_eps = e;
    c.name = prefix + fmt("normal_eps=%g", e);
    out.push_back(c);
  }
  for (float d : MAX_DIST_VALUES) {
    if (d == base.march.max_dist) continue;
    BenchConfig c = base;
    c.march.max_dist = d;
    c.name = prefix + fmt("far=%g", d);
    out.push_back(c);
  }
  for (int n : SAMPLES_VALUES) {
    BenchConfig c = base;
    c.samples = n;
    c.name = prefix + fmt("spp=%g", n);
    out.push_back(c);
  }
}

}  // namespace

std::vector<BenchConfig> preset_configs() {
  BenchConfig naive{"naive", Quality::Final, naive_march_settings(), naive_preset_samples(), true};
  return {naive, preset("draft", Quality::Draft), preset("final", Quality::Final)};
}

std::vector<BenchConfig> preset_configs(int width, int height) {
  std::vector<BenchConfig> out = preset_configs();
  if (small_frame(width, height))
    out.back().adaptive = adaptive_preset(Quality::Final, width, height);
  return out;
}

std::vector<BenchConfig> sweep_configs() {
  std::vector<BenchConfig> out;
  for (const BenchConfig& base : preset_configs())
    if (!base.march.naive) sweep_around(base, out);
  BenchConfig ref = reference_config();
  ref.named_preset = false;
  for (int n : REFERENCE_SAMPLES_VALUES) {
    BenchConfig c = ref;
    c.samples = n;
    c.name = fmt("reference:spp=%g", n);
    out.push_back(c);
  }
  for (const BenchConfig& c : adaptive_configs()) out.push_back(c);
  return out;
}

BenchConfig reference_config() {
  return preset("reference", Quality::Reference);
}

bool same_settings(const BenchConfig& a, const BenchConfig& b) {
  return settings_text(a) == settings_text(b);
}

std::string settings_text(const BenchConfig& c) {
  const MarchSettings& m = c.march;
  char b[512];
  std::snprintf(b, sizeof b,
                "quality=%s samples=%d max_steps=%d hit_eps=%.9g step_factor=%.9g normal_eps=%.9g "
                "shadow_steps=%d reflect_steps=%d max_dist=%.9g naive=%d hit_mask=%d",
                quality_name(c.quality), c.samples, m.max_steps, double(m.hit_eps),
                double(m.step_factor), double(m.normal_eps), m.shadow_steps, m.reflect_steps,
                double(m.max_dist), int(m.naive), int(m.hit_mask));
  // Only adaptive points add text, so fixed points (and the reference cache) keep their keys.
  return c.adaptive.enabled ? std::string(b) + " adaptive: " + adaptive_text(c.adaptive) : b;
}

}  // namespace sdfreel::bench
