#pragma once
// March precision presets. Every number that a preset sets lives in quality.cpp, nowhere else.
#include <optional>
#include <string>

namespace sdfreel {

enum class Quality { Draft, Final, Reference };

struct MarchSettings {
  int max_steps;      // primary-ray step cap
  float hit_eps;      // hit threshold at unit distance; scaled by t * pixel footprint
  float step_factor;  // over-relaxation factor (1 = plain sphere tracing)
  float normal_eps;   // finite-difference step for normals, at unit distance
  int shadow_steps;   // soft-shadow step cap
  int reflect_steps;  // secondary (reflection) ray step cap
  float max_dist;     // far limit of primary rays
};

MarchSettings march_settings(Quality q);
std::optional<Quality> parse_quality(const std::string& name);
const char* quality_name(Quality q);

}  // namespace sdfreel
