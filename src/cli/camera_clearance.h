#pragma once
// Where a timeline's camera enters the scene's geometry, for `sdfreel check`'s warning: the eye of
// every selected frame against the scene's solid_distance() at that frame's time (the solids may
// move), inside (negative) or nearer than the frame plans' near plane (a mesh's surface is cut
// open there, a marched one fills the view).
#include <string>
#include <vector>

#include "scenes/scene.h"
#include "timeline/timeline.h"

namespace sdfreel {

struct CameraClearance {
  bool scene_can_tell = false;  // the scene gives solid_distance()
  std::vector<int> inside;      // frames whose eye is inside a solid
  std::vector<int> too_near;    // frames whose eye is outside but nearer than the near plane
  float near_plane = 0.0f;      // the frame plans' default (render/frame_plan.h)
};

CameraClearance camera_clearance(const Timeline& tl, const SceneInfo& info,
                                 const std::vector<int>& frames);

// "0.40-0.93 s (frames 12-28), 2.00 s (frame 60)": runs of consecutive frames, at most `most`
// runs, then "and N more".
std::string frame_runs(const std::vector<int>& frames, double fps, size_t most = 4);

}  // namespace sdfreel
