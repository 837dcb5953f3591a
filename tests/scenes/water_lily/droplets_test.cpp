// Water drops on the pads and petals (seed 001's wish list, issue 28): placed by a hash, each
// inside its grid cell, only on faces that look up, as many as the share asks; in a frame they
// catch the sun (highlights brighter than any pad without them) and darken at their rims.
#include "scenes/water_lily/droplets.h"

#include <gtest/gtest.h>

#include "render/camera.h"
#include "scenes/registry.h"
#include "scenes/scene_pixels.h"
#include "scenes/water_lily/layout.h"

namespace sdfreel::water_lily {
namespace {

using glm::vec2;
using glm::vec3;

// The share of a 2 x 2 square of ground plan covered by drops (cover > 0.5), sampled finely.
float covered(float share, float up) {
  constexpr int N = 400;
  int in = 0;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      in +=
          dropletAt(vec2(-1.0f + 2.0f * i / N, -1.0f + 2.0f * j / N), DROP_SEED, share, up).cover >
          0.5f;
  return float(in) / float(N * N);
}

TEST(WaterLilyDroplets, AsManyAsTheShareAsksOnlyOnFacesThatLookUp) {
  EXPECT_EQ(covered(0.0f, 1.0f), 0.0f);
  EXPECT_EQ(covered(1.0f, DROP_UP0), 0.0f) << "a face steeper than DROP_UP0 holds none";
  const float pads = covered(DROP_SHARE_PAD, 1.0f), all = covered(1.0f, 1.0f);
  // A drop of mean radius 0.19 cells covers about 11% of its cell.
  EXPECT_GT(pads, 0.02f);
  EXPECT_LT(pads, 0.12f);
  EXPECT_NEAR(pads / all, DROP_SHARE_PAD, 0.1f);
}

TEST(WaterLilyDroplets, EachDropStaysInsideItsCell) {
  constexpr int N = 200;  // samples along each cell edge, for 8 x 8 cells
  for (int i = 0; i < 8 * N; ++i)
    for (int j = 0; j < 8 * N; ++j) {
      const float u = (i + 0.5f) / N, v = (j + 0.5f) / N;
      const float fu = u - float(int(u)), fv = v - float(int(v));
      const bool border = fu < 0.015f || fu > 0.985f || fv < 0.015f || fv > 0.985f;
      if (!border) continue;
      EXPECT_EQ(dropletAt(vec2(u, v) * DROP_CELL, DROP_SEED, 1.0f, 1.0f).cover, 0.0f)
          << u << " " << v;
    }
}

// Looking down at pad 0 from above: with drops, some pixels are brighter than the brightest pixel
// of the pad without them (the sun's highlight on a drop) and the rims darken others.
TEST(WaterLilyDroplets, DropsOnAPadCatchTheSun) {
  const SceneInfo& info = *find_scene("water_lily");
  const LeafPlacement& pad = LEAVES[0];
  test::ScenePixels img[2];
  for (int k = 0; k < 2; ++k) {
    FrameContext ctx = test::scene_context(info, 192, 192, 0.0, Quality::Final);
    // The pad's sunlit side, seen from near where it mirrors the sun: domes turn it to the eye.
    const glm::dvec3 at(pad.xz.x + 0.35, 0.0, pad.xz.y - 0.45);
    ctx.pose = CameraPose{at + glm::dvec3(0.25, 0.6, -0.3), at, 15.0, 0.0};
    ctx.params.set("droplets", {double(k)});
    finish_frame_context(ctx);
    img[k] = test::render_pixels(info, ctx);
  }
  const vec3 luma(0.2126f, 0.7152f, 0.0722f);
  float brightest = 0.0f;
  for (const vec3& c : img[0].px) brightest = std::max(brightest, glm::dot(c, luma));
  int highlights = 0, darker = 0;
  for (size_t i = 0; i < img[0].px.size(); ++i) {
    const float a = glm::dot(img[0].px[i], luma), b = glm::dot(img[1].px[i], luma);
    highlights += b > brightest + 0.05f;
    darker += b < 0.8f * a;
  }
  EXPECT_GT(highlights, 0);
  EXPECT_GT(darker, 20);
}

}  // namespace
}  // namespace sdfreel::water_lily
