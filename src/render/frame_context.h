#pragma once
// Everything one frame depends on. A frame is a pure function of this struct (and the build).
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "render/adaptive_sampling.h"
#include "render/camera.h"
#include "render/params.h"
#include "render/quality.h"

namespace sdfreel {

struct FrameContext {
  int frame_index = 0;
  double video_time = 0.0;  // t_i = i / fps, seconds
  double fps = 30.0;        // the timeline's frame rate (a user's shader reads it: iFrameRate)
  double scene_time = 0.0;  // TIME, from the [time] curve; double so that 1e6 s keeps precision
  int width = 64, height = 36;
  int samples = 1;            // fixed sampling: every pixel takes this many
  AdaptiveSampling adaptive;  // when enabled: per pixel, in rounds, up to adaptive.maximum
  uint64_t seed = 1;
  Quality quality = Quality::Final;
  MarchSettings march{};
  CameraPose pose;
  CameraBasis camera{};
  ParamValues params;
  // Sub-pixel sample offsets in [0,1)^2, `samples` of them (adaptive.maximum when adaptive),
  // identical for every pixel: both backends read this list, so they sample the same positions.
  std::vector<glm::vec2> sample_offsets;
};

// Fills march, camera and sample_offsets from quality, pose and samples (or adaptive).
void finish_frame_context(FrameContext& ctx);
// How the frame samples: fixed `samples` is adaptive sampling with minimum = maximum = samples.
AdaptiveSampling sampling_of(const FrameContext& ctx);

}  // namespace sdfreel
