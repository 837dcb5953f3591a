// The fur's strand hash in GLSL (shaders/fur/strand_hash.glsl) against its C++ twin
// (src/scenes/fur/strand_hash.h), bit for bit, on cells around 0, negative cells and cells near
// +-2^24 (the largest the float uniforms carry exactly): a mismatch would give the backends
// different fur.
#include <cstdint>

#include "gl/gl_fixture.h"
#include "scenes/fur/strand_hash.h"

namespace sdfreel {
namespace {

using test::GlTest;

constexpr int W = 128, H = 128;

void expect_same_hashes(GlDriver& driver, GlPlatform& platform, glm::ivec2 origin,
                        glm::ivec2 stride) {
  GlPass pass;
  pass.name = "fur hash probe";
  pass.program = driver.compile({"common/fullscreen.vert", "fur_hash_probe.glsl", ""});
  pass.target = platform.frame_target(W, H);
  pass.uniforms = {{"u_origin", 2, {float(origin.x), float(origin.y)}},
                   {"u_stride", 2, {float(stride.x), float(stride.y)}}};
  driver.run(pass);
  const ImageRGBA img = driver.read_rgba(pass.target);
  int mismatches = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      // Image row 0 is the top row: window row H - 1 - y.
      const glm::ivec2 cell = origin + glm::ivec2(x, H - 1 - y) * stride;
      const glm::uvec2 h = fur::pcg2d(glm::uvec2(uint32_t(cell.x), uint32_t(cell.y)));
      const float* got = img.at(x, y);
      const bool same = got[0] == float(h.x >> 16u) && got[1] == float(h.x & 65535u) &&
                        got[2] == float(h.y >> 16u) && got[3] == fur::strand_random(cell.x, cell.y);
      if (!same && mismatches++ < 5)
        ADD_FAILURE() << "cell (" << cell.x << ", " << cell.y << "): GLSL " << got[0] << " "
                      << got[1] << " " << got[2] << " " << got[3] << ", C++ " << (h.x >> 16u) << " "
                      << (h.x & 65535u) << " " << (h.y >> 16u) << " "
                      << fur::strand_random(cell.x, cell.y);
    }
  EXPECT_EQ(mismatches, 0);
}

TEST_F(GlTest, FurStrandHashIsTheSameInGlsl) {
  expect_same_hashes(*driver, *platform, {-64, -64}, {1, 1});
  expect_same_hashes(*driver, *platform, {-16777000, 16776000}, {7, 3});
  expect_same_hashes(*driver, *platform, {1000, -500000}, {997, 7919});
}

}  // namespace
}  // namespace sdfreel
