#pragma once
// How far and how fast a timeline's camera moves, for `sdfreel check`: measured by sampling the
// path the frames will see, four times a frame between the first and the last key.
#include "timeline/timeline.h"

namespace sdfreel {

struct CameraPathStats {
  double length = 0.0;        // world units travelled by the camera's position
  double top_speed = 0.0;     // world units per second of video, the fastest stretch
  double top_speed_at = 0.0;  // video time (s) where it is reached
};

CameraPathStats camera_path_stats(const Timeline& tl, const CameraPose& fallback);

}  // namespace sdfreel
