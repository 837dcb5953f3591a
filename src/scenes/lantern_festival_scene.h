#pragma once
// The lantern_festival scene (seed 000): paper lanterns floating on a night lake.
#include <cstdint>
#include <memory>
#include <vector>

#include "scenes/lantern_festival_grid.h"
#include "scenes/lantern_festival_march.h"
#include "scenes/lantern_festival_shading.h"
#include "scenes/lantern_festival_sky.h"
#include "scenes/scene.h"

namespace sdfreel::lantern {

std::vector<ParamSpec> lantern_festival_params();

// The generated textures of one seed.
struct LanternTextures {
  uint32_t seed = 0;
  Texture blue_noise, paper_normal, paper_noise, sky, sky_blurred;
};
std::unique_ptr<LanternTextures> make_lantern_textures(uint32_t seed);
// The textures of `seed`, shared: made once and reused while the seed stays the same (every
// frame of a render, and scenes created one after another by the bench or the tests).
std::shared_ptr<const LanternTextures> lantern_textures(uint32_t seed);

// The 32-bit texture seed of a timeline seed.
inline uint32_t texture_seed(uint64_t seed) {
  return uint32_t(seed) ^ uint32_t(seed >> 32);
}

class LanternFestivalScene : public Scene {
 public:
  void prepare(const FrameContext& ctx) override;
  glm::vec3 radiance(const Ray& ray, RayStats& stats) const override;
  std::vector<ShaderUniform> shader_uniforms() const override;
  std::vector<ShaderTexture> shader_textures() const override;

  // For tests and tools: the per-frame state prepare() built.
  const LanternField& field() const { return field_; }
  const SkyFrame& sky_frame() const { return sky_; }
  const LightFrame& light_frame() const { return light_; }
  const LanternTextures& textures() const { return *textures_; }

 private:
  CellHit marchLanterns(const glm::vec3& o, const glm::vec3& dir, float t_max,
                        const MarchLimits& lim, RayStats& stats) const;
  glm::vec3 shadeLanternHit(const glm::vec3& o, const glm::vec3& dir, const CellHit& hit,
                            float t_total, float pixel_angle) const;
  glm::vec3 shadeWater(const glm::vec3& p, const glm::vec3& dir, float t, float pixel_angle,
                       RayStats& stats) const;
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

}  // namespace sdfreel::lantern
