// Exhibit 1 composited with the hall by depth (issue 12): the hall hides it exactly where the
// depths say, it is drawn with the camera inside its bounding mesh, and moved by its transform it
// renders as the moved object. Runs the museum plan's own passes on the CPU, one sample at the
// pixel centres, into targets the test can read.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <string>

#include "backends/cpu/cpu_image_pass.h"
#include "backends/cpu/cpu_mesh_pass.h"
#include "backends/cpu/cpu_ray_pass.h"
#include "scenes/museum/exhibits.h"
#include "scenes/registry.h"
#include "scenes/scene_pixels.h"
#include "scenes/sdf_morph/geometry.h"

namespace sdfreel {
namespace {

constexpr int W = 96, H = 54;
const char* HALL = "hall";
const char* EXHIBIT = "exhibit 1: sdf_morph";

FrameContext museum_context(const CameraPose& pose, double shift_x = 0.0, double lift = 0.0) {
  const SceneInfo& info = *find_scene("museum");
  FrameContext ctx = test::scene_context(info, W, H, 2.0, Quality::Final);
  ctx.pose = pose;
  ctx.params.set("exhibit_shift_x", {shift_x});
  ctx.params.set("exhibit_lift", {lift});
  finish_frame_context(ctx);
  return ctx;
}

// The targets after the museum plan's passes named in `names` (in plan order).
struct Targets {
  ImageRGBA colour, depth;
};
Targets run_passes(const FrameContext& ctx, const std::set<std::string>& names) {
  std::unique_ptr<Scene> scene = find_scene("museum")->make();
  scene->prepare(ctx);
  const FramePlan plan = scene->frame_plan(ctx);
  CpuPassContext pc{ctx,
                    glm::vec2(0.5f),
                    make_camera_model(ctx.camera, W, H, plan.near_plane, plan.far_plane),
                    footprint_angle(ctx.camera.tan_half_fov, H),
                    1,
                    16,
                    true};
  CpuTargets targets(plan_targets(plan), W, H);
  targets.clear();
  RayStats stats;
  for (const Pass& pass : plan.passes) {
    if (!names.count(pass_name(pass))) continue;
    if (const auto* ray = std::get_if<RayPass>(&pass))
      run_ray_pass(*ray, pc, targets, stats);
    else if (const auto* mesh = std::get_if<MeshPass>(&pass))
      run_mesh_pass(*mesh, pc, targets);
    else
      run_image_pass(std::get<ImagePass>(pass), pc, targets);
  }
  return {targets.get(HALL, "test"), targets.get(DEPTH_TARGET, "test")};
}

bool same_rgb(const float* a, const float* b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

int drawn(const Targets& t) {
  int n = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) n += t.depth.at(x, y)[0] < 1.0f;
  return n;
}

// Behind plinth 2, looking across the hall at exhibit 1 over it: the plinth hides the lower part.
const CameraPose BEHIND_PLINTH{{-3.0, 0.9, 3.6}, {-3.0, 1.35, -1.7}, 30.0, 0.0};
// In front of exhibit 1, nothing between.
const CameraPose FACING{{-3.0, 1.6, 0.5}, {-3.0, 1.35, -1.7}, 40.0, 0.0};

TEST(MuseumDepth, TheHallHidesTheExhibitExactlyWhereItIsNearer) {
  const FrameContext ctx = museum_context(BEHIND_PLINTH);
  const Targets hall = run_passes(ctx, {HALL});
  const Targets exhibit = run_passes(ctx, {EXHIBIT});
  const Targets both = run_passes(ctx, {HALL, EXHIBIT});
  int hidden = 0, shown = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const float zh = hall.depth.at(x, y)[0], ze = exhibit.depth.at(x, y)[0];
      const float z = both.depth.at(x, y)[0];
      if (ze < zh) {
        ++shown;
        EXPECT_EQ(z, ze) << x << "," << y;
        EXPECT_TRUE(same_rgb(both.colour.at(x, y), exhibit.colour.at(x, y))) << x << "," << y;
      } else {
        hidden += ze < 1.0f;
        EXPECT_EQ(z, zh) << x << "," << y;
        EXPECT_TRUE(same_rgb(both.colour.at(x, y), hall.colour.at(x, y))) << x << "," << y;
      }
    }
  EXPECT_GT(shown, 30) << "the exhibit should show above the plinth";
  EXPECT_GT(hidden, 30) << "the plinth should hide part of the exhibit";
}

TEST(MuseumDepth, CameraInsideTheBoundStillDrawsTheExhibit) {
  const FrameContext base = museum_context(FACING);
  const glm::mat4 model = museum::exhibit_one_model(base);
  const float scale = glm::length(glm::vec3(model[0]));
  const float half = sdf_morph::OBJECT_BOUND_RADIUS * scale;
  const glm::vec3 centre = glm::vec3(
      model * glm::vec4(0.0f, sdf_morph::OBJECT_BOUND_Y - sdf_morph::PEDESTAL_HEIGHT, 0.0f, 1.0f));
  const glm::vec3 eye = centre + glm::vec3(0.85f, 0.6f, 0.85f) * half;
  const FrameContext ctx = museum_context(CameraPose{eye, centre, 70.0, 0.0});
  for (int k = 0; k < 3; ++k) ASSERT_LT(std::abs(eye[k] - centre[k]), half) << "not inside";
  const Targets exhibit = run_passes(ctx, {EXHIBIT});
  EXPECT_GT(drawn(exhibit), W * H / 10) << "the exhibit vanished with the camera in its bound";
}

TEST(MuseumDepth, MovedExhibitRendersAsTheMovedObject) {
  // Moving the exhibit by s and the camera with it shows the same picture of it.
  const glm::dvec3 s(0.4, 0.25, 0.0);
  CameraPose moved = FACING;
  moved.position += s;
  moved.target += s;
  const Targets a = run_passes(museum_context(FACING), {EXHIBIT});
  const Targets b = run_passes(museum_context(moved, s.x, s.y), {EXHIBIT});
  const Targets still = run_passes(museum_context(moved), {EXHIBIT});
  int both = 0, differ = 0, moved_away = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const float za = a.depth.at(x, y)[0], zb = b.depth.at(x, y)[0];
      moved_away += (za < 1.0f) != (still.depth.at(x, y)[0] < 1.0f);
      if ((za < 1.0f) != (zb < 1.0f)) {
        ++differ;
        continue;
      }
      if (za < 1.0f) {  // the hit's depth, up to the hit threshold
        ++both;
        EXPECT_NEAR(za, zb, 1e-4f) << x << "," << y;
      }
    }
  EXPECT_GT(both, 100);
  EXPECT_LE(differ, both / 50) << "silhouette pixels that moved";
  EXPECT_GT(moved_away, 50) << "the camera move alone must change the picture";
}

}  // namespace
}  // namespace sdfreel
