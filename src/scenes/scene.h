#pragma once
// A scene: code that turns a primary ray into linear radiance (CPU backend), plus the metadata
// that the timeline, `sdfreel scenes`, the OSMesa backend and the tests need. Each scene lives in
// src/scenes/<scene>/ and is registered by one line in registry.cpp (docs/adding-a-scene.md).
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/frame_context.h"
#include "render/frame_plan.h"
#include "render/params.h"
#include "render/rays.h"
#include "render/shader_inputs.h"
#include "sdf/lanes.h"

namespace sdfreel {

// A distance function of a scene, for micro-benchmarks and lane tests: d[i] at (x[i], y[i], z[i])
// for i < n (n a multiple of LANES), one point at a time (`scalar`) or eight lanes at a time
// (`lanes`), with the same bits. Valid after prepare(), for that frame.
struct DistanceFunction {
  std::string name;  // the function's name in the scene's code, e.g. "sdfWater"
  std::function<void(const float*x, const float*y, const float*z, float*d, int n)> scalar, lanes;
};

class Scene {
 public:
  virtual ~Scene() = default;
  // Called once per frame before any ray: cache per-frame constants (wrapped phases, parameter
  // reads, per-cell data). Must be deterministic and depend only on ctx. Backends call it under the
  // render's thread count (render/tiling.h with_threads), so its parallel loops keep to --threads.
  virtual void prepare(const FrameContext& ctx) = 0;
  // Linear scene-referred radiance (Rec.709 primaries) along one primary ray. Thread-safe (const).
  virtual glm::vec3 radiance(const Ray& ray, RayStats& stats) const = 0;
  // The same for a packet: out[i] for i < rays.count, bit for bit equal to radiance(rays.ray(i))
  // and adding the same stats. The default runs radiance() lane by lane; scenes override it with
  // eight-lane code (sdf/lanes.h).
  virtual void radiance_packet(const RayPacket& rays, glm::vec3* out, RayStats& stats) const;
  // The frame as a plan of passes (render/frame_plan.h), after prepare(). The default is one ray
  // pass of radiance_packet (radiance on the scalar path) into "colour", GLSL SceneInfo::shader.
  virtual FramePlan frame_plan(const FrameContext& ctx) const;
  // For the OSMesa backend, after prepare(): the per-frame constants and textures its shader reads.
  // After prepare(): the distance functions its marches evaluate, scalar and in lanes.
  virtual std::vector<DistanceFunction> distance_functions() const { return {}; }
  // After prepare_solids(): the distance from p to the solid surfaces a camera must stay out of
  // (negative inside), for `check`'s warning; none where the scene cannot tell.
  virtual std::optional<float> solid_distance(const glm::vec3& /*p*/) const { return std::nullopt; }
  // The part of prepare() that solid_distance() needs: all of it, unless the scene's solids are
  // cheaper to place (the museum's hall does not move; its prepare() renders a probe).
  virtual void prepare_solids(const FrameContext& ctx) { prepare(ctx); }
  virtual std::vector<ShaderUniform> shader_uniforms() const { return {}; }
  virtual std::vector<ShaderTexture> shader_textures() const { return {}; }
  // Names the content of shader_textures(): equal keys, equal texels, so the backend uploads them
  // once rather than every frame. 0: unknown, upload every frame.
  virtual uint64_t shader_textures_key() const { return 0; }
};

struct ShaderProject;  // shader/shader_project.h

struct SceneInfo {
  std::string name;
  std::string description;  // one paragraph, printed by `sdfreel scenes NAME`
  std::vector<ParamSpec> params;
  CameraPose default_camera;
  // Where this scene's marches are hardest (close-ups, grazing rays, eyes low or looking up): the
  // packet-path and CPU-against-GL tests render these besides the poses of test_camera_poses().
  std::vector<CameraPose> test_poses;
  std::string shader;  // GLSL main file relative to shaders/ ("<scene>/<scene>.glsl"), for OSMesa
  std::function<std::unique_ptr<Scene>()> make;  // empty for a user's shader (GL only)
  // A user's shader (docs/shaders.md): what the GL backend runs instead of `shader`.
  std::shared_ptr<const ShaderProject> shader_project;
  // The backend's image is display-referred sRGB (a Shadertoy shader's own output): the display
  // frame is that image as it is, the linear one its sRGB decoding; no [color] view applies.
  bool display_referred = false;
  // For `sdfreel map`: the scene's up, along which the map looks down (light_beams' 2D world is
  // the plane z = 0, seen along -z); the height its camera stays under (the museum's ceiling); and
  // whether a view from the side shows anything but a wall or an edge.
  glm::dvec3 map_up{0.0, 1.0, 0.0};
  double map_ceiling = 1e9;
  bool map_side_view = true;
  // Its marches count their SDF evaluations per ray on both backends (RayStats, the GLSL
  // sdf_evals output): the bench's evaluations a pixel and the sdf_evals compositing pass.
  bool counts_sdf_evals = false;
  // It draws its primary surfaces' distance and normal instead of colours when
  // MarchSettings::surface asks (scenes/common/surface_output.h), on both backends: the depth and
  // normal compositing passes.
  bool draws_surfaces = false;
};

// The poses the scene-wide tests render: the default camera, the same eye looking down steeply
// and nearly level with a narrow field of view (any scene), then the scene's own test_poses.
std::vector<CameraPose> test_camera_poses(const SceneInfo& info);

}  // namespace sdfreel
