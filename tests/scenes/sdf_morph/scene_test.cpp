// The sdf_morph scene through its Scene interface (tiny images rendered with a plain pixel loop)
// and its geometry and lighting functions directly.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "backends/cpu/cpu_backend.h"
#include "render/camera.h"
#include "render/frame_context.h"
#include "scenes/registry.h"
#include "scenes/scene_pixels.h"
#include "scenes/sdf_morph/geometry.h"
#include "scenes/sdf_morph/render.h"
#include "scenes/sdf_morph/uniforms.h"

namespace sdfreel {
namespace {

using glm::vec3;

constexpr int W = 32, H = 18;
constexpr double DEFAULT_PERIOD = 6.0;  // the morph_period default

const SceneInfo& info() {
  const SceneInfo* s = find_scene("sdf_morph");
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

bool all_finite_non_negative(const Image& img) {
  for (const vec3& c : img.px)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(c[k]) || c[k] < 0.0f) return false;
  return true;
}

float channel_distance(const vec3& a, const vec3& b) {
  const vec3 d = glm::abs(a - b);
  return d.x + d.y + d.z;
}

TEST(SdfMorphScene, RegisteredWithDocumentedParameters) {
  const SceneInfo& s = info();
  EXPECT_EQ(s.shader, "sdf_morph/sdf_morph.glsl");
  ASSERT_TRUE(s.make);
  for (const char* name : {"morph_period", "rotation_speed", "color", "reflectivity",
                           "key_light_intensity", "shadow_softness", "environment_intensity"}) {
    const ParamSpec* p = find_param(s.params, name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_FALSE(p->doc.empty()) << name;
    ASSERT_EQ(int(p->def.size()), p->components) << name;
    for (double v : p->def) {
      EXPECT_GE(v, p->min) << name;
      EXPECT_LE(v, p->max) << name;
    }
  }
  EXPECT_EQ(find_param(s.params, "morph_period")->def[0], DEFAULT_PERIOD);
}

TEST(SdfMorphScene, TinyImageIsFiniteAndNonNegative) {
  for (Quality q : {Quality::Draft, Quality::Final}) {
    const Image img = render(context(0.7, q));
    EXPECT_TRUE(all_finite_non_negative(img));
    EXPECT_GT(img.stats.sdf_evals, uint64_t(W * H));  // object pixels take many evaluations
    EXPECT_GT(img.stats.steps, 0u);
  }
}

TEST(SdfMorphScene, ObjectIsVisibleAgainstTheStudio) {
  const FrameContext ctx = context(0.5 * DEFAULT_PERIOD);  // the mug: no hole at the centre
  const Image img = render(ctx);
  // The centre looks at the object; a top corner at the bare studio wall.
  const vec3 centre = img.at(W / 2, H / 2 - 2), corner = img.at(1, 1);
  EXPECT_GT(channel_distance(centre, corner), 0.05f);
  // The corner is exactly the environment; the centre is not.
  const sdf_morph::MorphUniforms u = sdf_morph::make_morph_uniforms(ctx);
  const vec3 corner_dir = primary_ray_dir(ctx.camera, 1.5f, 1.5f, W, H);
  EXPECT_EQ(corner, sdf_morph::environment(corner_dir, u));
  const vec3 centre_dir = primary_ray_dir(ctx.camera, W / 2 + 0.5f, H / 2 - 1.5f, W, H);
  EXPECT_GT(channel_distance(centre, sdf_morph::environment(centre_dir, u)), 0.05f);
}

TEST(SdfMorphScene, MorphsBetweenTorusAndMugOverThePeriod) {
  EXPECT_EQ(sdf_morph::morph_weight(0.0, DEFAULT_PERIOD), 0.0f);
  EXPECT_EQ(sdf_morph::morph_weight(0.5 * DEFAULT_PERIOD, DEFAULT_PERIOD), 1.0f);
  EXPECT_EQ(sdf_morph::morph_weight(DEFAULT_PERIOD, DEFAULT_PERIOD), 0.0f);
  // Smooth and monotonic on the way there.
  float prev = 0.0f;
  for (int i = 1; i <= 300; ++i) {
    const float w = sdf_morph::morph_weight(0.5 * DEFAULT_PERIOD * i / 300.0, DEFAULT_PERIOD);
    ASSERT_GE(w, prev);
    ASSERT_LE(w - prev, 0.03f);
    prev = w;
  }
  // The picture changes: same rotation (speed 0), torus vs mug.
  FrameContext a = context(0.0), b = context(0.5 * DEFAULT_PERIOD);
  a.params.set("rotation_speed", {0.0});
  b.params.set("rotation_speed", {0.0});
  EXPECT_GT(mean_abs_difference(render(a), render(b)), 0.01);
}

TEST(SdfMorphScene, HugeTimeStillAnimatesSmoothly) {
  const double t = 1e6, dt = 1.0 / 30.0;
  const Image a = render(context(t)), b = render(context(t + dt));
  ASSERT_TRUE(all_finite_non_negative(a));
  ASSERT_TRUE(all_finite_non_negative(b));
  const double diff = mean_abs_difference(a, b);
  EXPECT_GT(diff, 0.0);   // it moved
  EXPECT_LT(diff, 0.02);  // by one frame's worth, not a jump
  // Phases are wrapped in double: the same step at TIME = 1e6 and at TIME = 0 (plus whole
  // periods) gives the same rotation and morph change.
  const sdf_morph::MorphUniforms u0 = sdf_morph::make_morph_uniforms(context(t));
  const sdf_morph::MorphUniforms u1 = sdf_morph::make_morph_uniforms(context(t + dt));
  const float turned = std::atan2(u0.rot_cos * u1.rot_sin - u0.rot_sin * u1.rot_cos,
                                  u0.rot_cos * u1.rot_cos + u0.rot_sin * u1.rot_sin);
  EXPECT_NEAR(turned, 0.35 * dt, 1e-5);  // rotation_speed default 0.35 rad/s
}

TEST(SdfMorphScene, OverRelaxationFindsTheSameSurfaces) {
  FrameContext relaxed = context(3.3, Quality::Final), plain = relaxed;
  relaxed.march.step_factor = 1.6f;  // aggressive: forces the step-back path often
  plain.march.step_factor = 1.0f;
  const Image a = render(relaxed), b = render(plain);
  int differ = 0;
  for (size_t i = 0; i < a.px.size(); ++i) differ += channel_distance(a.px[i], b.px[i]) > 0.02f;
  EXPECT_LE(differ, 2);  // at most a silhouette pixel or two flips
  EXPECT_LT(mean_abs_difference(a, b), 1e-3);
}

TEST(SdfMorphScene, DeterministicRenders) {
  const Image a = render(context(2.5)), b = render(context(2.5));
  for (size_t i = 0; i < a.px.size(); ++i) ASSERT_EQ(a.px[i], b.px[i]) << i;
  EXPECT_EQ(a.stats.sdf_evals, b.stats.sdf_evals);
}

TEST(SdfMorphScene, CpuBackendMatchesThePixelLoopWithAnyThreadCount) {
  FrameContext ctx = context(1.9);
  const Image loop = render(ctx);
  for (int threads : {1, 2}) {
    CpuBackend backend(threads, 5);  // small tiles: many tiles in flight at once
    backend.begin(info());
    RayStats stats;
    const ImageRGBA img = backend.render(ctx, stats);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const float* p = img.at(x, y);
        ASSERT_EQ(vec3(p[0], p[1], p[2]), loop.at(x, y))
            << threads << " threads, " << x << "," << y;
      }
    EXPECT_EQ(stats.sdf_evals, loop.stats.sdf_evals);
  }
}

TEST(SdfMorphScene, ParametersChangeWhatTheyShould) {
  const FrameContext base = context(0.5 * DEFAULT_PERIOD);
  const Image ref = render(base);
  const int cx = W / 2, cy = H / 2 - 2;
  {  // colour: the object changes, the studio wall does not
    FrameContext c = base;
    c.params.set("color", {0.1, 0.2, 0.9});
    const Image img = render(c);
    EXPECT_GT(channel_distance(img.at(cx, cy), ref.at(cx, cy)), 0.02f);
    EXPECT_EQ(img.at(1, 1), ref.at(1, 1));
  }
  {  // no environment and no key light: a black picture
    FrameContext c = base;
    c.params.set("environment_intensity", {0.0});
    c.params.set("key_light_intensity", {0.0});
    const Image img = render(c);
    for (const vec3& p : img.px) ASSERT_EQ(p, vec3(0.0f));
  }
  {  // a brighter key light brightens the lit pedestal front
    FrameContext c = base;
    c.params.set("key_light_intensity", {6.0});
    const Image img = render(c);
    const vec3 a = img.at(W / 2, H - 4), b = ref.at(W / 2, H - 4);
    EXPECT_GT(a.x + a.y + a.z, b.x + b.y + b.z);
  }
}

TEST(SdfMorphScene, HardCamerasStayFinite) {
  struct Pose {
    glm::dvec3 position, target;
  };
  const Pose poses[] = {
      {{0.0, 1.33, 0.0}, {0.0, 1.33, 2.0}},     // inside the torus' tube (top, on the axis)
      {{0.0, 0.2, 0.0}, {1.0, 0.2, 0.0}},       // inside the pedestal
      {{0.0, -1.0, -2.0}, {0.0, 0.5, 0.0}},     // below the floor
      {{0.0, 6.0, 0.0}, {0.0, 0.0, 0.0}},       // straight down
      {{0.0, 0.01, -3.0}, {0.0, 0.01, 100.0}},  // grazing the floor towards the horizon
      {{3e3, 40.0, -4e3}, {0.0, 0.5, 0.0}},     // very far away
  };
  for (const Pose& p : poses) {
    FrameContext ctx = context(1.3, Quality::Final);
    ctx.pose.position = p.position;
    ctx.pose.target = p.target;
    finish_frame_context(ctx);
    EXPECT_TRUE(all_finite_non_negative(render(ctx))) << p.position.x << " " << p.position.y;
  }
}

TEST(SdfMorphScene, HandsItsFrameConstantsToTheShader) {
  const FrameContext ctx = context(2.2, Quality::Final);
  std::unique_ptr<Scene> scene = info().make();
  scene->prepare(ctx);
  const std::vector<ShaderUniform> list = scene->shader_uniforms();
  const sdf_morph::MorphUniforms u = sdf_morph::make_morph_uniforms(ctx);
  std::map<std::string, std::vector<float>> by_name;
  for (const ShaderUniform& s : list) {
    EXPECT_EQ(s.name.rfind("u_morph.", 0), 0u) << s.name;
    EXPECT_EQ(int(s.values.size()), s.components) << s.name;
    EXPECT_TRUE(by_name.emplace(s.name, s.values).second) << "duplicate " << s.name;
  }
  EXPECT_EQ(by_name.size(), 18u + 6u * sdf_morph::SOFTBOX_COUNT);  // every field of the struct
  EXPECT_EQ(by_name.at("u_morph.morph"), std::vector<float>{u.morph});
  EXPECT_EQ(by_name.at("u_morph.rot_sin"), std::vector<float>{u.rot_sin});
  EXPECT_EQ(by_name.at("u_morph.max_steps"), std::vector<float>{float(ctx.march.max_steps)});
  EXPECT_EQ(by_name.at("u_morph.shadow_k"), std::vector<float>{u.shadow_k});
  const glm::vec3 d = u.boxes[2].dir;
  EXPECT_EQ(by_name.at("u_morph.boxes[2].dir"), (std::vector<float>{d.x, d.y, d.z}));
  EXPECT_EQ(by_name.at("u_morph.boxes[1].half_size").size(), 2u);
}

// ---- geometry ----

sdf_morph::MorphUniforms uniforms_at(float morph, float angle) {
  sdf_morph::MorphUniforms u = sdf_morph::make_morph_uniforms(context(0.0));
  u.morph = morph;
  u.rot_cos = dm::cos(angle);
  u.rot_sin = dm::sin(angle);
  return u;
}

TEST(SdfMorphGeometry, ObjectDistanceIsOneLipschitzAtEveryMorphStage) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> x(-0.9f, 0.9f), y(0.3f, 1.7f), step(-0.02f, 0.02f);
  for (float morph : {0.0f, 0.25f, 0.5f, 0.8f, 1.0f}) {
    const sdf_morph::MorphUniforms u = uniforms_at(morph, 0.7f);
    float worst = 0.0f;
    for (int i = 0; i < 40000; ++i) {
      const vec3 p(x(rng), y(rng), x(rng));
      const vec3 q = p + vec3(step(rng), step(rng), step(rng));
      if (glm::length(p - q) < 1e-3f) continue;  // rounding of f would dominate the ratio
      const float fp = sdf_morph::mapObject(p, u), fq = sdf_morph::mapObject(q, u);
      ASSERT_TRUE(std::isfinite(fp));
      worst = std::max(worst, std::abs(fp - fq) / glm::length(p - q));
    }
    EXPECT_LE(worst, 1.0f + 1e-3f) << "morph " << morph;
    EXPECT_GT(worst, 0.9f) << "morph " << morph;  // a distance, not a shrunken bound
  }
}

TEST(SdfMorphGeometry, BoundedSceneNeverOverestimates) {
  // The bounding spheres may only lower the distance (safe steps), never raise it.
  std::mt19937 rng(12);
  std::uniform_real_distribution<float> x(-3.0f, 3.0f), y(-0.5f, 3.0f);
  RayStats stats;
  for (float morph : {0.0f, 0.5f, 1.0f}) {
    const sdf_morph::MorphUniforms u = uniforms_at(morph, 2.0f);
    for (int i = 0; i < 40000; ++i) {
      const vec3 p(x(rng), y(rng), x(rng));
      const float exact = std::min(sdf_morph::mapObject(p, u), sdf_morph::mapPedestal(p));
      ASSERT_LE(sdf_morph::mapScene(p, u, stats), exact + 1e-6f);
    }
  }
  EXPECT_EQ(stats.sdf_evals, 3u * 40000u);
}

TEST(SdfMorphGeometry, ShapesSitInsideTheirBounds) {
  // Sample the surfaces (points with |d| small) and check they lie in the object's sphere and
  // rest on the pedestal top.
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> x(-1.0f, 1.0f), y(0.3f, 1.8f);
  for (float morph : {0.0f, 0.5f, 1.0f}) {
    const sdf_morph::MorphUniforms u = uniforms_at(morph, 1.1f);
    float lowest = 10.0f;
    int inside = 0;
    for (int i = 0; i < 200000; ++i) {
      const vec3 p(x(rng), y(rng), x(rng));
      if (sdf_morph::mapObject(p, u) > 0.0f) continue;
      ++inside;
      lowest = std::min(lowest, p.y);
      ASSERT_LT(glm::length(p - sdf_morph::objectBoundCenter()), sdf_morph::OBJECT_BOUND_RADIUS);
    }
    EXPECT_GT(inside, 1000) << morph;
    EXPECT_GE(lowest, sdf_morph::PEDESTAL_HEIGHT - 1e-4f) << morph;
    EXPECT_LT(lowest, sdf_morph::PEDESTAL_HEIGHT + 0.04f) << morph;  // it touches the top
  }
}

TEST(SdfMorphGeometry, MugIsHollowWithAHandleAndTorusHasAHole) {
  const vec3 cavity(0.0f, 0.5f, 0.0f),
      wall(sdf_morph::MUG_RADIUS - 0.5f * sdf_morph::MUG_WALL, 0.4f, 0.0f);
  const vec3 handle(sdf_morph::HANDLE_X + sdf_morph::HANDLE_RADIUS,
                    sdf_morph::MUG_HALF_HEIGHT + sdf_morph::HANDLE_Y, 0.0f);
  EXPECT_GT(sdf_morph::mapMug(cavity), 0.0f);  // empty inside
  EXPECT_LT(sdf_morph::mapMug(wall), 0.0f);
  EXPECT_LT(sdf_morph::mapMug(handle), 0.0f);
  EXPECT_LT(sdf_morph::mapMug(vec3(0.0f, 0.5f * sdf_morph::MUG_BOTTOM, 0.0f)), 0.0f);  // a floor
  EXPECT_GT(sdf_morph::mapMug(vec3(-handle.x, handle.y, 0.0f)), 0.0f);  // one handle only
  const vec3 hole(0.0f, sdf_morph::TORUS_CENTER_Y, 0.0f);
  EXPECT_NEAR(sdf_morph::mapTorus(hole), sdf_morph::TORUS_MAJOR - sdf_morph::TORUS_MINOR, 1e-6f);
}

TEST(SdfMorphLighting, SoftShadowDarkBehindLitInTheOpen) {
  const sdf_morph::MorphUniforms u = uniforms_at(0.0f, 0.0f);
  const vec3 key = u.boxes[0].dir;
  RayStats stats;
  // A floor point straight "behind" the torus' top as seen from the key light.
  const vec3 top(0.0f, sdf_morph::PEDESTAL_HEIGHT + 2.0f * sdf_morph::TORUS_CENTER_Y - 0.1f, 0.0f);
  const vec3 floor_point = top - key * (top.y / key.y);
  EXPECT_LT(sdf_morph::softShadow(floor_point + vec3(0.0f, 0.002f, 0.0f), key, u, stats), 0.05f);
  // Far out on the floor nothing is in the way, and the march is skipped altogether.
  const uint64_t evals = stats.sdf_evals;
  EXPECT_EQ(sdf_morph::softShadow(vec3(8.0f, 0.002f, 8.0f), key, u, stats), 1.0f);
  EXPECT_EQ(stats.sdf_evals, evals);
  // Around the shadow, a smaller k gives a wider penumbra: more partially lit floor points.
  sdf_morph::MorphUniforms soft = u;
  soft.shadow_k = 2.0f;
  int partial_soft = 0, partial_hard = 0;
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) {
      const vec3 p(-2.5f + 0.075f * i, 0.002f, -0.5f + 0.075f * j);
      const float s_soft = sdf_morph::softShadow(p, key, soft, stats);
      const float s_hard = sdf_morph::softShadow(p, key, u, stats);
      ASSERT_TRUE(s_soft >= 0.0f && s_soft <= 1.0f);
      partial_soft += s_soft > 0.05f && s_soft < 0.95f;
      partial_hard += s_hard > 0.05f && s_hard < 0.95f;
    }
  EXPECT_GT(partial_hard, 0);
  EXPECT_GT(partial_soft, partial_hard);
}

TEST(SdfMorphLighting, NormalsAreUnitAndPointOutOfTheObject) {
  const sdf_morph::MorphUniforms u = uniforms_at(1.0f, 0.0f);
  RayStats stats;
  // The mug's side facing -z (towards the default camera) at mid height.
  const vec3 p(0.0f, sdf_morph::PEDESTAL_HEIGHT + sdf_morph::MUG_HALF_HEIGHT,
               -sdf_morph::MUG_RADIUS);
  const vec3 n = sdf_morph::calcNormal(p, 1e-3f, u, stats);
  EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
  EXPECT_LT(n.z, -0.99f);
  EXPECT_EQ(stats.sdf_evals, 4u);  // the tetrahedron: four taps
}

TEST(SdfMorphLighting, EnvironmentShowsSoftBoxesAndScales) {
  const sdf_morph::MorphUniforms u = uniforms_at(0.0f, 0.0f);
  const vec3 key = sdf_morph::environment(u.boxes[0].dir, u);
  const vec3 wall = sdf_morph::environment(vec3(0.0f, 0.1f, 1.0f) / std::sqrt(1.01f), u);
  EXPECT_GT(key.x, 10.0f * wall.x);  // the soft box is far brighter than the wall
  sdf_morph::MorphUniforms dim = u;
  dim.env_intensity = 0.5f;
  const vec3 half = sdf_morph::environment(u.boxes[0].dir, dim);
  EXPECT_NEAR(half.x, 0.5f * key.x, 1e-5f * key.x);
  // Every direction, including straight up and down, is finite and non-negative.
  for (int i = 0; i < 2000; ++i) {
    const float a = 0.01f * i, b = 0.0031f * i - 3.1f;
    const vec3 d(std::cos(b) * std::cos(a), std::sin(b), std::cos(b) * std::sin(a));
    const vec3 c = sdf_morph::environment(d, u);
    ASSERT_TRUE(std::isfinite(c.x + c.y + c.z));
    ASSERT_GE(std::min(c.x, std::min(c.y, c.z)), 0.0f);
  }
}

}  // namespace
}  // namespace sdfreel
