#pragma once
// The named targets of a frame plan on the CPU: one frame-sized RGBA float image each (depth in
// channel 0), reused from sample to sample and cleared before each.
#include <map>
#include <string>
#include <vector>

#include "render/frame_plan.h"
#include "render/image.h"

namespace sdfreel {

class CpuTargets {
 public:
  CpuTargets(const std::vector<TargetSpec>& specs, int width, int height);
  void clear();
  // Throws std::runtime_error naming the pass when the plan names a target it does not declare.
  ImageRGBA& get(const std::string& name, const std::string& pass);

 private:
  std::vector<TargetSpec> specs_;
  std::map<std::string, ImageRGBA> images_;
};

}  // namespace sdfreel
