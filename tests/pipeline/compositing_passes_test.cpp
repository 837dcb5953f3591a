// Compositing passes of a frame ([output] passes, render/compositing_passes.h): the samples pass
// is what the backend sampled, the sdf_evals pass adds up to the frame's own count and is the same
// on the CPU's packet and single-ray paths, and asking for passes changes no pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "backends/cpu/cpu_backend.h"
#include "pipeline/frame_pipeline.h"
#include "scenes/registry.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

Timeline small_timeline(const std::string& scene, const std::string& sampling,
                        const std::string& passes) {
  const std::string text = "[video]\nscene = \"" + scene +
                           "\"\nfps = 24\nduration = 1\nresolution = [48, 27]\n" + sampling +
                           "\n[output]\nframes = [\"exr\"]\n" + passes + "\n";
  return parse_timeline(all_scenes(), "passes.toml", text, nullptr, nullptr);
}

const PassImage& pass_named(const RenderedFrame& f, const std::string& name) {
  for (const PassImage& p : f.passes)
    if (p.name == name) return p;
  throw std::runtime_error("no pass " + name);
}

TEST(CompositingPasses, EvalsAddUpToTheFrameCountOnBothCpuPathsInEveryScene) {
  for (const SceneInfo& scene : all_scenes()) {
    if (!scene.counts_sdf_evals) continue;
    const Timeline tl =
        small_timeline(scene.name, "samples = 2", "passes = [\"sdf_evals\", \"samples\"]");
    std::vector<std::vector<float>> evals;
    for (bool packets : {true, false}) {
      FramePipeline pipe(tl, std::make_unique<CpuBackend>(2, 16, packets));
      const RenderedFrame f = pipe.render(5);
      ASSERT_EQ(f.passes.size(), 2u);
      EXPECT_EQ(f.passes[0].name, "sdf_evals");  // in the order asked for
      const PassImage& e = pass_named(f, "sdf_evals");
      ASSERT_EQ(e.values.size(), size_t(48 * 27));
      double sum = 0.0;
      for (float v : e.values) {
        ASSERT_GE(v, 0.0f);
        ASSERT_EQ(v, std::floor(v));
        sum += v;
      }
      EXPECT_GT(sum, 0.0) << scene.name;
      EXPECT_EQ(sum, double(f.stats.sdf_evals)) << scene.name << (packets ? " packets" : " rays");
      for (float v : pass_named(f, "samples").values) ASSERT_EQ(v, 2.0f);
      evals.push_back(e.values);
    }
    EXPECT_EQ(evals[0], evals[1]) << scene.name << ": packets and single rays count differently";
  }
}

// The id pass names the surface under each pixel's centre, in the scene's numbering: sdf_morph's
// object (1) and pedestal (2) where the default camera sees them, nothing (0) above them.
TEST(CompositingPasses, IdIsTheSurfaceAtThePixelsCentre) {
  const Timeline tl = small_timeline("sdf_morph", "samples = 3", "passes = [\"id\"]");
  FramePipeline pipe(tl, std::make_unique<CpuBackend>(2));
  const RenderedFrame f = pipe.render(5);
  const std::vector<float>& id = pass_named(f, "id").values;
  EXPECT_EQ(id[8 * 48 + 22], 1.0f);   // the morphing object
  EXPECT_EQ(id[18 * 48 + 24], 2.0f);  // its pedestal
  EXPECT_EQ(id[0], 0.0f);             // the studio behind
  for (float v : id) ASSERT_TRUE(v == 0.0f || v == 1.0f || v == 2.0f) << v;
  // One ray through each centre in hit-mask mode: exactly that render of the frame's context.
  FrameContext ctx = f.ctx;
  ctx.samples = 1;
  finish_frame_context(ctx);
  ctx.march.hit_mask = true;
  CpuBackend cpu(1);
  cpu.begin(pipe.scene());
  RayStats stats;
  const ImageRGBA mask = cpu.render(ctx, stats);
  for (size_t i = 0; i < id.size(); ++i) ASSERT_EQ(id[i], mask.pixels[i * 4]) << i;
}

// An adaptive frame of a plan of several passes (the museum) and of one ray pass (the lanterns):
// the samples pass is the backend's count, and the picture is the one rendered without passes.
TEST(CompositingPasses, SamplesAreTheBackendsCountsAndPassesChangeNoPixel) {
  for (const std::string scene : {"museum", "lantern_festival"}) {
    const std::string sampling = "adaptive = { minimum = 1, maximum = 6, threshold = 0.02 }";
    const Timeline with = small_timeline(scene, sampling, "passes = [\"samples\", \"id\"]");
    const Timeline without = small_timeline(scene, sampling, "");
    FramePipeline pipe(with, std::make_unique<CpuBackend>(2));
    const RenderedFrame f = pipe.render(3);
    const SampleCounts& counts = f.sample_counts;  // the frame's, not the id render's
    const PassImage& samples = pass_named(f, "samples");
    EXPECT_EQ(samples.channels, std::vector<std::string>{"samples"});
    ASSERT_EQ(samples.values.size(), counts.size());
    for (size_t i = 0; i < counts.size(); ++i) ASSERT_EQ(samples.values[i], float(counts[i]));
    const auto [lo, hi] = std::minmax_element(counts.begin(), counts.end());
    EXPECT_EQ(*lo, 1) << scene;  // adaptive: the counts vary
    EXPECT_GT(*hi, 1) << scene;
    FramePipeline plain(without, std::make_unique<CpuBackend>(2));
    const RenderedFrame g = plain.render(3);
    EXPECT_TRUE(g.passes.empty());
    EXPECT_EQ(f.linear_hash, g.linear_hash) << scene;
    EXPECT_EQ(f.display_md5, g.display_md5) << scene;
  }
}

}  // namespace
}  // namespace sdfreel
