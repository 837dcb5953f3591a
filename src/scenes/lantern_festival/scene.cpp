// The lantern_festival scene: per-frame preparation and the per-ray pipeline (lake, lanterns,
// reflections, sky).
#include "scenes/lantern_festival/scene.h"

#include <cstdio>
#include <mutex>

#include "scenes/common/surface_output.h"
#include "scenes/common/texture_cache.h"
#include "scenes/lantern_festival/generated_textures.h"

namespace sdfreel::lantern_festival {

namespace {

// The candle stands low in the lantern (lantern frame; the paper spans y = -1 .. 1).
const glm::vec3 CANDLE_LOCAL(0.0f, -0.45f, 0.0f);
const glm::vec3 METAL_ALBEDO(0.30f, 0.24f, 0.16f);
const glm::vec3 WOOD_ALBEDO(0.32f, 0.17f, 0.07f);
// Sky fill light on every surface, per unit of sky_intensity.
const glm::vec3 SKY_AMBIENT(0.012f, 0.018f, 0.035f);
// Cells of the per-frame table: every cell a primary or reflected ray can reach (two max_dist).
constexpr int CELL_TABLE_MAX_RADIUS = 160;

// MarchSettings::hit_mask output: which marched surface the primary ray hit.
constexpr float HIT_ID_NONE = 0.0f;
constexpr float HIT_ID_LANTERN = 1.0f;
constexpr float HIT_ID_WATER = 2.0f;

float param(const FrameContext& ctx, const char* name) {
  return float(ctx.params.scalar(name));
}

}  // namespace

std::unique_ptr<LanternTextures> make_lantern_textures(uint32_t seed) {
  auto t = std::make_unique<LanternTextures>();
  t->seed = seed;
  t->blue_noise = make_blue_noise(BLUE_NOISE_SIZE, 4, seed);
  t->paper_normal = make_paper_normal_map(PAPER_MAP_SIZE, seed + 1u);
  t->paper_noise = make_paper_noise_map(PAPER_MAP_SIZE, seed + 2u);
  t->sky = make_sky_environment(SKY_WIDTH, SKY_HEIGHT, seed + 3u);
  t->sky_blurred = downsample(t->sky, SKY_REFLECTION_DOWNSAMPLE);
  return t;
}

std::unique_ptr<LanternTextures> cached_lantern_textures(uint32_t seed) {
  char key[160];
  std::snprintf(key, sizeof key,
                "lantern_festival textures: seed=%u blue_noise=%dx4 paper=%d sky=%dx%d/%d", seed,
                BLUE_NOISE_SIZE, PAPER_MAP_SIZE, SKY_WIDTH, SKY_HEIGHT, SKY_REFLECTION_DOWNSAMPLE);
  std::vector<Texture> list = cached_textures(key, [seed] {
    std::unique_ptr<LanternTextures> t = make_lantern_textures(seed);
    return std::vector<Texture>{std::move(t->blue_noise), std::move(t->paper_normal),
                                std::move(t->paper_noise), std::move(t->sky),
                                std::move(t->sky_blurred)};
  });
  auto t = std::make_unique<LanternTextures>();
  t->seed = seed;
  t->blue_noise = std::move(list.at(0));
  t->paper_normal = std::move(list.at(1));
  t->paper_noise = std::move(list.at(2));
  t->sky = std::move(list.at(3));
  t->sky_blurred = std::move(list.at(4));
  return t;
}

std::shared_ptr<const LanternTextures> lantern_textures(uint32_t seed) {
  static std::mutex mutex;
  static std::shared_ptr<const LanternTextures> last;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!last || last->seed != seed) last = cached_lantern_textures(seed);
  return last;
}

void LanternFestivalScene::prepare(const FrameContext& ctx) {
  const uint32_t seed = texture_seed(ctx.seed);
  if (!textures_ || textures_->seed != seed) textures_ = lantern_textures(seed);
  march_ = ctx.march;
  reference_march_ = ctx.quality == Quality::Reference;

  field_.lake =
      make_lake_frame(ctx.scene_time, param(ctx, "wave_amplitude"), param(ctx, "wave_speed"));
  field_.grid = make_grid_frame(field_.lake, param(ctx, "grid_size"), param(ctx, "lantern_jitter"),
                                param(ctx, "lantern_scale"), textures_->blue_noise);
  const glm::vec2 eye(ctx.camera.origin.x, ctx.camera.origin.z);
  const float reach = 2.0f * march_.max_dist / field_.grid.size + 2.0f;
  const int radius = int(dm::min(dm::floor(reach) + 1.0f, float(CELL_TABLE_MAX_RADIUS)));
  field_.table.build(field_.grid, field_.lake, cellId(field_.grid, eye), radius);

  const glm::vec3 moon_dir =
      direction_from_angles(ctx.params.scalar("moon_elevation"), ctx.params.scalar("moon_azimuth"));
  const glm::vec3 moon_light = ctx.params.vec3("moon_color") * param(ctx, "moon_intensity");
  const float sky_intensity = param(ctx, "sky_intensity");
  sky_ = make_sky_frame(textures_->sky, textures_->sky_blurred, sky_intensity, moon_dir, moon_light,
                        ctx.params.vec3("fog_color"), param(ctx, "horizon_fog"),
                        textures_->paper_noise);

  light_.moon_dir = sky_.moon_dir;
  light_.moon_light = moon_light;
  light_.ambient = SKY_AMBIENT * sky_intensity;
  light_.candle_color = ctx.params.vec3("candle_color") * param(ctx, "candle_intensity");
  light_.candle_local = CANDLE_LOCAL;
  light_.flicker_time =
      dm::wrap_phase(ctx.scene_time * ctx.params.scalar("flicker_speed"), double(FLICKER_PERIOD));
  light_.flicker_strength = param(ctx, "flicker_strength");
  light_.paper_albedo = ctx.params.vec3("paper_color");
  light_.metal_albedo = METAL_ALBEDO;
  light_.wood_albedo = WOOD_ALBEDO;
  light_.paper_normal = &textures_->paper_normal;
  light_.paper_noise = &textures_->paper_noise;

  water_color_ = ctx.params.vec3("water_color");
  reflection_strength_ = param(ctx, "water_reflection_strength");
  fog_density_ = param(ctx, "fog_density");
}

glm::vec3 LanternFestivalScene::applyFog(const glm::vec3& col, float t) const {
  return dm::mix(col, sky_.fog_color, 1.0f - dm::exp(-fog_density_ * t));
}

float LanternFestivalScene::normalEps(float t, float pixel_angle) const {
  if (march_.naive) return march_.normal_eps;  // world units
  return dm::max(march_.normal_eps * t * pixel_angle, 1e-4f);
}

MarchLimits LanternFestivalScene::limits(int max_steps, float pixel_angle, float t_offset) const {
  MarchLimits lim{max_steps, march_.hit_eps, march_.step_factor, pixel_angle, t_offset};
  lim.naive = march_.naive;
  return lim;
}

CellHit LanternFestivalScene::marchLanterns(const glm::vec3& o, const glm::vec3& dir, float t_max,
                                            const MarchLimits& lim, RayStats& stats) const {
  if (march_.naive) {
    const NaiveHit h = marchNaive(field_, o, dir, t_max, false, lim, stats);
    return {h.hit, h.t, h.cell};
  }
  if (!reference_march_) return marchCells(field_, o, dir, 0.0f, t_max, lim, stats);
  // The seed's way: sphere tracing of repeated(), then the lantern nearest to the hit.
  const MarchHit h = march(field_, o, dir, 0.0f, t_max, lim, stats);
  if (!h.hit) return {};
  return {true, h.t, nearestLantern(field_, o + dir * h.t).cell};
}

// t_total: distance from the eye (sets the normal's footprint).
glm::vec3 LanternFestivalScene::lanternHitNormal(const glm::vec3& o, const glm::vec3& dir,
                                                 const CellHit& hit, float t_total,
                                                 float pixel_angle) const {
  return lanternNormal(field_.grid, hit.cell, o + dir * hit.t, normalEps(t_total, pixel_angle));
}

glm::vec3 LanternFestivalScene::shadeLanternHit(const glm::vec3& o, const glm::vec3& dir,
                                                const CellHit& hit, const glm::vec3& n) const {
  const glm::vec3 p = o + dir * hit.t;
  LanternHit h;
  h.p = p;
  h.n = n;
  h.view = -dir;
  h.local = toLocal(hit.cell, p - hit.cell.center) * field_.grid.inv_scale;
  h.cell = hit.cell;
  return shadeLantern(light_, field_.grid, h);
}

WaterBounce LanternFestivalScene::bounceOffWater(const Ray& ray, float t, RayStats& stats) const {
  WaterBounce b;
  b.p = ray.origin + ray.dir * t;
  const float eps = normalEps(t, ray.pixel_angle);
  const glm::vec3 normal = waterNormal(field_.lake, b.p, eps);
  b.r = ray.dir - normal * (2.0f * glm::dot(normal, ray.dir));  // reflect(dir, normal)
  const MarchLimits lim = limits(march_.reflect_steps, ray.pixel_angle, t);
  b.hit = marchLanterns(b.p, b.r, march_.max_dist, lim, stats);
  if (b.hit.hit) b.n = lanternHitNormal(b.p, b.r, b.hit, t + b.hit.t, ray.pixel_angle);
  return b;
}

glm::vec3 LanternFestivalScene::shadeWater(const WaterBounce& b, const glm::vec3& sky_seen) const {
  const glm::vec3 reflected = b.hit.hit ? shadeLanternHit(b.p, b.r, b.hit, b.n) : sky_seen;
  return reflected * reflection_strength_ + water_color_;
}

// The naive preset: one plain sphere trace of lanterns and lake together.
void LanternFestivalScene::marchPrimaryNaive(const Ray& ray, MarchHit& water, CellHit& lantern,
                                             RayStats& stats) const {
  const MarchLimits lim = limits(march_.max_steps, ray.pixel_angle, 0.0f);
  const NaiveHit h = marchNaive(field_, ray.origin, ray.dir, march_.max_dist, true, lim, stats);
  water = MarchHit{h.hit && h.water, h.t};
  lantern = CellHit{h.hit && !h.water, h.t, h.cell};
}

// The phases (march, water bounce, shading) are shared with radiance_packet, which runs the first
// two in lanes (lantern_festival/lanes.cpp).
glm::vec3 LanternFestivalScene::radiance(const Ray& ray, RayStats& stats) const {
  MarchHit water;
  CellHit lantern;
  if (march_.naive) {
    marchPrimaryNaive(ray, water, lantern, stats);
  } else {
    const MarchLimits lim = limits(march_.max_steps, ray.pixel_angle, 0.0f);
    water = marchWater(field_.lake, ray.origin, ray.dir, march_.max_dist, lim, stats);
    const float t_far = water.hit ? water.t : march_.max_dist;
    lantern = marchLanterns(ray.origin, ray.dir, t_far, lim, stats);
  }
  if (march_.hit_mask) return hitMask(water, lantern);
  if (march_.surface != SURFACE_COLOUR) {  // the depth and normal passes
    if (lantern.hit)
      return surfaceOutput(
          march_.surface, lantern.t,
          lanternHitNormal(ray.origin, ray.dir, lantern, lantern.t, ray.pixel_angle));
    if (water.hit)
      return surfaceOutput(march_.surface, water.t,
                           waterNormal(field_.lake, ray.origin + ray.dir * water.t,
                                       normalEps(water.t, ray.pixel_angle)));
    return noSurface(march_.surface);
  }
  const glm::vec3 normal =
      lantern.hit ? lanternHitNormal(ray.origin, ray.dir, lantern, lantern.t, ray.pixel_angle)
                  : glm::vec3(0.0f);
  WaterBounce bounce;
  if (seesWater(water, lantern)) bounce = bounceOffWater(ray, water.t, stats);
  return shadeHits(ray, water, lantern, normal, bounce, skySeen(ray, water, lantern, bounce));
}

glm::vec3 LanternFestivalScene::hitMask(const MarchHit& water, const CellHit& lantern) const {
  return glm::vec3(lantern.hit ? HIT_ID_LANTERN : water.hit ? HIT_ID_WATER : HIT_ID_NONE);
}

glm::vec3 LanternFestivalScene::skySeen(const Ray& ray, const MarchHit& water,
                                        const CellHit& lantern, const WaterBounce& bounce) const {
  if (lantern.hit) return glm::vec3(0.0f);
  if (water.hit) return bounce.hit.hit ? glm::vec3(0.0f) : skyReflected(sky_, bounce.r);
  return sky(sky_, ray.dir);
}

glm::vec3 LanternFestivalScene::shadeHits(const Ray& ray, const MarchHit& water,
                                          const CellHit& lantern, const glm::vec3& lantern_normal,
                                          const WaterBounce& bounce,
                                          const glm::vec3& sky_seen) const {
  if (lantern.hit)
    return applyFog(shadeLanternHit(ray.origin, ray.dir, lantern, lantern_normal), lantern.t);
  if (water.hit) return applyFog(shadeWater(bounce, sky_seen), water.t);
  return sky_seen;
}

}  // namespace sdfreel::lantern_festival
