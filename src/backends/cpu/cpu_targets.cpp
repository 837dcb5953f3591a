#include "backends/cpu/cpu_targets.h"

#include <algorithm>
#include <stdexcept>

#include "render/tiling.h"

namespace sdfreel {

namespace {
constexpr size_t kPixelsPerTask = 1 << 14;  // pixels a clearing task fills
}  // namespace

CpuTargets::CpuTargets(const std::vector<TargetSpec>& specs, int width, int height, int threads)
    : specs_(specs), threads_(threads) {
  for (const TargetSpec& s : specs_)
    if (!images_
             .emplace(s.name,
                      s.size.x > 0 ? ImageRGBA(s.size.x, s.size.y) : ImageRGBA(width, height))
             .second)
      throw std::runtime_error("frame plan: target '" + s.name + "' declared twice");
}

void CpuTargets::clear() {
  clear_where(false);
}
void CpuTargets::clear_per_sample() {
  clear_where(true);
}

void CpuTargets::clear_where(bool per_sample_only) {
  for (const TargetSpec& s : specs_) {
    if (per_sample_only && (s.per_frame || skipped_.count(s.name))) continue;
    const glm::vec4 c = s.kind == TargetKind::Depth ? glm::vec4(1.0f) : s.clear;
    std::vector<float>& px = images_.at(s.name).pixels;
    // A frame's targets are tens of megabytes, cleared before every sample: in parallel ranges.
    for_each_range(px.size() / 4, kPixelsPerTask, threads_, [&](size_t begin, size_t end) {
      for (size_t i = begin * 4; i < end * 4; i += 4) {
        px[i] = c.x;
        px[i + 1] = c.y;
        px[i + 2] = c.z;
        px[i + 3] = c.w;
      }
    });
  }
}

ImageRGBA& CpuTargets::get(const std::string& name, const std::string& pass) {
  const auto it = images_.find(name);
  if (it == images_.end())
    throw std::runtime_error("frame plan: pass '" + pass + "' names target '" + name +
                             "', which the plan does not declare");
  return it->second;
}

}  // namespace sdfreel
