#include "gl/mixed_plan.h"

#include <glm/gtc/matrix_transform.hpp>

#include "render/camera_model.h"
#include "render/unit_cube.h"
#include "sdf/det_math.h"

namespace sdfreel::test {

namespace {

const glm::vec3 SPHERE_CENTRE(0.6f, 0.7f, 0.3f);
const float SPHERE_RADIUS = 0.7f;
const glm::vec3 SPHERE_ALBEDO(0.9f, 0.35f, 0.2f);
const glm::vec3 LIGHT_DIR(0.48f, 0.8f, -0.36f);
constexpr int MAX_STEPS = 96;
constexpr float HIT_EPS = 1e-4f;
constexpr float MAX_T = 40.0f;

// The twin of tests/gl/shaders/sphere_ray.glsl.
bool shade_ray(const Ray& ray, const glm::vec3& forward, RayStats& stats, glm::vec3& colour,
               float& view_depth) {
  float t = 0.0f;
  for (int i = 0; i < MAX_STEPS; ++i) {
    const glm::vec3 p = ray.origin + ray.dir * t;
    const glm::vec3 q = p - SPHERE_CENTRE;
    const float d = dm::sqrt(q.x * q.x + q.y * q.y + q.z * q.z) - SPHERE_RADIUS;
    ++stats.sdf_evals;
    if (d < HIT_EPS) {
      const glm::vec3 n = q / SPHERE_RADIUS;
      const float lambert =
          dm::max(n.x * LIGHT_DIR.x + n.y * LIGHT_DIR.y + n.z * LIGHT_DIR.z, 0.0f);
      colour = SPHERE_ALBEDO * (0.2f + 0.8f * lambert);
      view_depth = t * (ray.dir.x * forward.x + ray.dir.y * forward.y + ray.dir.z * forward.z);
      return true;
    }
    t = t + d;
    if (t > MAX_T) break;
  }
  return false;
}

MeshInstance box(const glm::vec3& centre, const glm::vec3& size, const glm::vec3& colour) {
  return {glm::scale(glm::translate(glm::mat4(1.0f), centre), size), glm::vec4(colour, 1.0f)};
}

}  // namespace

FramePlan mixed_plan(const FrameContext& ctx) {
  static const std::shared_ptr<const TriangleMesh> mesh = unit_cube();
  FramePlan plan;
  MeshPass cubes;
  cubes.name = "cubes";
  cubes.mesh = mesh;
  cubes.instances = {box({0, -0.05f, 0}, {8, 0.1f, 8}, {0.5f, 0.5f, 0.45f}),
                     box({-0.6f, 0.4f, -0.6f}, {0.8f, 0.8f, 0.8f}, {0.2f, 0.4f, 0.8f}),
                     box({1.2f, 0.25f, -1.0f}, {0.5f, 0.5f, 0.5f}, {0.3f, 0.7f, 0.3f}),
                     box({-1.5f, 0.6f, 1.2f}, {0.6f, 1.2f, 0.6f}, {0.8f, 0.7f, 0.2f})};
  cubes.fragment = "lit_mesh.frag";
  cubes.shade = [](const MeshFragment& f) {
    const glm::vec3 n = glm::normalize(f.world_normal);
    const float lambert = std::max(glm::dot(n, LIGHT_DIR), 0.0f);
    return glm::vec4(glm::vec3(f.instance_data) * (0.2f + 0.8f * lambert), 1.0f);
  };
  RayPass sphere;
  sphere.name = "sphere";
  sphere.depth = DEPTH_TARGET;
  sphere.depth_test = DepthTest::TestAndWrite;
  sphere.shader = "sphere_ray.glsl";
  const glm::vec3 forward = ctx.camera.forward;
  const CameraModel cam =
      make_camera_model(ctx.camera, ctx.width, ctx.height, plan.near_plane, plan.far_plane);
  sphere.scalar = [forward, cam](const Ray& ray, glm::vec3& colour, float& depth, bool& keep,
                                 RayStats& stats) {
    float view_depth = 0.0f;
    keep = shade_ray(ray, forward, stats, colour, view_depth);
    if (keep) depth = window_depth(cam, view_depth);
  };
  plan.passes = {cubes, sphere};
  return plan;
}

FrameContext mixed_context(int width, int height, int samples) {
  FrameContext ctx;
  ctx.width = width;
  ctx.height = height;
  ctx.samples = samples;
  ctx.pose = {{2.2, 1.6, -3.6}, {0.0, 0.45, 0.0}, 45.0, 0.0};
  finish_frame_context(ctx);
  return ctx;
}

}  // namespace sdfreel::test
