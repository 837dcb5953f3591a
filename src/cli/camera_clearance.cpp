#include "cli/camera_clearance.h"

#include <cstdio>

#include "pipeline/frame_pipeline.h"

namespace sdfreel {

CameraClearance camera_clearance(const Timeline& tl, const SceneInfo& info,
                                 const std::vector<int>& frames) {
  CameraClearance c;
  c.near_plane = FramePlan().near_plane;  // the scenes' mesh passes use it (fur, museum)
  if (!info.make || frames.empty()) return c;
  const std::unique_ptr<Scene> scene = info.make();
  for (int frame : frames) {
    const FrameContext ctx = frame_context(tl, info, frame);
    scene->prepare_solids(ctx);
    const std::optional<float> d = scene->solid_distance(glm::vec3(ctx.pose.position));
    if (!d) return CameraClearance{};
    c.scene_can_tell = true;
    if (*d < 0.0f)
      c.inside.push_back(frame);
    else if (*d < c.near_plane)
      c.too_near.push_back(frame);
  }
  return c;
}

std::string frame_runs(const std::vector<int>& frames, double fps, size_t most) {
  std::string out;
  size_t runs = 0;
  for (size_t i = 0; i < frames.size();) {
    size_t j = i;
    while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
    if (runs++ < most) {
      char s[96];
      if (i == j)
        std::snprintf(s, sizeof s, "%.2f s (frame %d)", frames[i] / fps, frames[i]);
      else
        std::snprintf(s, sizeof s, "%.2f-%.2f s (frames %d-%d)", frames[i] / fps, frames[j] / fps,
                      frames[i], frames[j]);
      out += (out.empty() ? "" : ", ") + std::string(s);
    }
    i = j + 1;
  }
  if (runs > most) out += " and " + std::to_string(runs - most) + " more";
  return out;
}

}  // namespace sdfreel
