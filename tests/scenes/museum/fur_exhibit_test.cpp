// Exhibit 3 in the hall (issue 13): the museum schedules the fur's pushes with its own
// parameters (fur_push_times), and the case's frames stay pure functions of TIME.
#include "scenes/museum/fur_exhibit.h"

#include <gtest/gtest.h>

#include <cstring>
#include <set>

#include "scenes/plan_passes.h"
#include "scenes/registry.h"
#include "scenes/scene_pixels.h"

namespace sdfreel {
namespace {

constexpr int W = 96, H = 54;
// Beside plinth 3, looking down into the fur case.
const CameraPose AT_THE_CASE{{3.0, 1.5, -0.6}, {1.8, 1.1, -1.7}, 40.0, 0.0};

ImageRGBA hall_at(double time, double push_time, bool ids = false) {
  FrameContext ctx = test::scene_context(*find_scene("museum"), W, H, time, Quality::Final);
  ctx.pose = AT_THE_CASE;
  ctx.params.set("fur_push_times", {push_time, -1.0, -1.0});
  finish_frame_context(ctx);
  ctx.march.hit_mask = ids;
  return test::run_plan_passes("museum", ctx).get("hall", "test");
}

bool same(const ImageRGBA& a, const ImageRGBA& b) {
  return std::memcmp(a.at(0, 0), b.at(0, 0), sizeof(float) * 4 * W * H) == 0;
}

TEST(MuseumFur, PushTimesComeFromTheMuseumsOwnParameters) {
  const double push = 2.0;
  // Before the push the case is as if never pushed; after it the shapes are in the air.
  EXPECT_TRUE(same(hall_at(1.9, push), hall_at(1.9, -1.0)));
  EXPECT_FALSE(same(hall_at(2.3, push), hall_at(2.3, -1.0)));
}

// The bench's per-surface errors need one id per surface: the shapes' ids (5, 6, 7) are none of
// the hall's (2), exhibit 1's (1) or the card's (3, 4).
TEST(MuseumFur, ShapesHaveHitIdsOfTheirOwn) {
  const ImageRGBA ids = hall_at(1.0, -1.0, true);
  std::set<float> seen;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) seen.insert(ids.at(x, y)[0]);
  for (float id : {5.0f, 6.0f, 7.0f}) EXPECT_EQ(seen.count(id), 1u) << id;
}

}  // namespace
}  // namespace sdfreel
