// Exhibit 2 in the hall (issue 13): the lenticular card's pass draws into the hall's targets,
// composited with the hall by depth both ways, and the GL side gets its textures beside the
// probe under a key that changes when either does.
#include "scenes/museum/card_exhibit.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "scenes/museum/museum_passes.h"
#include "scenes/registry.h"
#include "scenes/scene_pixels.h"

namespace sdfreel {
namespace {

constexpr int W = 96, H = 54;
const char* HALL = "hall";
const char* CARD = "lenticular card";

FrameContext museum_context(const CameraPose& pose, double lift = 0.0) {
  FrameContext ctx = test::scene_context(*find_scene("museum"), W, H, 2.0, Quality::Final);
  ctx.pose = pose;
  ctx.params.set("exhibit_lift", {lift});
  finish_frame_context(ctx);
  return ctx;
}

// Low in front of plinth 2, looking up at the card over the plinth's front edge: the plinth
// hides the stand's base.
const CameraPose BELOW_CARD{{-1.6, 0.62, -0.25}, {-3.0, 1.25, 1.7}, 22.0, 0.0};

TEST(MuseumCard, DrawnIntoTheHallTargetsWithDepthTestAndWrite) {
  const FrameContext ctx = museum_context(BELOW_CARD);
  std::unique_ptr<Scene> scene = find_scene("museum")->make();
  scene->prepare(ctx);
  const FramePlan plan = scene->frame_plan(ctx);
  int cards = 0;
  for (const Pass& pass : plan.passes) {
    if (pass_name(pass) != CARD) continue;
    ++cards;
    const RayPass& ray = std::get<RayPass>(pass);
    EXPECT_EQ(ray.colour, HALL);
    EXPECT_EQ(ray.depth, DEPTH_TARGET);
    EXPECT_EQ(int(ray.depth_test), int(DepthTest::TestAndWrite));
    EXPECT_EQ(ray.shader, "lenticular_card/card_pass.glsl");
  }
  EXPECT_EQ(cards, 1);
}

TEST(MuseumCard, TheHallAndTheCardHideEachOtherByDepth) {
  const FrameContext ctx = museum_context(BELOW_CARD);
  const test::MuseumTargets hall = test::run_museum_passes(ctx, {HALL});
  const test::MuseumTargets card = test::run_museum_passes(ctx, {CARD});
  const test::MuseumTargets both = test::run_museum_passes(ctx, {HALL, CARD});
  int shown = 0, hidden = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const float zh = hall.depth.at(x, y)[0], zc = card.depth.at(x, y)[0];
      const float z = both.depth.at(x, y)[0];
      const float* c = both.colour.at(x, y);
      const float* expected = zc < zh ? card.colour.at(x, y) : hall.colour.at(x, y);
      shown += zc < zh;
      hidden += zc < 1.0f && zc >= zh;
      EXPECT_EQ(z, std::min(zh, zc)) << x << "," << y;
      EXPECT_TRUE(c[0] == expected[0] && c[1] == expected[1] && c[2] == expected[2])
          << x << "," << y;
    }
  EXPECT_GT(shown, W * H / 10) << "the card should fill much of this view";
  EXPECT_GT(hidden, 10) << "the plinth's edge should hide the card's base";
}

// The bench's per-surface errors need one id per surface: the card (3) and its stand (4) are
// not the hall (2) or exhibit 1 (1).
TEST(MuseumCard, CardAndStandHaveHitIdsOfTheirOwn) {
  FrameContext ctx = museum_context(BELOW_CARD);
  ctx.march.hit_mask = true;
  const test::MuseumTargets ids = test::run_museum_passes(ctx, {CARD});
  std::set<float> seen;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (ids.depth.at(x, y)[0] < 1.0f) seen.insert(ids.colour.at(x, y)[0]);
  EXPECT_EQ(seen, (std::set<float>{3.0f, 4.0f}));
}

TEST(MuseumCard, TexturesHoldThePrintsAndTheProbeUnderAKeyThatFollowsBoth) {
  const CameraPose pose = find_scene("museum")->default_camera;
  std::unique_ptr<Scene> a = find_scene("museum")->make();
  std::unique_ptr<Scene> b = find_scene("museum")->make();
  a->prepare(museum_context(pose));
  std::set<std::string> names;
  for (const ShaderTexture& t : a->shader_textures()) names.insert(t.name);
  EXPECT_EQ(names, (std::set<std::string>{"u_probe", "u_card_print", "u_card_ridges"}));
  const uint64_t key = a->shader_textures_key();
  EXPECT_NE(key, 0u);
  b->prepare(museum_context(pose));
  EXPECT_EQ(b->shader_textures_key(), key) << "same frame inputs, same texels";
  b->prepare(museum_context(pose, 0.25));  // exhibit 1 lifted: its probe moves
  EXPECT_NE(b->shader_textures_key(), key);
}

}  // namespace
}  // namespace sdfreel
