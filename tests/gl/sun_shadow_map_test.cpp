// The museum's sun shadow map drawn by GL (rasterised by llvmpipe) and by the CPU (its own
// rasteriser with GL's coverage rules, exhibit 1 marched per texel on both) is the same map: a
// plan of the museum's setup passes at the map's size, the map copied into the frame. Where both
// cover a texel, the hall's casters agree within 1e-6 in window depth (about 15 micrometres along
// the sun), and with exhibit 1 within one texel width along the sun (its march stops within
// hit_eps texel footprints of the surface, from a start the two rasterisers interpolate a little
// differently); texels only one side covers (an edge through a texel centre, where llvmpipe snaps
// vertices to 1/256 texel and the CPU does not) are at most 0.05% of the map and lie on an edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "backends/cpu/plan_runner.h"
#include "backends/gl/gl_plan_runner.h"
#include "gl/gl_fixture.h"
#include "scenes/museum/atmosphere.h"
#include "scenes/museum/sun_shadow.h"
#include "scenes/registry.h"

namespace sdfreel {
namespace {

using test::GlTest;

constexpr float DEPTH_TOLERANCE = 1e-6f;
constexpr double MAX_COVERAGE_SHARE = 0.0005;

FramePlan map_plan(const FrameContext& ctx, size_t setup_passes) {
  std::unique_ptr<Scene> scene = find_scene("museum")->make();
  scene->prepare(ctx);
  const FramePlan museum = scene->frame_plan(ctx);
  FramePlan plan;
  plan.near_plane = museum.near_plane;
  plan.far_plane = museum.far_plane;
  plan.targets = {museum::sun_map_target()};
  plan.setup_passes = museum.setup_passes;
  plan.setup_passes.resize(setup_passes);
  plan.passes = {museum::copy_pass(museum::SUN_MAP_TARGET, COLOUR_TARGET)};
  return plan;
}

struct MapComparison {
  int covered = 0, coverage = 0, off_edge = 0;
  float worst = 0.0f;
};

MapComparison compare_maps(const ImageRGBA& gl, const ImageRGBA& cpu) {
  const int n = gl.width;
  auto depth = [n](const ImageRGBA& img, int x, int y) {
    return img.at(std::clamp(x, 0, n - 1), std::clamp(y, 0, n - 1))[0];
  };
  MapComparison m;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float g = depth(gl, x, y), c = depth(cpu, x, y);
      if (g < 1.0f && c < 1.0f) {
        ++m.covered;
        m.worst = std::max(m.worst, std::fabs(g - c));
        continue;
      }
      if (g == c) continue;
      ++m.coverage;
      bool edge = false;  // some neighbour is covered differently on one side
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          edge = edge || (depth(gl, x + dx, y + dy) < 1.0f) != (g < 1.0f) ||
                 (depth(cpu, x + dx, y + dy) < 1.0f) != (c < 1.0f);
      m.off_edge += !edge;
    }
  return m;
}

TEST_F(GlTest, MuseumSunShadowMapIsTheSameMapOnBothBackends) {
  const SceneInfo& info = *find_scene("museum");
  FrameContext ctx;
  ctx.width = ctx.height = museum::SUN_MAP_SIZE;
  ctx.samples = 1;
  ctx.scene_time = 2.0;
  ctx.pose = info.default_camera;
  ctx.params = ParamValues(&info.params);
  finish_frame_context(ctx);
  GlPlanRunner runner(*driver, 1);
  RayStats stats;
  const museum::SunView& sun = museum::sun_view();
  const float texel_depth = sun.texel * sun.inv_depth_range;
  const float tolerance[2] = {DEPTH_TOLERANCE, texel_depth};
  for (size_t passes = 1; passes <= 2; ++passes) {  // the hall's casters; and exhibit 1
    const FramePlan plan = map_plan(ctx, passes);
    const ImageRGBA gl = runner.run(plan, ctx, {}, stats);
    const auto t0 = std::chrono::steady_clock::now();
    const ImageRGBA cpu = run_plan_cpu(plan, ctx, {}, stats);
    const double cpu_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const MapComparison m = compare_maps(gl, cpu);
    const int texels = ctx.width * ctx.height;
    EXPECT_GT(m.covered, texels / 10) << passes;  // the wall around the opening, the plinths
    EXPECT_LE(m.worst, tolerance[passes - 1]) << passes;
    EXPECT_LE(double(m.coverage), MAX_COVERAGE_SHARE * texels) << passes;
    EXPECT_EQ(m.off_edge, 0) << passes;
    std::printf(
        "sun map %dx%d, %zu setup pass(es): %d texels covered on both, worst depth "
        "difference %.3g; %d texels covered on one side only; CPU %.4f s (with the copy)\n",
        ctx.width, ctx.height, passes, m.covered, double(m.worst), m.coverage, cpu_s);
  }
}

}  // namespace
}  // namespace sdfreel
