// A frame's context takes the adaptive sampling of the size the command settled on
// (Timeline::adaptive_at_size): `final`'s small-frame preset after a --resolution override.
#include <gtest/gtest.h>

#include "pipeline/frame_pipeline.h"
#include "scenes/registry.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

TEST(FrameContextAdaptive, FollowsTheSettledSize) {
  Timeline tl = parse_timeline(all_scenes(), "t.toml",
                               "[video]\nscene = \"sdf_morph\"\nresolution = [1280, 720]\n"
                               "adaptive = true\n",
                               nullptr);
  const SceneInfo* scene = find_scene(tl.scene);
  ASSERT_NE(scene, nullptr);
  EXPECT_EQ(frame_context_at(tl, *scene, 0, 0.0).adaptive.maximum, 16);
  tl.width = 160, tl.height = 90;  // as --resolution 160x90 sets it
  const FrameContext ctx = frame_context_at(tl, *scene, 0, 0.0);
  EXPECT_TRUE(ctx.adaptive.enabled);
  EXPECT_EQ(ctx.adaptive.minimum, 4);
  EXPECT_EQ(ctx.adaptive.maximum, 28);
  EXPECT_EQ(ctx.adaptive.threshold, 0.008f);
}

}  // namespace
}  // namespace sdfreel
