// Frame plans on GL: image passes over off-screen targets give the CPU's bits (crepuscular rays,
// and its analytic check over uniform occlusion); a mesh pass writes the depth a ray pass would
// write for the same points, into a depth target a later pass samples.
#include "backends/cpu/plan_runner.h"

#include "backends/gl/gl_plan_runner.h"
#include "gl/gl_fixture.h"
#include "passes/plan_fixture.h"
#include "render/camera_model.h"
#include "render/passes/crepuscular_rays.h"

namespace sdfreel {
namespace {

using test::GlTest;

FramePlan rays_plan(const CrepuscularRays& rays, bool pattern, float c) {
  FramePlan plan;
  plan.targets = {{"occlusion", TargetKind::Colour, glm::vec4(0.0f)}};
  plan.passes = {test::occlusion_fill("occlusion", pattern, c),
                 crepuscular_rays_pass(rays, "occlusion", COLOUR_TARGET)};
  return plan;
}

TEST_F(GlTest, CrepuscularRaysGiveTheCpuBitsAndTheClosedForm) {
  GlPlanRunner runner(*driver, 1);
  CrepuscularRays rays;
  rays.light_uv = glm::vec2(0.7f, 0.35f);
  const FrameContext ctx = test::plan_context(40, 22);
  RayStats stats;
  const FramePlan pattern = rays_plan(rays, true, 0.0f);
  const ImageRGBA gl = runner.run(pattern, ctx, {}, stats);
  const ImageRGBA cpu = run_plan_cpu(pattern, ctx, {}, stats);
  ASSERT_EQ(gl.pixels.size(), cpu.pixels.size());
  int differ = 0;
  for (size_t i = 0; i < gl.pixels.size(); ++i) differ += gl.pixels[i] != cpu.pixels[i];
  EXPECT_EQ(differ, 0) << "of " << gl.pixels.size() << " values, e.g. pixel 0: " << gl.pixels[0]
                       << " against " << cpu.pixels[0];
  rays.light_uv = glm::vec2(0.5f);
  rays.decay = 0.97f;
  rays.weight = 0.3f;
  const ImageRGBA uniform = runner.run(rays_plan(rays, false, 0.6f), ctx, {}, stats);
  const double want =
      test::crepuscular_closed_form(0.6, rays.samples, rays.weight, rays.decay, rays.exposure);
  for (int y = 0; y < ctx.height; ++y) {
    for (int x = 0; x < ctx.width; ++x) {
      ASSERT_NEAR(uniform.at(x, y)[0], want, rays.samples * want * 0x1p-24) << x << "," << y;
    }
  }
}

// A quad facing the camera at view depth 3, drawn by a mesh pass (instance data = its colour),
// its depth copied to colour by an image pass: the depth a ray pass writes for the same point.
TEST_F(GlTest, MeshDepthMatchesRayDepthAndLaterPassesSampleIt) {
  const int w = 24, h = 16;
  FrameContext ctx = test::plan_context(w, h);
  ctx.pose = {{0.3, 1.2, -4.0}, {0.0, 0.8, 0.0}, 45.0, 7.0};
  finish_frame_context(ctx);
  const CameraBasis& b = ctx.camera;
  auto quad = std::make_shared<TriangleMesh>();
  const glm::vec3 centre = b.origin + b.forward * 3.0f;
  for (const glm::vec2 c :
       {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
    const glm::vec3 p = centre + b.right * (c.x * 10.0f) + b.up * (c.y * 10.0f);
    quad->positions.insert(quad->positions.end(), {p.x, p.y, p.z});
  }
  quad->indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise as the camera sees it
  FramePlan plan;
  plan.targets = {{"depth_as_colour", TargetKind::Colour, glm::vec4(0.0f)}};
  MeshPass mesh;
  mesh.name = "quad";
  mesh.mesh = quad;
  mesh.instances = {{glm::mat4(1.0f), glm::vec4(0.25f, 0.5f, 1.0f, 1.0f)}};
  mesh.fragment = "flat_mesh.frag";
  mesh.cull = CullMode::Back;
  ImagePass copy;
  copy.name = "depth copy";
  copy.inputs = {{DEPTH_TARGET, "u_depth"}};
  copy.output = "depth_as_colour";
  copy.shader = "depth_copy.glsl";
  plan.passes = {mesh, copy};
  GlPlanRunner runner(*driver, 1);
  RayStats stats;
  const ImageRGBA colour = runner.run(plan, ctx, {}, stats);
  EXPECT_EQ(colour.at(5, 5)[0], 0.25f);
  EXPECT_EQ(colour.at(5, 5)[2], 1.0f);
  // Read the depth copy back through a plan whose output is that copy.
  ImagePass show = copy;
  show.output = COLOUR_TARGET;
  plan.passes = {mesh, show};
  const ImageRGBA depth = runner.run(plan, ctx, {}, stats);
  const CameraModel cam = make_camera_model(b, w, h, plan.near_plane, plan.far_plane);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec3 dir = primary_ray_dir(b, float(x) + 0.5f, float(y) + 0.5f, w, h);
      const float t = 3.0f / glm::dot(dir, b.forward);  // the ray meets the plane at depth 3
      ASSERT_NEAR(depth.at(x, y)[0], window_depth(cam, t * glm::dot(dir, b.forward)), 1e-6f)
          << "pixel " << x << "," << y;
    }
  // Front faces culled: the quad disappears, depth stays cleared (1).
  plan.passes[0] = mesh;
  std::get<MeshPass>(plan.passes[0]).cull = CullMode::Front;
  EXPECT_EQ(runner.run(plan, ctx, {}, stats).at(5, 5)[0], 1.0f);
}

}  // namespace
}  // namespace sdfreel
