// The lantern_festival scene as a whole: registered with every parameter the issue names, renders
// finite night-blue sky and warm lanterns, survives hard cases, caches its textures per seed and
// hands the OSMesa twin its uniforms and textures.
#include "scenes/lantern_festival/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "backends/cpu/cpu_backend.h"
#include "scenes/registry.h"

namespace sdfreel::lantern_festival {
namespace {

const SceneInfo& info() {
  const SceneInfo* s = find_scene("lantern_festival");
  if (!s) throw std::runtime_error("lantern_festival is not registered");
  return *s;
}

FrameContext context(int w, int h, double time, const CameraPose& pose, uint64_t seed = 1) {
  FrameContext ctx;
  ctx.width = w;
  ctx.height = h;
  ctx.scene_time = time;
  ctx.video_time = time;
  ctx.seed = seed;
  ctx.quality = Quality::Draft;
  ctx.pose = pose;
  ctx.params = ParamValues(&info().params);
  finish_frame_context(ctx);
  return ctx;
}

TEST(LanternFestivalScene, ListsEveryParameter) {
  const char* required[] = {"wave_amplitude",
                            "wave_speed",
                            "flicker_strength",
                            "flicker_speed",
                            "grid_size",
                            "lantern_scale",
                            "candle_intensity",
                            "candle_color",
                            "moon_intensity",
                            "moon_elevation",
                            "moon_azimuth",
                            "water_color",
                            "water_reflection_strength",
                            "fog_color",
                            "fog_density",
                            "sky_intensity"};
  for (const char* name : required) {
    const ParamSpec* p = find_param(info().params, name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_FALSE(p->doc.empty()) << name;
    for (double v : p->def) {
      EXPECT_GE(v, p->min) << name;
      EXPECT_LE(v, p->max) << name;
    }
  }
  EXPECT_EQ(info().shader, "lantern_festival/lantern_festival.glsl");
}

struct Rendered {
  ImageRGBA img;
  RayStats stats;
};

Rendered render(const FrameContext& ctx) {
  CpuBackend cpu(2);
  cpu.begin(info());
  Rendered r;
  r.img = cpu.render(ctx, r.stats);
  return r;
}

TEST(LanternFestivalScene, NightSkyAboveWarmLanterns) {
  const Rendered r = render(context(96, 54, 3.0, info().default_camera));
  int warm = 0;
  for (float v : r.img.pixels) ASSERT_TRUE(std::isfinite(v));
  for (int y = 0; y < r.img.height; ++y)
    for (int x = 0; x < r.img.width; ++x) {
      const float* p = r.img.at(x, y);
      if (p[0] > 0.2f && p[0] > 2.0f * p[2]) ++warm;
    }
  // The top rows are night sky: dark, blue over red (stars and the moon aside).
  int blue = 0;
  for (int x = 0; x < r.img.width; ++x) {
    const float* p = r.img.at(x, 2);
    blue += p[2] > p[0] && p[2] < 0.5f;
  }
  EXPECT_GT(blue, r.img.width * 8 / 10);
  EXPECT_GT(warm, 20);  // glowing lanterns
  EXPECT_GT(r.stats.sdf_evals, 0u);
}

TEST(LanternFestivalScene, HardCasesStayFinite) {
  const CameraPose poses[] = {
      {{0.0, 0.2, 0.0}, {0.0, 5.0, 0.01}, 60.0, 0.0},          // straight up, on a lantern axis
      {{0.0, -3.0, 0.0}, {10.0, -3.0, 10.0}, 60.0, 0.0},       // under the lake
      {{1e4, 0.5, -1e4}, {1e4 + 10.0, 0.0, -1e4}, 50.0, 0.0},  // far from the origin
      {{3.0, 0.4, -10.0}, {3.0, 0.40001, 200.0}, 10.0, 0.0},   // grazing the horizon
  };
  for (const CameraPose& pose : poses)
    for (double time : {0.0, 1e6}) {
      const Rendered r = render(context(24, 16, time, pose));
      for (float v : r.img.pixels) ASSERT_TRUE(std::isfinite(v)) << "time " << time;
    }
}

TEST(LanternFestivalScene, ParameterExtremesStayFinite) {
  for (int corner = 0; corner < 2; ++corner) {
    FrameContext ctx = context(32, 18, 2.5, info().default_camera);
    for (const ParamSpec& p : info().params)
      ctx.params.set(p.name, std::vector<double>(size_t(p.components), corner ? p.max : p.min));
    const Rendered r = render(ctx);
    for (float v : r.img.pixels) ASSERT_TRUE(std::isfinite(v)) << (corner ? "max" : "min");
  }
}

TEST(LanternFestivalScene, PaperOnTheLanternAxisHasNoNaN) {
  LanternFestivalScene scene;
  scene.prepare(context(8, 8, 1.0, info().default_camera));
  const LanternCell cell = scene.field().cell(glm::vec2(0.0f));
  LanternHit h;
  h.local = glm::vec3(0.0f, -1.0f, 0.0f);  // the paper's bottom, on the axis
  h.cell = cell;
  h.p = cell.center + toWorld(cell, h.local);
  h.n = glm::vec3(0.0f, 1.0f, 0.0f);
  h.view = glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::vec3 c = shadePaper(scene.light_frame(), scene.field().grid, h);
  EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
  EXPECT_GT(c.x, 0.0f);
  const glm::vec2 uv = calcCylindricalUVs(radialDirection(h.local), h.local);
  EXPECT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y));
}

TEST(LanternFestivalScene, TexturesAreMadeOncePerSeed) {
  LanternFestivalScene scene;
  scene.prepare(context(8, 8, 0.0, info().default_camera, 5));
  const LanternTextures* first = &scene.textures();
  const std::vector<float> sky = first->sky.texels;
  scene.prepare(context(8, 8, 1.0, info().default_camera, 5));
  EXPECT_EQ(&scene.textures(), first);  // not regenerated for the next frame
  scene.prepare(context(8, 8, 1.0, info().default_camera, 6));
  EXPECT_NE(scene.textures().sky.texels, sky);  // another seed, another sky

  LanternFestivalScene again;
  again.prepare(context(8, 8, 0.0, info().default_camera, 5));
  EXPECT_EQ(again.textures().sky.texels, sky);
  EXPECT_EQ(again.textures().blue_noise.texels, first->blue_noise.texels);
}

TEST(LanternFestivalScene, LanternsDoNotFlickerInUnison) {
  LanternFestivalScene scene;
  scene.prepare(context(8, 8, 2.0, info().default_camera));
  std::set<float> strengths;
  for (int i = 0; i < 8; ++i)
    strengths.insert(candleStrength(scene.light_frame(), scene.field().cell(glm::vec2(i, 0))));
  EXPECT_GE(strengths.size(), 7u);

  // flicker_strength 0 holds every candle steady at the seed's mid value.
  FrameContext ctx = context(8, 8, 2.0, info().default_camera);
  ctx.params.set("flicker_strength", {0.0});
  scene.prepare(ctx);
  for (int i = 0; i < 8; ++i)
    EXPECT_FLOAT_EQ(candleStrength(scene.light_frame(), scene.field().cell(glm::vec2(i, 0))),
                    0.55f);
}

TEST(LanternFestivalScene, FlickerFollowsTheSeedsCosines) {
  // (cos(2 pi T) + 2) 0.15 + (cos(3 pi T) + 1) 0.1 + (cos(2.5 pi T) + 1) 0.1
  for (float t : {0.0f, 0.3f, 1.0f, 2.7f}) {
    const double ref = (std::cos(t * 2.0 * M_PI) + 2.0) * 0.15 +
                       (std::cos(t * 3.0 * M_PI) + 1.0) * 0.1 +
                       (std::cos(t * 2.5 * M_PI) + 1.0) * 0.1;
    EXPECT_NEAR(flickerValue(t), ref, 2e-6);
  }
  EXPECT_NEAR(flickerValue(0.0f), 0.85f, 1e-6f);
  // Period 4 (FLICKER_PERIOD): the per-lantern phase offsets wrap cleanly.
  EXPECT_NEAR(flickerValue(0.7f), flickerValue(4.7f), 2e-6f);
  // Its three cosines run in lanes: the bits of the scalar sum, over the clock's range and past it.
  for (float t = -1.0f; t < 9.0f; t += 0.000731f) {
    const float scalar = (dm::cos(t * 2.0f * dm::PI) + 2.0f) * 0.15f +
                         (dm::cos(t * 3.0f * dm::PI) + 1.0f) * 0.1f +
                         (dm::cos(t * 2.5f * dm::PI) + 1.0f) * 0.1f;
    ASSERT_EQ(flickerValue(t), scalar) << "t " << t;
  }
}

TEST(LanternFestivalScene, ShaderInterface) {
  LanternFestivalScene scene;
  scene.prepare(context(8, 8, 3.0, info().default_camera));
  std::set<std::string> names;
  for (const ShaderUniform& u : scene.shader_uniforms()) {
    EXPECT_TRUE(names.insert(u.name).second) << "duplicate " << u.name;
    ASSERT_GE(u.components, 1);
    ASSERT_LE(u.components, 4);
    ASSERT_FALSE(u.values.empty()) << u.name;
    EXPECT_EQ(u.values.size() % size_t(u.components), 0u) << u.name;
    for (float v : u.values) EXPECT_TRUE(std::isfinite(v)) << u.name;
  }
  for (const char* n : {"u_lake.phase", "u_lake.rough_phase", "u_grid.size", "u_light.flicker_time",
                        "u_sky.moon_dir", "u_light.candle_color", "u_water.reflection_strength"})
    EXPECT_EQ(names.count(n), 1u) << n;
  const std::vector<ShaderTexture> tex = scene.shader_textures();
  ASSERT_EQ(tex.size(), 5u);
  for (const ShaderTexture& t : tex)
    EXPECT_EQ(t.texels.size(), size_t(t.width) * t.height * t.channels) << t.name;
}

}  // namespace
}  // namespace sdfreel::lantern_festival
