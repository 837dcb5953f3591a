// [video] adaptive: per-pixel adaptive sampling (render/adaptive_sampling.h). `adaptive = true`
// takes the quality preset's numbers (for the frame's size: Timeline::adaptive_at_size); a table
// sets any of them. `samples` keeps meaning fixed
// sampling, so a timeline gives one or the other.

#include "render/adaptive_sampling.h"
#include "render/adaptive_target.h"
#include "timeline/rules.h"
#include "timeline/sections.h"

namespace sdfreel {

namespace {

void parse_table(const TomlReader& r, const toml::table& t, AdaptiveSampling& a,
                 Timeline::AdaptiveGiven& given) {
  r.check_keys(t, "video.adaptive", {"minimum", "maximum", "threshold", "target_db"});
  const toml::node* min_node = t.get("minimum");
  const toml::node* max_node = t.get("maximum");
  if (min_node) a.minimum = int(r.integer_in(*min_node, "video.adaptive.minimum", 1, kMaxSamples));
  if (max_node) a.maximum = int(r.integer_in(*max_node, "video.adaptive.maximum", 1, kMaxSamples));
  if (a.maximum < a.minimum)
    r.fail(max_node ? *max_node : *min_node,
           "video.adaptive.maximum (" + std::to_string(a.maximum) +
               ") must be at least video.adaptive.minimum (" + std::to_string(a.minimum) + ")");
  const toml::node* threshold = t.get("threshold");
  const toml::node* target = t.get("target_db");
  given = {min_node != nullptr, max_node != nullptr, threshold || target};
  if (threshold && target) r.fail(*target, "video.adaptive takes threshold or target_db, not both");
  if (threshold) {
    const double v = r.number(*threshold, "video.adaptive.threshold");
    if (!(v >= 0.0 && v <= 1.0))
      r.fail(*threshold, "video.adaptive.threshold must be in 0..1, got " + format_number(v));
    a.threshold = float(v);
  }
  if (target) {
    const double v = r.number(*target, "video.adaptive.target_db");
    if (!(v >= 1.0 && v <= 120.0))
      r.fail(*target, "video.adaptive.target_db must be in 1..120, got " + format_number(v));
    a.threshold = threshold_for_target_db(v);
  }
}

}  // namespace

void parse_adaptive(const TomlReader& r, const toml::table& video, Timeline& tl) {
  const toml::node* n = video.get("adaptive");
  if (!n) return;
  if (const toml::node* s = video.get("samples"))
    r.fail(*s,
           "video.samples (fixed sampling) and video.adaptive exclude each other: adaptive "
           "sampling takes video.adaptive.minimum..maximum samples a pixel");
  AdaptiveSampling a = adaptive_preset(tl.quality);
  if (const auto* b = n->as_boolean()) {
    a.enabled = b->get();
  } else if (n->is_table()) {
    a.enabled = true;
    parse_table(r, *n->as_table(), a, tl.adaptive_given);
  } else {
    r.fail(*n,
           "video.adaptive must be true, false or a table {minimum, maximum, threshold or "
           "target_db}, not " +
               type_name(*n));
  }
  tl.adaptive = a;
}

}  // namespace sdfreel
