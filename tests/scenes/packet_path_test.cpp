// The CPU backend's two paths give the same bits: eight-lane packets (Scene::radiance_packet) and
// one ray at a time (Scene::radiance), for every registered scene (from its test poses, SceneInfo),
// preset and debug mode, with partial
// packets (odd sizes, sample counts that are not multiples of eight), for any thread count and
// tile size. The ray statistics the bench reports must match too.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "backends/cpu/cpu_backend.h"
#include "render/frame_context.h"
#include "scenes/registry.h"

namespace sdfreel {
namespace {

struct Case {
  std::string scene;
  Quality quality;
  int samples;
  bool naive = false;
  bool hit_mask = false;
};

FrameContext context(const SceneInfo& info, const Case& c, const CameraPose& pose, double time) {
  FrameContext ctx;
  ctx.width = 27;  // 27 x 13: edge tiles and packets that are not full
  ctx.height = 13;
  ctx.samples = c.samples;
  ctx.scene_time = time;
  ctx.quality = c.quality;
  ctx.pose = pose;
  ctx.params = ParamValues(&info.params);
  finish_frame_context(ctx);
  if (c.naive) ctx.march = naive_march_settings();
  ctx.march.hit_mask = c.hit_mask;
  return ctx;
}

struct Frame {
  ImageRGBA image;
  RayStats stats;
};

Frame render(const SceneInfo& info, const FrameContext& ctx, bool packets, int threads = 2,
             int tile = 16) {
  CpuBackend backend(threads, tile, packets);
  backend.begin(info);
  Frame f{ImageRGBA(1, 1), RayStats{}};
  f.image = backend.render(ctx, f.stats);
  return f;
}

bool same_bits(const ImageRGBA& a, const ImageRGBA& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

class PacketPath : public ::testing::TestWithParam<Case> {};

TEST_P(PacketPath, SameBitsAndStatsAsOneRayAtATime) {
  const Case& c = GetParam();
  const SceneInfo* info = find_scene(c.scene);
  ASSERT_NE(info, nullptr);
  for (const CameraPose& pose : test_camera_poses(*info))
    for (double time : {0.0, 3.7}) {
      const FrameContext ctx = context(*info, c, pose, time);
      const Frame scalar = render(*info, ctx, false);
      const Frame packets = render(*info, ctx, true);
      EXPECT_TRUE(same_bits(scalar.image, packets.image)) << "time " << time;
      EXPECT_EQ(scalar.stats.sdf_evals, packets.stats.sdf_evals);
      EXPECT_EQ(scalar.stats.steps, packets.stats.steps);
      EXPECT_EQ(scalar.stats.capped, packets.stats.capped);
    }
}

TEST_P(PacketPath, IndependentOfThreadsAndTileSize) {
  const Case& c = GetParam();
  const SceneInfo* info = find_scene(c.scene);
  ASSERT_NE(info, nullptr);
  const FrameContext ctx = context(*info, c, info->default_camera, 1.3);
  const Frame a = render(*info, ctx, true, 1, 16);
  const Frame b = render(*info, ctx, true, 2, 5);
  EXPECT_TRUE(same_bits(a.image, b.image));
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const SceneInfo& info : all_scenes()) {
    const std::string& s = info.name;
    out.push_back({s, Quality::Draft, 1});
    out.push_back({s, Quality::Final, 3});
    out.push_back({s, Quality::Final, 1, true});         // naive
    out.push_back({s, Quality::Final, 2, false, true});  // hit mask
    out.push_back({s, Quality::Reference, 1});
  }
  return out;
}

std::string case_name(const ::testing::TestParamInfo<Case>& i) {
  const Case& c = i.param;
  std::string q = c.quality == Quality::Draft   ? "draft"
                  : c.quality == Quality::Final ? "final"
                                                : "reference";
  if (c.naive) q = "naive";
  if (c.hit_mask) q += "_hitmask";
  return c.scene + "_" + q + "_" + std::to_string(c.samples) + "spp";
}

INSTANTIATE_TEST_SUITE_P(Scenes, PacketPath, ::testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace sdfreel
