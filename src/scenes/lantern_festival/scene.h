#pragma once
// The lantern_festival scene (seed 000): paper lanterns floating on a night lake.
#include <cstdint>
#include <memory>
#include <vector>

#include "scenes/lantern_festival/grid.h"
#include "scenes/lantern_festival/march.h"
#include "scenes/lantern_festival/shading.h"
#include "scenes/lantern_festival/sky.h"
#include "scenes/scene.h"

namespace sdfreel::lantern_festival {

std::vector<ParamSpec> lantern_festival_params();

// The generated textures of one seed.
struct LanternTextures {
  uint32_t seed = 0;
  Texture blue_noise, paper_normal, paper_noise, sky, sky_blurred;
};
std::unique_ptr<LanternTextures> make_lantern_textures(uint32_t seed);
// The same textures through the cache folder (scenes/common/texture_cache.h): read when a file of
// this seed, these sizes and this build is intact there, else made and stored.
std::unique_ptr<LanternTextures> cached_lantern_textures(uint32_t seed);
// The textures of `seed`, shared: loaded once and reused while the seed stays the same (every
// frame of a render, and scenes created one after another by the bench or the tests).
std::shared_ptr<const LanternTextures> lantern_textures(uint32_t seed);

// The 32-bit texture seed of a timeline seed.
inline uint32_t texture_seed(uint64_t seed) {
  return uint32_t(seed) ^ uint32_t(seed >> 32);
}

// A primary ray that sees the lake: where it meets it, the reflected direction, what the
// reflection hits and the lantern's normal there.
struct WaterBounce {
  glm::vec3 p{0.0f}, r{0.0f};
  CellHit hit;
  glm::vec3 n{0.0f};
};

class LanternFestivalScene : public Scene {
 public:
  void prepare(const FrameContext& ctx) override;
  glm::vec3 radiance(const Ray& ray, RayStats& stats) const override;
  // The marches and the bounce in lanes, for every preset (lantern_festival/lanes.cpp).
  void radiance_packet(const RayPacket& rays, glm::vec3* out, RayStats& stats) const override;
  // "sdfWater", "lanternDistance" and "repeated" (lantern_festival/distance_functions.cpp).
  std::vector<DistanceFunction> distance_functions() const override;
  // The lake's surface and the nearest lanterns.
  std::optional<float> solid_distance(const glm::vec3& p) const override;
  std::vector<ShaderUniform> shader_uniforms() const override;
  std::vector<ShaderTexture> shader_textures() const override;
  // The textures are generated from their seed alone.
  uint64_t shader_textures_key() const override { return textures_ ? textures_->seed + 1ull : 0; }

  // For tests and tools: the per-frame state prepare() built.
  const LanternField& field() const { return field_; }
  const SkyFrame& sky_frame() const { return sky_; }
  const LightFrame& light_frame() const { return light_; }
  const LanternTextures& textures() const { return *textures_; }

 private:
  CellHit marchLanterns(const glm::vec3& o, const glm::vec3& dir, float t_max,
                        const MarchLimits& lim, RayStats& stats) const;
  // The normal at a lantern hit of o + t dir; t_total: distance from the eye (the footprint).
  glm::vec3 lanternHitNormal(const glm::vec3& o, const glm::vec3& dir, const CellHit& hit,
                             float t_total, float pixel_angle) const;
  glm::vec3 shadeLanternHit(const glm::vec3& o, const glm::vec3& dir, const CellHit& hit,
                            const glm::vec3& n) const;
  // The phases of radiance(): the water bounce (normal, reflection march) and the shading.
  static bool seesWater(const MarchHit& water, const CellHit& lantern) {
    return water.hit && !lantern.hit;
  }
  WaterBounce bounceOffWater(const Ray& ray, float t, RayStats& stats) const;
  // sky_seen: what the ray meets when it hits nothing, the sky (primary rays) or the blurred sky
  // (the water's reflection): skySeen, or its lanes in radiance_packet.
  glm::vec3 shadeWater(const WaterBounce& b, const glm::vec3& sky_seen) const;
  glm::vec3 hitMask(const MarchHit& water, const CellHit& lantern) const;
  glm::vec3 skySeen(const Ray& ray, const MarchHit& water, const CellHit& lantern,
                    const WaterBounce& bounce) const;
  glm::vec3 shadeHits(const Ray& ray, const MarchHit& water, const CellHit& lantern,
                      const glm::vec3& lantern_normal, const WaterBounce& bounce,
                      const glm::vec3& sky_seen) const;
  glm::vec3 applyFog(const glm::vec3& col, float t) const;
  // Normal step at path length t: a pixel footprint, or (naive preset) a world-space constant.
  float normalEps(float t, float pixel_angle) const;
  MarchLimits limits(int max_steps, float pixel_angle, float t_offset) const;
  void marchPrimaryNaive(const Ray& ray, MarchHit& water, CellHit& lantern, RayStats& stats) const;

  std::shared_ptr<const LanternTextures> textures_;
  LanternField field_;
  SkyFrame sky_;
  LightFrame light_;
  MarchSettings march_{};
  bool reference_march_ = false;  // Quality::Reference: the seed's sphere tracing of repeated()
  glm::vec3 water_color_{0.0f};
  float reflection_strength_ = 0.0f;
  float fog_density_ = 0.0f;
};

}  // namespace sdfreel::lantern_festival
