// What the GLSL twin (shaders/lantern_festival/lantern_festival.glsl) reads besides the frame
// uniforms (u_march, u_time, p_<param>, the camera): the per-frame structs prepare() filled, field
// for field, as u_lake.*, u_grid.*, u_light.*, u_sky.* and u_water.*, and the generated textures.
#include "scenes/common/uniform_list.h"
#include "scenes/lantern_festival/scene.h"

namespace sdfreel::lantern_festival {

namespace {

ShaderTexture shader_texture(const char* name, const Texture& t) {
  return {name, t.width, t.height, t.channels, t.texels};
}

}  // namespace

std::vector<ShaderUniform> LanternFestivalScene::shader_uniforms() const {
  std::vector<ShaderUniform> all;
  const LakeFrame& k = field_.lake;
  std::vector<float> dirs, amps, freqs, phases;
  for (int i = 0; i < WAVE_COUNT; ++i) {
    dirs.push_back(k.dir[i].x);
    dirs.push_back(k.dir[i].y);
    amps.push_back(k.amp[i]);
    freqs.push_back(k.freq[i]);
    phases.push_back(k.phase[i]);
  }
  UniformList("u_lake")
      .add("dir", 2, dirs)
      .add("amp", 1, amps)
      .add("freq", 1, freqs)
      .add("phase", 1, phases)
      .v2("rough_dir", k.rough_dir)
      .f("rough_amp", k.rough_amp)
      .f("rough_freq", k.rough_freq)
      .f("rough_phase", k.rough_phase)
      .f("lipschitz", k.lipschitz)
      .f("max_height", k.max_height)
      .f("step_scale", k.step_scale)
      .append_to(all);

  const GridFrame& g = field_.grid;
  UniformList("u_grid")
      .f("size", g.size)
      .f("max_offset", g.max_offset)
      .f("scale", g.scale)
      .f("inv_scale", g.inv_scale)
      .f("bound_radius", g.bound_radius)
      .f("bound_half_height", g.bound_half_height)
      .f("early_out", g.early_out)
      .f("extent", g.extent)
      .f("slab_lo", g.slab_lo)
      .f("slab_hi", g.slab_hi)
      .append_to(all);

  UniformList("u_light")
      .v3("moon_dir", light_.moon_dir)
      .v3("moon_light", light_.moon_light)
      .v3("ambient", light_.ambient)
      .v3("candle_color", light_.candle_color)
      .v3("candle_local", light_.candle_local)
      .f("flicker_time", light_.flicker_time)
      .f("flicker_strength", light_.flicker_strength)
      .v3("paper_albedo", light_.paper_albedo)
      .v3("metal_albedo", light_.metal_albedo)
      .v3("wood_albedo", light_.wood_albedo)
      .append_to(all);

  UniformList("u_sky")
      .f("intensity", sky_.intensity)
      .v3("moon_dir", sky_.moon_dir)
      .v3("moon_right", sky_.moon_right)
      .v3("moon_up", sky_.moon_up)
      .v3("moon_disc", sky_.moon_disc)
      .v3("moon_glow", sky_.moon_glow)
      .f("moon_cos_inner", sky_.moon_cos_inner)
      .f("moon_cos_outer", sky_.moon_cos_outer)
      .v3("fog_color", sky_.fog_color)
      .f("horizon_fog", sky_.horizon_fog)
      .append_to(all);

  UniformList("u_water")
      .v3("color", water_color_)
      .f("reflection_strength", reflection_strength_)
      .f("fog_density", fog_density_)
      .flag("reference_march", reference_march_)
      .flag("naive", march_.naive)
      .flag("hit_mask", march_.hit_mask)
      .f("surface", float(march_.surface))
      .append_to(all);
  return all;
}

std::vector<ShaderTexture> LanternFestivalScene::shader_textures() const {
  if (!textures_) return {};
  return {shader_texture("u_blue_noise", textures_->blue_noise),
          shader_texture("u_paper_normal", textures_->paper_normal),
          shader_texture("u_paper_noise", textures_->paper_noise),
          shader_texture("u_sky_env", textures_->sky),
          shader_texture("u_sky_env_blurred", textures_->sky_blurred)};
}

}  // namespace sdfreel::lantern_festival
