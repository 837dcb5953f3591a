// The light_beams scene: the glow formula, the flicker against the seed's formula, the camera's
// 2D view, and frames through the Scene interface.
#include <gtest/gtest.h>

#include <cmath>

#include "render/camera.h"
#include "render/frame_context.h"
#include "scenes/light_beams/crossings.h"
#include "scenes/light_beams/render.h"
#include "scenes/light_beams/visibility.h"
#include "scenes/registry.h"

namespace sdfreel::light_beams {
namespace {

using glm::vec3;

const SceneInfo& info() {
  const SceneInfo* s = find_scene("light_beams");
  EXPECT_NE(s, nullptr);
  return *s;
}

FrameContext context(double time, Quality q = Quality::Final) {
  FrameContext ctx;
  ctx.width = 64;
  ctx.height = 36;
  ctx.scene_time = time;
  ctx.quality = q;
  ctx.pose = info().default_camera;
  ctx.params = ParamValues(&info().params);
  finish_frame_context(ctx);
  return ctx;
}

// The seed's GLSL flicker in double, unwrapped.
double seed_flicker(double seed, double speed, double time) {
  const double pi = 3.141592653589793;
  const double s = seed / speed + time;
  return std::cos(std::sin(s / (0.1 * pi)) + std::cos(1.5 * s)) +
         std::sin(s / pi + std::cos(10.0 * s));
}

TEST(LightBeamsScene, FlickerFollowsTheSeedsFormula) {
  int on = 0, compared = 0;
  for (double base : {0.0, 1e6}) {
    for (int i = 0; i < 20000; ++i) {
      const double t = base + i * 0.003;
      const double want = seed_flicker(4.3, 0.8, t);
      EXPECT_NEAR(flicker_value(4.3, 0.8, t), want, 2e-5) << t;
      if (std::abs(want - FLICKER_THRESHOLD) > 1e-4) {
        ++compared;
        EXPECT_EQ(flicker(4.3, 0.8, t), want > FLICKER_THRESHOLD) << t;
        on += want > FLICKER_THRESHOLD;
      }
    }
  }
  EXPECT_GT(on, 0) << "the beams never flicker over the sampled minutes";
  EXPECT_LT(on, compared / 5);
}

TEST(LightBeamsScene, GlowIsTheSeedsInverseQuadratic) {
  BeamsUniforms u;
  u.glow_constant = 0.5f;
  u.glow_linear = 3.0f;
  u.glow_quadratic = 7.0f;
  for (float d : {0.0f, 0.01f, 0.3f, 2.0f})
    EXPECT_FLOAT_EQ(attenuation(d, u), 1.0f / (0.5f + 3.0f * d + 7.0f * d * d)) << d;
}

TEST(LightBeamsScene, LightsAreWhiteInsideAndOnTheEdgeAndColouredInTheGlow) {
  BeamsUniforms u = make_beams_uniforms(context(0.0));
  const int amber = 0;
  const float gain = u.gain[amber];
  ASSERT_GT(gain, 0.0f);
  RayStats stats;
  const vec2 c = u.shapes[amber].a;
  EXPECT_EQ(lightEmission(c, amber, 0.01f, u, stats), vec3(gain));
  // On the edge (d = 0 exactly: a circle of radius 0.5 at the origin) still white.
  u.shapes[amber] = Shape{SHAPE_CIRCLE, {0.0f, 0.0f}, {}, 0.5f};
  u.shapes[OCCLUDER].a = u.shapes[OCCLUDER].b = vec2(50.0f, 50.0f);
  findCrossings(u);  // the shapes moved: how they lie and cross, again
  EXPECT_EQ(lightEmission({0.5f, 0.0f}, amber, 0.01f, u, stats), vec3(gain));
  // Past the blend: the light's colour times the glow and the visible share.
  const vec2 p(0.0f, -0.7f);
  const float vis = lightVisibility(p, amber, 0.2f, u, stats);  // the preset's estimator
  const vec3 e = lightEmission(p, amber, 0.01f, u, stats);
  const vec3 want = u.color[amber] * attenuation(0.2f, u) * (gain * vis);
  EXPECT_NEAR(e.x, want.x, 1e-5f);
  EXPECT_NEAR(e.y, want.y, 1e-5f);
  EXPECT_GT(e.x, e.z);  // amber
}

TEST(LightBeamsScene, TheCameraLooksAtThePlaneZ0) {
  const FrameContext ctx = context(2.0);
  const BeamsUniforms u = make_beams_uniforms(ctx);
  // The default camera at (0, 0, 1) looking down -z: image right is +x, image up is +y.
  EXPECT_NEAR(ctx.camera.right.x, 1.0f, 1e-6f);
  EXPECT_NEAR(ctx.camera.up.y, 1.0f, 1e-6f);
  // A ray straight down from (x, y, 1) shows the 2D point (x, y).
  for (const vec2 p : {vec2(0.0f, 0.0f), vec2(-0.95f, 0.35f), vec2(0.3f, -0.2f)}) {
    RayStats a, b;
    const Ray ray{vec3(p.x, p.y, 1.0f), vec3(0.0f, 0.0f, -1.0f), 0.01f};
    EXPECT_EQ(sceneRadiance(ray, u, a), radianceAt(p, 0.01f, u, b));
  }
  // Looking away from the plane: the background.
  RayStats s;
  EXPECT_EQ(sceneRadiance(Ray{vec3(0.0f, 0.0f, 1.0f), vec3(0.0f, 0.0f, 1.0f), 0.01f}, u, s),
            u.background);
}

TEST(LightBeamsScene, TheOccluderIsDarkAndPresetsPickTheirEstimators) {
  FrameContext ctx = context(1.0);
  ctx.params.set("occluder_x", {0.25});
  ctx.params.set("occluder_y", {-0.1});
  const BeamsUniforms u = make_beams_uniforms(ctx);
  EXPECT_EQ(u.estimator, ESTIMATOR_PENUMBRA);
  RayStats s;
  // Inside the occluder every light is hidden: only the ground is left.
  EXPECT_EQ(radianceAt({0.25f, -0.1f}, 0.01f, u, s), u.background);
  EXPECT_EQ(make_beams_uniforms(context(1.0, Quality::Reference)).estimator, ESTIMATOR_EXACT);
  EXPECT_EQ(make_beams_uniforms(context(1.0, Quality::Draft)).estimator, ESTIMATOR_PENUMBRA);
  FrameContext naive = context(1.0);
  naive.march = naive_march_settings();
  EXPECT_EQ(make_beams_uniforms(naive).estimator, ESTIMATOR_SEED_RAY);
}

TEST(LightBeamsScene, BeamsSwayWithTime) {
  const BeamsUniforms a = make_beams_uniforms(context(0.0));
  const BeamsUniforms b = make_beams_uniforms(context(0.5));
  for (int k = 0; k < BEAM_COUNT; ++k) {
    const Shape& sa = a.shapes[FIRST_BEAM + k];
    EXPECT_EQ(sa.a.x, sa.b.x);  // vertical
    EXPECT_NE(sa.a.x, b.shapes[FIRST_BEAM + k].a.x) << k;
  }
}

// The packet-path (TIME 0, 3.7) and agreement (TIME 3) tests render the default scene: beams cross
// lights there, so both check the cut shared angles (crossings.h) too.
TEST(LightBeamsScene, BeamsCrossLightsInTheTestedFrames) {
  for (double time : {0.0, 3.0, 3.7}) {
    const BeamsUniforms u = make_beams_uniforms(context(time));
    EXPECT_GT(u.crossing_first[SHAPE_COUNT * SHAPE_COUNT], 0) << "TIME " << time;
  }
}

}  // namespace
}  // namespace sdfreel::light_beams
