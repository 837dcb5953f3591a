#pragma once
// A scene: code that turns a primary ray into linear radiance (CPU backend), plus the metadata
// that the timeline, `sdfreel scenes` and the OSMesa backend need. One file per scene registers it
// in registry.cpp.
#include <functional>
#include <memory>
#include <string>
#include <vector>
#include <glm/glm.hpp>

#include "render/frame_context.h"
#include "render/params.h"

namespace sdfreel {

// Per-sample counters, summed per frame for the bench (SDF evaluations per pixel, step caps).
struct RayStats {
  uint64_t sdf_evals = 0;
  uint64_t steps = 0;
  uint64_t capped = 0;  // rays that hit max_steps
  void add(const RayStats& o) { sdf_evals += o.sdf_evals; steps += o.steps; capped += o.capped; }
};

struct Ray {
  glm::vec3 origin;
  glm::vec3 dir;        // unit length
  float pixel_angle;    // angular size of one pixel (radians): hit epsilon grows with t * pixel_angle
};

class Scene {
 public:
  virtual ~Scene() = default;
  // Called once per frame before any ray: cache per-frame constants (wrapped phases, parameter
  // reads, per-cell data). Must be deterministic and depend only on ctx.
  virtual void prepare(const FrameContext& ctx) = 0;
  // Linear scene-referred radiance (Rec.709 primaries) along one primary ray. Thread-safe (const).
  virtual glm::vec3 radiance(const Ray& ray, RayStats& stats) const = 0;
};

struct SceneInfo {
  std::string name;
  std::string description;               // one paragraph, printed by `sdfreel scenes NAME`
  std::vector<ParamSpec> params;
  CameraPose default_camera;
  std::string shader;                    // GLSL file under shaders/, for the OSMesa backend
  std::function<std::unique_ptr<Scene>()> make;
};

}  // namespace sdfreel
