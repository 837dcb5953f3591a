// The OSMesa backend uploads a scene's textures once per content key (Scene::shader_textures_key):
// a frame rendered after another with a different texture seed must equal the same frame from a
// fresh backend, so a stale texture can never survive a change of seed.
#include <gtest/gtest.h>

#include <cstring>

#include "backends/gl/gl_backend.h"
#include "render/frame_context.h"
#include "scenes/registry.h"

namespace sdfreel {
namespace {

FrameContext lantern_context(const SceneInfo& info, uint64_t seed) {
  FrameContext ctx;
  ctx.width = 32;
  ctx.height = 18;
  ctx.seed = seed;
  ctx.scene_time = 2.0;
  ctx.quality = Quality::Draft;
  ctx.pose = info.default_camera;
  ctx.params = ParamValues(&info.params);
  finish_frame_context(ctx);
  return ctx;
}

TEST(OsmesaTextures, ChangingTheSeedUploadsNewTextures) {
  const SceneInfo* info = find_scene("lantern_festival");
  ASSERT_NE(info, nullptr);
  std::unique_ptr<GlBackend> reused, fresh;
  try {
    reused = std::make_unique<GlBackend>();
    fresh = std::make_unique<GlBackend>();
  } catch (const std::exception& e) {
    GTEST_SKIP() << "OSMesa unavailable: " << e.what();
  }
  reused->begin(*info);
  fresh->begin(*info);
  RayStats stats;
  const ImageRGBA a = reused->render(lantern_context(*info, 1), stats);
  const ImageRGBA b = reused->render(lantern_context(*info, 2), stats);
  const ImageRGBA expected = fresh->render(lantern_context(*info, 2), stats);
  ASSERT_EQ(b.pixels.size(), expected.pixels.size());
  EXPECT_EQ(std::memcmp(b.pixels.data(), expected.pixels.data(), b.pixels.size() * sizeof(float)),
            0);
  // The seeds give different lantern layouts: the test would notice stale textures.
  EXPECT_NE(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace sdfreel
