#pragma once
// The named targets of a frame plan on the CPU: one RGBA float image each (depth in channel 0),
// frame-sized unless the spec gives a size, reused from sample to sample and cleared before each
// (per-frame targets once a frame).
#include <map>
#include <set>
#include <string>
#include <vector>

#include "render/frame_plan.h"
#include "render/image.h"

namespace sdfreel {

class CpuTargets {
 public:
  // threads: how many clear the images (0 = all cores), as the passes run.
  CpuTargets(const std::vector<TargetSpec>& specs, int width, int height, int threads = 1);
  void clear();             // every target
  void clear_per_sample();  // all but the per-frame targets and those skipped below
  // Leaves `name` out of clear_per_sample: for a target whose values nothing reads.
  void skip_per_sample_clear(const std::string& name) { skipped_.insert(name); }
  // Throws std::runtime_error naming the pass when the plan names a target it does not declare.
  ImageRGBA& get(const std::string& name, const std::string& pass);

 private:
  void clear_where(bool per_sample_only);
  std::vector<TargetSpec> specs_;
  int threads_;
  std::map<std::string, ImageRGBA> images_;
  std::set<std::string> skipped_;
};

}  // namespace sdfreel
