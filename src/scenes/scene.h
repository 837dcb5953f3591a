#pragma once
// A scene: code that turns a primary ray into linear radiance (CPU backend), plus the metadata
// that the timeline, `sdfreel scenes`, the OSMesa backend and the tests need. Each scene lives in
// src/scenes/<scene>/ and is registered by one line in registry.cpp (docs/adding-a-scene.md).
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "render/frame_context.h"
#include "render/params.h"
#include "sdf/lanes.h"

namespace sdfreel {

// Per-sample counters, summed per frame for the bench (SDF evaluations per pixel, step caps).
struct RayStats {
  uint64_t sdf_evals = 0;
  uint64_t steps = 0;
  uint64_t capped = 0;  // rays that hit max_steps
  void add(const RayStats& o) {
    sdf_evals += o.sdf_evals;
    steps += o.steps;
    capped += o.capped;
  }
};

// Per-frame constants a scene hands to its GLSL twin (OSMesa backend): the same numbers that
// prepare() computed for the C++ path, so both backends start from identical inputs.
struct ShaderUniform {
  std::string name;           // GLSL uniform name
  int components = 1;         // 1..4: float, vec2, vec3, vec4
  std::vector<float> values;  // components * array length (array when longer)
};

// A texture a scene generates (blue noise, sky, paper maps) for its GLSL twin. Shaders should
// read it with texelFetch and filter in code exactly as the C++ path does.
struct ShaderTexture {
  std::string name;  // sampler uniform name
  int width = 0, height = 0, channels = 4;
  std::vector<float> texels;  // width * height * channels, row-major, row 0 first
};

struct Ray {
  glm::vec3 origin;
  glm::vec3 dir;      // unit length
  float pixel_angle;  // angular size of one pixel (radians): hit epsilon grows with t * pixel_angle
};

// Up to LANES primary rays from one eye: the CPU backend's SIMD unit. Lanes >= count are padding
// (copies of the last ray): inactive, never counted in RayStats, their output ignored.
struct RayPacket {
  glm::vec3 origin;
  V3x8 dir;           // unit length
  float pixel_angle;  // as in Ray
  int count = LANES;  // valid lanes, 1..LANES
  M8 valid() const;   // lane < count
  Ray ray(int i) const { return Ray{origin, dir.lane(i), pixel_angle}; }
};

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
  // reads, per-cell data). Must be deterministic and depend only on ctx.
  virtual void prepare(const FrameContext& ctx) = 0;
  // Linear scene-referred radiance (Rec.709 primaries) along one primary ray. Thread-safe (const).
  virtual glm::vec3 radiance(const Ray& ray, RayStats& stats) const = 0;
  // The same for a packet: out[i] for i < rays.count, bit for bit equal to radiance(rays.ray(i))
  // and adding the same stats. The default runs radiance() lane by lane; scenes override it with
  // eight-lane code (sdf/lanes.h).
  virtual void radiance_packet(const RayPacket& rays, glm::vec3* out, RayStats& stats) const;
  // For the OSMesa backend, after prepare(): the per-frame constants and textures its shader reads.
  // After prepare(): the distance functions its marches evaluate, scalar and in lanes.
  virtual std::vector<DistanceFunction> distance_functions() const { return {}; }
  virtual std::vector<ShaderUniform> shader_uniforms() const { return {}; }
  virtual std::vector<ShaderTexture> shader_textures() const { return {}; }
  // Names the content of shader_textures(): equal keys, equal texels, so the backend uploads them
  // once rather than every frame. 0: unknown, upload every frame.
  virtual uint64_t shader_textures_key() const { return 0; }
};

struct SceneInfo {
  std::string name;
  std::string description;  // one paragraph, printed by `sdfreel scenes NAME`
  std::vector<ParamSpec> params;
  CameraPose default_camera;
  // Where this scene's marches are hardest (close-ups, grazing rays, eyes low or looking up): the
  // packet-path and CPU-against-GL tests render these besides the poses of test_camera_poses().
  std::vector<CameraPose> test_poses;
  std::string shader;  // GLSL main file relative to shaders/ ("<scene>/<scene>.glsl"), for OSMesa
  std::function<std::unique_ptr<Scene>()> make;
};

// The poses the scene-wide tests render: the default camera, the same eye looking down steeply
// and nearly level with a narrow field of view (any scene), then the scene's own test_poses.
std::vector<CameraPose> test_camera_poses(const SceneInfo& info);

}  // namespace sdfreel
