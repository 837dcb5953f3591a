// Scene "sdf_morph" (seed 004, exhibit 1): a glossy object that morphs between a torus and a mug
// while it turns on a pedestal in a photo studio. The seed's reflection probe becomes an analytic
// studio environment (sdf_morph/render.cpp); the seed's depth-buffer integration becomes a
// pedestal and floor in the same ray-marched scene, so the object casts soft shadows onto them.
#include <memory>
#include <utility>
#include <vector>

#include "scenes/common/param.h"
#include "scenes/scene.h"
#include "scenes/sdf_morph/geometry.h"
#include "scenes/sdf_morph/lanes.h"
#include "scenes/sdf_morph/render.h"
#include "scenes/sdf_morph/uniforms.h"

namespace sdfreel {
namespace {

// The parameters, each with its default, range and meaning (printed by `sdfreel scenes sdf_morph`).
std::vector<ParamSpec> params() {
  return {
      scalar_param("morph_period", 6.0, 0.5, 120.0, "seconds for torus -> mug -> torus"),
      scalar_param("rotation_speed", 0.35, -3.14159, 3.14159,
                   "turning speed of the object about the vertical axis, radians per second"),
      colour_param("color", {0.9, 0.6, 0.3}, "base (diffuse) colour of the object, linear Rec.709"),
      scalar_param(
          "reflectivity", 0.6, 0.0, 1.0,
          "mirror reflection at normal incidence (Schlick F0); grazing angles reflect fully"),
      scalar_param("key_light_intensity", 2.0, 0.0, 20.0,
                   "irradiance of the key light (direction of the large front-left soft box)"),
      scalar_param("shadow_softness", 12.0, 1.0, 128.0,
                   "penumbra sharpness k of the soft shadows: small = soft and wide, large = hard"),
      scalar_param("environment_intensity", 1.0, 0.0, 10.0,
                   "scale of the studio: walls, soft boxes (reflections) and ambient light"),
  };
}

class SdfMorphScene : public Scene {
 public:
  void prepare(const FrameContext& ctx) override { u_ = sdf_morph::make_morph_uniforms(ctx); }
  glm::vec3 radiance(const Ray& ray, RayStats& stats) const override {
    return sdf_morph::sceneRadiance(ray, u_, stats);
  }
  void radiance_packet(const RayPacket& rays, glm::vec3* out, RayStats& stats) const override {
    sdf_morph::radiance_lanes(rays, u_, out, stats);
  }
  std::vector<DistanceFunction> distance_functions() const override {
    return sdf_morph::morphDistanceFunctions(u_);
  }
  std::optional<float> solid_distance(const glm::vec3& p) const override {
    bool exact;
    return sdf_morph::mapSceneBounded(p, u_, sdf_morph::OBJECT_BOUND_MARGIN, exact);
  }
  std::vector<ShaderUniform> shader_uniforms() const override {
    return sdf_morph::morph_shader_uniforms(u_);
  }

 private:
  sdf_morph::MorphUniforms u_;
};

// Close-ups: the object fills the frame (relaxed marches, reflections of the pedestal and of the
// mug's inside), and the pedestal's foot with the object's shadow on the floor.
std::vector<CameraPose> test_poses(const CameraPose& def) {
  CameraPose close = def;
  close.position = close.target + (close.position - close.target) * 0.35;
  close.fov_deg = 30.0;
  CameraPose foot = def;
  foot.position = glm::dvec3(-1.2, 0.5, -1.6);
  foot.target = glm::dvec3(0.4, 0.1, 0.5);
  return {close, foot};
}

}  // namespace

SceneInfo sdf_morph_scene_info() {
  SceneInfo info;
  info.name = "sdf_morph";
  info.description =
      "A ray-marched glossy object that morphs between a torus and a mug (seed 004, exhibit 1) "
      "while it slowly turns on a pedestal in a photo studio. Its mirror-like surface reflects an "
      "analytic studio (gradient walls, three soft boxes) that stands in for the seed's "
      "reflection probe, mixed with a coloured base by a Fresnel term; a key light casts soft "
      "shadows onto the pedestal and floor.";
  info.params = params();
  info.default_camera = CameraPose{{0.0, 1.45, -3.4}, {0.0, 0.72, 0.0}, 40.0, 0.0};
  info.test_poses = test_poses(info.default_camera);
  info.shader = "sdf_morph/sdf_morph.glsl";
  info.counts_sdf_evals = true;
  info.draws_surfaces = true;
  info.make = [] { return std::unique_ptr<Scene>(new SdfMorphScene()); };
  return info;
}

}  // namespace sdfreel
