// The eye between the sphere's skin and its outermost shell (the hard case inside_outer_shell):
// the skin, 4 cm ahead, is drawn, not cut away by the near plane to show the case through it.
#include <gtest/gtest.h>

#include "scenes/plan_passes.h"
#include "scenes/registry.h"
#include "scenes/scene_pixels.h"

namespace sdfreel {
namespace {

constexpr int W = 32, H = 18;

TEST(FurInside, TheSkinAheadOfAnEyeInTheFurIsDrawn) {
  const SceneInfo& info = *find_scene("fur");
  FrameContext ctx = test::scene_context(info, W, H, 0.5, Quality::Final);
  ctx.pose = CameraPose{{-0.45, 1.13, -0.19}, {-0.45, 1.09, 0.0}, 60.0, 0.0};
  ctx.params.set("grow_amount", {0.0});
  finish_frame_context(ctx);
  ctx.march.hit_mask = true;  // colour = hit id: 1 + shape index, the sphere is shape 0
  CpuTargets targets = test::run_plan_passes("fur", ctx);
  EXPECT_EQ(targets.get(COLOUR_TARGET, "test").at(W / 2, H / 2)[0], 1.0f);
}

}  // namespace
}  // namespace sdfreel
