// Per-pixel adaptive sampling on the CPU (render/adaptive_sampling.h): the frame and the samples
// each pixel took do not depend on threads, tiles, packets or the runner's path; threshold 0 is
// fixed sampling at the maximum; a flat frame stops at the minimum everywhere; a sub-pixel star
// runs to the maximum and its neighbours take more than the minimum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include "backends/cpu/plan_runner.h"
#include "passes/plan_fixture.h"
#include "scenes/registry.h"

namespace sdfreel {
namespace {

// 0 or 1 from the bits of the ray direction: unrelated to the neighbours' rays.
glm::vec3 hashed(const glm::vec3& d) {
  uint32_t h = 0;
  for (int c = 0; c < 3; ++c) {
    uint32_t b;
    std::memcpy(&b, &d[c], 4);
    h = (h ^ b) * 0x9E3779B1u;
  }
  return glm::vec3(float((h >> 16) & 1u));
}

// A ray pass whose colour is colour(dir), on both the packet and the scalar path.
template <class Colour>
RayPass colour_pass(const std::string& name, Colour colour) {
  RayPass p;
  p.name = name;
  p.packet = [colour](const RayPacket& r, RayPassOutput& out, RayStats&) {
    for (int i = 0; i < r.count; ++i) {
      out.colour[i] = colour(r.dir.lane(i));
      out.keep[i] = true;
    }
  };
  p.scalar = [colour](const Ray& r, glm::vec3& c, float&, bool& keep, RayStats&) {
    c = colour(r.dir);
    keep = true;
  };
  return p;
}

// A ray pass whose colour is hashed(dir), or a constant.
RayPass test_pass(bool flat) {
  return colour_pass(flat ? "flat" : "hashed", [flat](const glm::vec3& d) {
    return flat ? glm::vec3(0.3f, 0.5f, 2.0f) : hashed(d);
  });
}

FramePlan plan_of(const RayPass& pass) {
  FramePlan plan;
  plan.passes = {pass};
  return plan;
}

// Writes into a target of its own: the frame stays the same, but the plan runs once per sample.
FramePlan with_side_pass(FramePlan plan) {
  ImagePass p;
  p.name = "side";
  p.output = "side";
  p.pixel = [](const ImageInputs&, int, int) { return glm::vec4(0.5f); };
  plan.targets.push_back({"side", TargetKind::Colour, glm::vec4(0.0f)});
  plan.passes.push_back(p);
  return plan;
}

struct Rendered {
  ImageRGBA image;
  SampleCounts counts;
};

Rendered run(const FramePlan& plan, const FrameContext& ctx, CpuRunSettings s) {
  Rendered r;
  RayStats stats;
  r.image = run_plan_cpu(plan, ctx, s, stats, &r.counts);
  return r;
}

// Every way the CPU can run the plan: threads and tile sizes, the per-pixel packet path, single
// rays, and the per-sample loop. All must give `want`'s bits and counts.
void expect_every_way_gives(const FramePlan& plan, const FrameContext& ctx, const Rendered& want,
                            const std::string& what) {
  const Rendered ways[] = {run(plan, ctx, {1, 16, true}), run(plan, ctx, {2, 7, true}),
                           run(plan, ctx, {2, 5, false}),
                           run(with_side_pass(plan), ctx, {2, 16, true})};
  for (const Rendered& r : ways) {
    EXPECT_EQ(r.image.pixels, want.image.pixels) << what;
    EXPECT_EQ(r.counts, want.counts) << what;
  }
}

FrameContext adaptive_context(int w, int h, AdaptiveSampling a) {
  FrameContext ctx = test::plan_context(w, h);
  ctx.adaptive = a;
  finish_frame_context(ctx);
  return ctx;
}

TEST(AdaptiveSampling, FlatFrameStopsAtTheMinimumEverywhere) {
  const FrameContext ctx = adaptive_context(21, 13, {true, 3, 16, 1e-6f});
  const FramePlan plan = plan_of(test_pass(true));
  const Rendered r = run(plan, ctx, {2, 16, true});
  EXPECT_EQ(r.counts, SampleCounts(21 * 13, 3));
  expect_every_way_gives(plan, ctx, r, "flat");
}

// A sub-pixel star: one bright point that only sample 1 of pixel (9, 5) hits. That pixel's
// halves never agree, so it runs to the maximum; its neighbours' own samples all miss, yet they
// differ from it and take more than the minimum (the edge estimate); the rest of the frame is
// flat and stops at the minimum.
TEST(AdaptiveSampling, SubPixelStarRunsToTheMaximum) {
  const int w = 23, h = 11, sx = 9, sy = 5;
  const FrameContext ctx = adaptive_context(w, h, {true, 2, 12, 0.01f});
  const glm::vec2 o = ctx.sample_offsets[1];
  const glm::vec3 star = primary_ray_dir(ctx.camera, float(sx) + o.x, float(sy) + o.y, w, h);
  const float radius = glm::length(
      primary_ray_dir(ctx.camera, float(sx) + o.x + 0.05f, float(sy) + o.y, w, h) - star);
  const RayPass pass = colour_pass("star", [star, radius](const glm::vec3& d) {
    return glm::length(d - star) < radius ? glm::vec3(100.0f) : glm::vec3(0.1f);
  });
  const FramePlan plan = plan_of(pass);
  const Rendered r = run(plan, ctx, {2, 16, true});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int n = r.counts[size_t(y) * w + x],
                ring = std::max(std::abs(x - sx), std::abs(y - sy));
      if (ring == 0) {
        EXPECT_EQ(n, 12);
        EXPECT_NEAR(r.image.at(x, y)[0], (100.0f + 11 * 0.1f) / 12.0f, 1e-4f);
      } else if (ring == 1) {
        EXPECT_GT(n, 2) << x << "," << y;
        EXPECT_NEAR(r.image.at(x, y)[0], 0.1f, 1e-6f) << x << "," << y;
      } else {
        EXPECT_EQ(n, 2) << x << "," << y;
      }
    }
  expect_every_way_gives(plan, ctx, r, "star");
}

FrameContext scene_context(const SceneInfo& info, int samples, AdaptiveSampling a) {
  FrameContext ctx;
  ctx.width = 29;  // not a multiple of the tile size or of eight lanes
  ctx.height = 17;
  ctx.samples = samples;
  ctx.adaptive = a;
  ctx.scene_time = ctx.video_time = 2.0;
  ctx.pose = info.default_camera;
  ctx.params = ParamValues(&info.params);
  finish_frame_context(ctx);
  return ctx;
}

TEST(AdaptiveSampling, ThresholdZeroGivesTheBitsOfFixedMaximum) {
  for (const SceneInfo& info : all_scenes()) {
    std::unique_ptr<Scene> scene = info.make();
    const FrameContext fixed = scene_context(info, 5, {});
    const FrameContext adaptive = scene_context(info, 1, {true, 2, 5, 0.0f});
    scene->prepare(fixed);
    const Rendered f = run(scene->frame_plan(fixed), fixed, {2, 16, true});
    scene->prepare(adaptive);
    const Rendered a = run(scene->frame_plan(adaptive), adaptive, {2, 16, true});
    EXPECT_EQ(a.image.pixels, f.image.pixels) << info.name;
    EXPECT_EQ(a.counts, SampleCounts(29 * 17, 5)) << info.name;
  }
}

TEST(AdaptiveSampling, ScenesGiveTheSameBitsEveryWay) {
  for (const SceneInfo& info : all_scenes()) {
    std::unique_ptr<Scene> scene = info.make();
    const FrameContext ctx = scene_context(info, 1, {true, 2, 10, 0.01f});
    scene->prepare(ctx);
    const FramePlan plan = scene->frame_plan(ctx);
    const Rendered r = run(plan, ctx, {2, 16, true});
    int stopped_early = 0;
    for (uint16_t n : r.counts) stopped_early += n < 10;
    EXPECT_GT(stopped_early, 0) << info.name;
    expect_every_way_gives(plan, ctx, r, info.name);
  }
}

}  // namespace
}  // namespace sdfreel
