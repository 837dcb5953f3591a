// Scene "water_lily" (seed 001): a Monet-inspired pond. Water lilies made of layers of reshaped
// spheres and notched lily pads float on water whose normal is bumped by time-dependent 3D FBM,
// calmer far away; the water mirrors the lilies and the FBM-lit sky through a Fresnel term. Soft
// shadows (Quilez's improved form) from the sun and the sky's fill light, contrast, saturation,
// vignette and distance fog as in the seed. Beyond the seed: coloured centres, translucent petals,
// curled pad rims, submerged pads and water drops.
//
// Parameters (`sdfreel scenes water_lily`):
//   curl_amount         petal curl rate; each flower swings around it with its own phase
//   leaf_drift          metres the drifting pad travels in x (and 0.6 of it in z)
//   water_speed         speed of the water's FBM through its time axis, noise units per second
//   water_bump          strength of the FBM bump (0: a mirror)
//   sun_elevation,      the sun's direction in degrees (azimuth 0 = +z, the default view's
//     sun_azimuth         direction; 90 = +x)
//   sun_color,          the sun's colour and irradiance
//     sun_intensity
//   petal_translucency  share of the sun that shines through a backlit petal
//   droplets            how many water drops sit on the pads and petals (0: none, 1: the look)
//   shadow_softness     penumbra sharpness k of the soft shadows
//   fog_distance        metres where the distance fog is complete
//   contrast            the seed's contrast curve mixed in, 0..1
//   saturation          1 = unchanged, above 1 more saturated
//   vignette            the seed's vignette falloff: 1 / (1 + (falloff r)^2)^2, r 1 at the sides
#include <memory>
#include <utility>
#include <vector>

#include "scenes/scene.h"
#include "scenes/water_lily/geometry.h"
#include "scenes/water_lily/lanes.h"
#include "scenes/water_lily/render.h"
#include "scenes/water_lily/uniforms.h"

namespace sdfreel {
namespace {

class WaterLilyScene : public Scene {
 public:
  void prepare(const FrameContext& ctx) override { u_ = water_lily::make_lily_uniforms(ctx); }
  glm::vec3 radiance(const Ray& ray, RayStats& stats) const override {
    return water_lily::sceneRadiance(ray, u_, stats);
  }
  void radiance_packet(const RayPacket& rays, glm::vec3* out, RayStats& stats) const override {
    water_lily::radiancePacket(rays, u_, out, stats);
  }
  std::vector<DistanceFunction> distance_functions() const override {
    return water_lily::lilyDistanceFunctions(u_);
  }
  std::optional<float> solid_distance(const glm::vec3& p) const override {
    return water_lily::mapNearest(p, u_, water_lily::BOUND_MARGIN).d;
  }
  std::vector<ShaderUniform> shader_uniforms() const override {
    return water_lily::lily_shader_uniforms(u_);
  }

 private:
  water_lily::LilyUniforms u_;
};

ParamSpec scalar(const char* name, double def, double min, double max, const char* doc) {
  return ParamSpec{name, 1, {def}, min, max, doc};
}

}  // namespace

SceneInfo water_lily_scene_info() {
  SceneInfo info;
  info.name = "water_lily";
  info.description =
      "A Monet-inspired pond (seed 001): water lilies built from layers of reshaped spheres "
      "(pointed, curled, flattened petals around a coloured centre) and notched lily pads with a "
      "Worley texture float on animated water. The water's normal is bumped by time-dependent 3D "
      "FBM that calms with distance; it mirrors the lilies and the FBM-lit sky through a Fresnel "
      "term. Soft shadows from the sun and the sky, translucent petals, curled and submerged "
      "pads, water drops on pads and petals, contrast, saturation, vignette and distance fog.";
  info.params = {
      scalar("curl_amount", 1.0, 0.0, 1.6,
             "petal curl rate (radians per unit of petal length, times each layer's share)"),
      scalar("leaf_drift", 0.25, 0.0, 1.0, "metres the drifting pad travels in x (0.6 of it in z)"),
      scalar("water_speed", 0.35, 0.0, 5.0, "speed of the water's FBM along its time axis, 1/s"),
      scalar("water_bump", 1.0, 0.0, 4.0, "strength of the water's FBM bump; 0 is a still mirror"),
      scalar("sun_elevation", 40.0, 5.0, 90.0, "height of the sun above the horizon, degrees"),
      scalar("sun_azimuth", -50.0, -180.0, 180.0,
             "direction of the sun, degrees: 0 = +z (ahead in the default view), 90 = +x"),
      ParamSpec{"sun_color", 3, {1.0, 0.93, 0.82}, 0.0, 1.0, "colour of the sunlight, linear"},
      scalar("sun_intensity", 1.6, 0.0, 10.0, "irradiance of the sun"),
      scalar("petal_translucency", 0.6, 0.0, 1.0,
             "share of the sunlight that shines through a backlit petal"),
      scalar("droplets", 1.0, 0.0, 2.0,
             "how many water drops sit on the pads and petals, as a share of the default; 0: none"),
      scalar("shadow_softness", 10.0, 1.0, 128.0,
             "penumbra sharpness k of the soft shadows: small = soft, large = hard"),
      scalar("fog_distance", 28.0, 1.0, 500.0, "metres where the distance fog is complete"),
      scalar("contrast", 0.35, 0.0, 1.0, "the seed's contrast curve col^2 (3 - 2 col), mixed in"),
      scalar("saturation", 1.15, 0.0, 2.0, "1 keeps the colours; above 1 more saturated"),
      scalar("vignette", 0.45, 0.0, 2.0,
             "the seed's vignette falloff: 1 / (1 + (falloff r)^2)^2, r 1 at the frame's sides"),
  };
  info.default_camera = CameraPose{{0.2, 1.25, -1.6}, {0.4, 0.05, 4.0}, 45.0, 0.0};
  info.shader = "water_lily/water_lily.glsl";
  info.counts_sdf_evals = true;
  info.draws_surfaces = true;
  info.make = [] { return std::unique_ptr<Scene>(new WaterLilyScene()); };
  return info;
}

}  // namespace sdfreel
