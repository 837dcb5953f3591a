#pragma once
// One packet of a ray pass on the CPU: the primary rays through eight image positions, traced
// together. Both runners (cpu_ray_pass.cpp: a tile's pixels at one sample offset;
// cpu_ray_pass_resolved.cpp: live (pixel, sample) pairs) fill their packets through it.
#include "backends/cpu/cpu_pass_context.h"
#include "render/camera_lanes.h"
#include "render/frame_plan.h"

namespace sdfreel {

// Traces the rays through image positions (x[i], y[i]) of lanes 0..count-1 (count <= LANES; the
// caller repeats its last position in the lanes beyond) into result, whose keep and depth start at
// false and 1 as GL's fragment stage would have them; evals[i] is what lane i counted.
inline void trace_packet(const RayPass& pass, const CpuPassContext& pc, const F8& x, const F8& y,
                         int count, RayPassOutput& result, RayStats& stats) {
  const FrameContext& f = pc.frame;
  const RayPacket packet = primary_packet(f.camera, pc.pixel_angle, x, y, count, f.width, f.height);
  result.start();
  stats.lane_evals = splat_mask(false);
  pass.packet(packet, result, stats);
  for (int i = 0; i < LANES; ++i) result.evals[i] = stats.lane_evals[i];
}

}  // namespace sdfreel
