#pragma once
// A test-only frame plan with every pass kind's compositing: a few cubes on a plane (one cube
// mesh, instanced and scaled), then a ray-marched sphere depth-tested against them.
#include "render/frame_context.h"
#include "render/frame_plan.h"

namespace sdfreel::test {

FramePlan mixed_plan(const FrameContext& ctx);
// Its camera: looking at the sphere past the cubes.
FrameContext mixed_context(int width, int height, int samples);

}  // namespace sdfreel::test
