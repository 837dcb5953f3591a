// Compositing passes through the frame pipeline on both backends: every pass the scene gives
// (samples, SDF evaluations, surface ids, depth, normals) the same pixel by pixel, and a frame
// rendered after a frame with passes is the frame rendered alone (the id pass's second render
// leaves nothing behind).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "backends/cpu/cpu_backend.h"
#include "backends/gl/gl_backend.h"
#include "gl/mesa_bits.h"
#include "pipeline/frame_pipeline.h"
#include "scenes/registry.h"
#include "scenes/scene_passes.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

Timeline passes_timeline(const std::string& scene, const std::string& passes) {
  const std::string text = "[video]\nscene = \"" + scene +
                           "\"\nfps = 24\nduration = 1\nresolution = [48, 27]\n"
                           "adaptive = { minimum = 1, maximum = 6, threshold = 0.02 }\n"
                           "[output]\nframes = [\"exr\"]\npasses = [" +
                           passes + "]\n";
  return parse_timeline(all_scenes(), "passes.toml", text, nullptr, nullptr);
}

TEST(PassesAgreement, BothBackendsGiveTheSamePasses) {
  for (const std::string scene :
       {"sdf_morph", "light_beams", "lantern_festival", "water_lily", "lenticular_card"}) {
    std::string names;
    for (const std::string& p : scene_passes(*find_scene(scene)))
      names += (names.empty() ? "\"" : ", \"") + p + "\"";
    const Timeline tl = passes_timeline(scene, names);
    std::unique_ptr<GlBackend> gl;
    try {
      gl = std::make_unique<GlBackend>();
    } catch (const std::exception& e) {
      GTEST_SKIP() << "GL unavailable: " << e.what();
    }
    if (!test::llvmpipe_bit_exact(*gl)) GTEST_SKIP() << "this Mesa's llvmpipe is not bit-exact";
    FramePipeline on_gl(tl, std::move(gl));
    FramePipeline on_cpu(tl, std::make_unique<CpuBackend>(2));
    for (int frame : {4, 9}) {
      const RenderedFrame a = on_cpu.render(frame), b = on_gl.render(frame);
      EXPECT_EQ(a.linear_hash, b.linear_hash) << scene << " frame " << frame;
      ASSERT_EQ(a.passes.size(), b.passes.size());
      ASSERT_GE(a.passes.size(), 3u);
      for (size_t i = 0; i < a.passes.size(); ++i)
        EXPECT_EQ(a.passes[i].values, b.passes[i].values)
            << scene << " frame " << frame << ": pass " << a.passes[i].name;
    }
    // Frame 9 after frame 4 and its id render: the bits of frame 9 rendered alone.
    const Timeline plain = passes_timeline(scene, "");
    FramePipeline alone(plain, std::make_unique<GlBackend>());
    EXPECT_EQ(alone.render(9).linear_hash, on_gl.render(9).linear_hash) << scene;
  }
}

}  // namespace
}  // namespace sdfreel
