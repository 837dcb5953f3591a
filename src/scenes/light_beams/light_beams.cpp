// Scene "light_beams" (seed 003, a recreation of Lusion's AKARI light beams): a 2D scene of
// glowing circles and stroked segments on a dark blue ground, vertical beams that sway and
// flicker, and an occluder that passes through them casting soft shadows.
//
// The 2D world is the plane z = 0, seen by the timeline's [camera] like any 3D scene: the default
// camera at (x, y, 1) looking at (x, y, 0) with fov = 90 shows the window centred on (x, y),
// 2 units high; the camera's distance (or fov) zooms, roll turns the view (docs/scenes/light_beams.md).
//
// Parameters (`sdfreel scenes light_beams`):
//   light_intensity   HDR scale of every light, cores (white) and glow
//   beam_intensity    the beams' scale relative to the other lights
//   glow_constant,    the seed's glow: 1 / (constant + linear * d + quadratic * d^2), d the
//   glow_linear,        distance to the light in world units
//   glow_quadratic
//   beam_speed        rate of the beams' horizontal sway (1 = their base rates)
//   beam_sway         amplitude of the sway, world units
//   beam_half_length  half the beams' length (0: both ends equal, a dot)
//   flicker_depth     how far a flicker dims a beam: 0 never, 1 out
//   occluder_x/_y     centre of the occluder (the seed's mouse): animate them for its path
//   occluder_radius   its radius, world units
//   background        the seed's ground colour, linear Rec.709
// The quality preset picks the shadow estimator (uniforms.h): the seed's one ray (the bench's
// naive), a penumbra share per occluder (draft, final), the exact visible share (reference).
#include <memory>
#include <utility>
#include <vector>

#include "scenes/light_beams/lanes.h"
#include "scenes/light_beams/render.h"
#include "scenes/light_beams/uniforms.h"
#include "scenes/scene.h"

namespace sdfreel {
namespace {

class LightBeamsScene : public Scene {
 public:
  void prepare(const FrameContext& ctx) override { u_ = light_beams::make_beams_uniforms(ctx); }
  glm::vec3 radiance(const Ray& ray, RayStats& stats) const override {
    return light_beams::sceneRadiance(ray, u_, stats);
  }
  void radiance_packet(const RayPacket& rays, glm::vec3* out, RayStats& stats) const override {
    light_beams::radiancePacket(rays, u_, out, stats);
  }
  std::vector<DistanceFunction> distance_functions() const override {
    return light_beams::beamsDistanceFunctions(u_);
  }
  std::vector<ShaderUniform> shader_uniforms() const override {
    return light_beams::beams_shader_uniforms(u_);
  }

 private:
  light_beams::BeamsUniforms u_;
};

ParamSpec scalar(const char* name, double def, double min, double max, const char* doc) {
  return ParamSpec{name, 1, {def}, min, max, doc};
}

// Close to the amber light and a beam (spans near pi, shadows of the beam), and a tilted, rolled
// view of the plane (perspective, rays that miss it above the horizon).
std::vector<CameraPose> test_poses(const CameraPose& def) {
  CameraPose near = def;
  near.position = glm::dvec3(-0.8, 0.3, 0.25);
  near.target = glm::dvec3(-0.8, 0.3, 0.0);
  near.roll_deg = 20.0;
  CameraPose tilted = def;
  tilted.position = glm::dvec3(0.2, -1.5, 0.6);
  tilted.target = glm::dvec3(0.0, 0.3, 0.0);
  return {near, tilted};
}

}  // namespace

SceneInfo light_beams_scene_info() {
  SceneInfo info;
  info.name = "light_beams";
  info.description =
      "Lusion's AKARI light beams recreated in 2D (seed 003): glowing circles and stroked "
      "segments with white cores and coloured halos on a dark blue ground, vertical beams that "
      "sway and flicker, and an occluder (the seed's mouse; animate occluder_x/occluder_y) whose "
      "soft shadows cut through the glow. The world is the plane z = 0 seen by the camera: "
      "position.xy is the view's centre, the distance to the plane (or fov) zooms. The reference "
      "preset computes each light's exactly visible share of its angular span.";
  info.params = {
      scalar("light_intensity", 2.5, 0.0, 100.0, "HDR scale of every light (white core and glow)"),
      scalar("beam_intensity", 0.4, 0.0, 100.0, "the beams' scale relative to the other lights"),
      scalar("glow_constant", 1.0, 1e-3, 100.0, "glow 1 / (constant + linear d + quadratic d^2)"),
      scalar("glow_linear", 12.0, 0.0, 1e4, "glow: linear term, per world unit"),
      scalar("glow_quadratic", 150.0, 0.0, 1e6, "glow: quadratic term, per square world unit"),
      scalar("beam_speed", 1.0, -10.0, 10.0, "rate of the beams' horizontal sway (1 = base)"),
      scalar("beam_sway", 0.3, 0.0, 2.0, "amplitude of the beams' sway, world units"),
      scalar("beam_half_length", 1.4, 0.0, 1e6,
             "half the beams' length, world units (1.4: beyond the default view's top and bottom)"),
      scalar("flicker_depth", 1.0, 0.0, 1.0, "how far a flicker dims a beam: 0 never, 1 out"),
      scalar("occluder_x", 0.0, -1e6, 1e6, "occluder centre x, world units (the seed's mouse)"),
      scalar("occluder_y", 0.0, -1e6, 1e6, "occluder centre y, world units"),
      scalar("occluder_radius", 0.16, 0.0, 1e6, "occluder radius, world units"),
      ParamSpec{"background",
                3,
                {0.01, 0.02, 0.05},
                0.0,
                1.0,
                "ground colour, linear Rec.709 (the seed's vec3(0.01, 0.02, 0.05))"},
  };
  info.default_camera = CameraPose{{0.0, 0.0, 1.0}, {0.0, 0.0, 0.0}, 90.0, 0.0};
  info.test_poses = test_poses(info.default_camera);
  info.map_up = {0.0, 0.0, 1.0};  // the map looks at the plane from further away
  info.map_side_view = false;     // the plane edge-on
  info.shader = "light_beams/light_beams.glsl";
  info.counts_sdf_evals = true;
  info.make = [] { return std::unique_ptr<Scene>(new LightBeamsScene()); };
  return info;
}

}  // namespace sdfreel
