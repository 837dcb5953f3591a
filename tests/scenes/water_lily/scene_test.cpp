// The water_lily scene through its Scene interface (tiny images with a plain pixel loop) and its
// parts directly: every element of seed 001 must be there and move as the seed says.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "render/camera.h"
#include "render/frame_context.h"
#include "scenes/registry.h"
#include "scenes/scene_pixels.h"
#include "scenes/water_lily/geometry.h"
#include "scenes/water_lily/render.h"
#include "scenes/water_lily/uniforms.h"

namespace sdfreel::water_lily {
namespace {

using glm::vec3;

constexpr int W = 32, H = 18;

const SceneInfo& info() {
  const SceneInfo* s = find_scene("water_lily");
  EXPECT_NE(s, nullptr);
  return *s;
}

FrameContext context(double time, Quality q = Quality::Draft) {
  return test::scene_context(info(), W, H, time, q);
}

using Image = test::ScenePixels;

Image render(const FrameContext& ctx) {
  return test::render_pixels(info(), ctx);
}

TEST(WaterLily, IsRegisteredWithDocumentedParameters) {
  EXPECT_EQ(info().shader, "water_lily/water_lily.glsl");
  for (const char* name : {"curl_amount", "leaf_drift", "water_speed", "water_bump", "contrast",
                           "saturation", "vignette", "fog_distance", "petal_translucency"}) {
    const ParamSpec* p = find_param(info().params, name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_FALSE(p->doc.empty()) << name;
  }
}

TEST(WaterLily, DefaultViewIsFiniteAndShowsFlowersLeavesWaterAndSky) {
  const Image img = render(context(2.0, Quality::Final));
  for (const vec3& c : img.px)
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(c[k]) && c[k] >= 0.0f);
  EXPECT_EQ(img.stats.capped, 0u);
  // Hit ids of the same view: flowers and pads are both seen.
  FrameContext ctx = context(2.0);
  ctx.march.hit_mask = true;
  const Image ids = render(ctx);
  int flowers = 0, leaves = 0, none = 0;
  for (const vec3& c : ids.px) {
    flowers += c.x == 1.0f;
    leaves += c.x == 2.0f;
    none += c.x == 0.0f;
  }
  EXPECT_GT(flowers, 4);
  EXPECT_GT(leaves, 8);
  EXPECT_GT(none, 8);  // water and sky
}

TEST(WaterLily, PetalsCurlWithTimeAndTheDriftingLeafMoves) {
  const LilyUniforms a = make_lily_uniforms(context(0.0));
  const LilyUniforms b = make_lily_uniforms(context(2.5));
  for (int f = 0; f < FLOWER_COUNT; ++f) EXPECT_NE(a.curl[f], b.curl[f]) << f;
  EXPECT_NE(a.drift_offset, b.drift_offset);
  EXPECT_NE(a.water_time_a, b.water_time_a);
  // The drifting leaf's distance field moves with it; the others stay.
  const glm::vec2 c = LEAVES[DRIFTING_LEAF].xz;
  const vec3 p(c.x + 0.3f, LEAF_Y, c.y);
  EXPECT_NE(lilyPad(p, DRIFTING_LEAF, a), lilyPad(p, DRIFTING_LEAF, b));
  const vec3 q(LEAVES[0].xz.x, LEAF_Y, LEAVES[0].xz.y);
  EXPECT_EQ(lilyPad(q, 0, a), lilyPad(q, 0, b));
  EXPECT_GT(mean_abs_difference(render(context(0.0)), render(context(2.5))), 1e-3);
}

TEST(WaterLily, WaterIsCalmerFarAway) {
  const LilyUniforms u = make_lily_uniforms(context(1.0));
  double near = 0.0, far = 0.0;
  for (int i = 0; i < 64; ++i) {
    const float x = 0.37f * float(i), z = 0.23f * float(i);
    near += 1.0 - waterNormal(x, z, 1.0f, u).y;
    far += 1.0 - waterNormal(x, z, 16.0f, u).y;
  }
  EXPECT_GT(near, 0.0);
  EXPECT_LT(far, 0.25 * near);
  EXPECT_EQ(waterNormal(1.0f, 2.0f, 40.0f, u), vec3(0.0f, 1.0f, 0.0f));
}

TEST(WaterLily, WaterWrapsWithoutACut) {
  // Just before and after the water's time coordinate wraps, the normals barely change.
  FrameContext ctx = context(0.0);
  const double speed = ctx.params.scalar("water_speed");
  const double wrap_time = 512.0 / speed;
  const LilyUniforms before = make_lily_uniforms(context(wrap_time - 0.01));
  const LilyUniforms after = make_lily_uniforms(context(wrap_time + 0.01));
  EXPECT_GT(before.water_blend, 0.99f);
  EXPECT_EQ(after.water_blend, 0.0f);
  for (int i = 0; i < 16; ++i) {
    const vec3 a = waterNormal(0.3f * float(i), 0.7f, 1.0f, before);
    const vec3 b = waterNormal(0.3f * float(i), 0.7f, 1.0f, after);
    EXPECT_LT(glm::length(a - b), 0.02f) << i;
  }
}

TEST(WaterLily, SoftShadowDarkensUnderAFlowerAndNotInTheOpen) {
  const LilyUniforms u = make_lily_uniforms(context(0.0));
  RayStats stats;
  // A point on the water on the far side of flower 0 from the sun: shadowed.
  const FlowerPlacement& f = FLOWERS[0];
  const vec3 under = vec3(f.xz.x, 0.0f, f.xz.y) - u.sun_dir * (0.25f / u.sun_dir.y);
  EXPECT_LT(softShadow(vec3(under.x, 0.01f, under.z), u.sun_dir, u.shadow_k, 64, u, stats), 0.5f);
  EXPECT_EQ(softShadow(vec3(-6.0f, 0.01f, -3.0f), u.sun_dir, u.shadow_k, 64, u, stats), 1.0f);
}

TEST(WaterLily, GradingFollowsTheSeed) {
  LilyUniforms u = make_lily_uniforms(context(0.0));
  u.vignette = 0.0f;
  u.contrast = 1.0f;
  u.saturation = 1.0f;
  const vec3 rd = u.cam_forward;
  // Contrast col^2 (3 - 2 col): darks darker, lights lighter, 0.5 fixed.
  EXPECT_LT(grade(vec3(0.2f), rd, u).x, 0.2f);
  EXPECT_GT(grade(vec3(0.8f), rd, u).x, 0.8f);
  EXPECT_FLOAT_EQ(grade(vec3(0.5f), rd, u).x, 0.5f);
  // Vignette, the seed's curve: the centre keeps its value; a ray through the screen at (sx, sy)
  // (1 at the frame's sides) is scaled by 1 / (1 + falloff^2 r^2)^2.
  u.contrast = 0.0f;
  u.vignette = 0.5f;
  EXPECT_EQ(grade(vec3(0.5f), rd, u), vec3(0.5f));
  const double sx = 0.8, sy = 0.6;  // r^2 = 1
  const vec3 off_axis =
      glm::normalize(u.cam_forward + float(sx / (u.inv_tan_half_fov * u.inv_aspect)) * u.cam_right +
                     float(sy / u.inv_tan_half_fov) * u.cam_up);
  const double want =
      0.5 / ((1.0 + 0.25 * (sx * sx + sy * sy)) * (1.0 + 0.25 * (sx * sx + sy * sy)));
  EXPECT_NEAR(grade(vec3(0.5f), off_axis, u).x, want, 1e-5) << "0.5 / 1.25^2 = 0.32";
}

// Seen against the sun, a petal's far side glows with the light through it (petal_translucency):
// the sun's shadow ray for that light starts out of the flower (throughPetal), not inside the
// petal, where it found the petal and let nothing through.
TEST(WaterLily, BacklitPetalsGlowWithTheLightThroughThem) {
  const FlowerPlacement& f = FLOWERS[0];
  const vec3 centre(f.xz.x, 0.15f, f.xz.y);
  const LilyUniforms u0 = make_lily_uniforms(context(0.0));
  // Across the flower from the sun, a little above it: the petals' far sides face the camera.
  const vec3 away = -glm::normalize(vec3(u0.sun_dir.x, 0.0f, u0.sun_dir.z));
  const glm::dvec3 eye(centre + away * 1.1f + vec3(0.0f, 0.35f, 0.0f));
  Image img[2];
  for (int k = 0; k < 2; ++k) {
    FrameContext ctx = test::scene_context(info(), 64, 36, 0.0, Quality::Draft);
    ctx.pose = CameraPose{eye, glm::dvec3(centre), 40.0, 0.0};
    ctx.params.set("petal_translucency", {k == 0 ? 0.0 : 0.6});
    finish_frame_context(ctx);
    img[k] = test::render_pixels(info(), ctx);
  }
  int glowing = 0;
  for (size_t i = 0; i < img[0].px.size(); ++i) {
    const float a = glm::dot(img[0].px[i], vec3(0.2126f, 0.7152f, 0.0722f));
    const float b = glm::dot(img[1].px[i], vec3(0.2126f, 0.7152f, 0.0722f));
    ASSERT_GE(b, a - 1e-6f) << i;  // light through a petal only adds
    glowing += b > 1.1f * a + 0.005f;
  }
  EXPECT_GT(glowing, int(img[0].px.size()) / 20) << glowing << " of " << img[0].px.size();
}

// Seed 001's reflection of a lily is "a lighter color that fits the scene": the water mirroring
// a white petal's underside shows the petal's own near-white colour, lighter than the sky it
// hides there (the underside lit as such came out a dark reddish-brown).
TEST(WaterLily, ReflectedLiliesAreTheirOwnLighterColours) {
  LilyUniforms u = make_lily_uniforms(context(0.0));
  u.vignette = 0.0f;  // the ray below is not the camera's
  RayStats stats;
  // Flower 0 (white) from below: up from the water beside its axis to an outer petal's underside.
  const FlowerPlacement& f = FLOWERS[0];
  vec3 q(f.xz.x + 0.3f, 0.0f, f.xz.y + 0.3f);
  for (int i = 0; i < 200; ++i) {
    const float d = mapScene(q, false, u, stats);
    if (d < 1e-4f) break;
    q.y += d;
  }
  ASSERT_LT(mapScene(q, false, u, stats), 1e-3f);
  ASSERT_GT(q.y, 0.0f);
  // A water point in front of it and the mirror's geometry: the ray from the eye meets the water
  // at w, at a grazing angle (where the water mirrors most), and goes on up along r to q.
  const vec3 w(q.x, 0.0f, q.z + 2.0f);
  const vec3 r = glm::normalize(q - w);
  PixelShade ps;
  ps.kind = SHADE_WATER;
  ps.rd = vec3(r.x, -r.y, r.z);
  ps.dist = 2.0f;
  ps.p = w;
  ps.n = vec3(0.0f, 1.0f, 0.0f);
  ps.rays.reflect = true;
  ps.rays.reflect_origin = w;
  ps.rays.reflect_dir = r;
  ps.rays.sun_shadow = ps.rays.fill_shadow = 1.0f;
  ps.rays.reflect_t = glm::length(q - w);
  const vec3 lily = shadeEnd(ps, u);
  ps.rays.reflect_t = NO_HIT;
  const vec3 sky = shadeEnd(ps, u);
  const vec3 luma(0.2126f, 0.7152f, 0.0722f);
  EXPECT_GT(glm::dot(lily, luma), glm::dot(sky, luma)) << "lighter than the sky it hides";
  EXPECT_GT(lily.g / lily.r, 0.8f) << "near-white, not reddish: " << lily.r << " " << lily.g;
  EXPECT_GT(lily.b / lily.r, 0.7f) << lily.r << " " << lily.b;
}

TEST(WaterLily, HugeTimeKeepsAnimating) {
  const LilyUniforms a = make_lily_uniforms(context(1e6));
  const LilyUniforms b = make_lily_uniforms(context(1e6 + 1.0 / 30.0));
  EXPECT_NE(a.curl[0], b.curl[0]);
  EXPECT_NE(a.water_time_a, b.water_time_a);
  EXPECT_LT(std::abs(a.curl[0] - b.curl[0]), 0.01f);
}

}  // namespace
}  // namespace sdfreel::water_lily
