// The museum's sun shadows through its shadow map (issue 12): the open floor in the window's beam
// is lit and the floor behind a plinth (from the sun) is not, as the map says and as the analytic
// test of the window and the occluder boxes agrees; exhibit 1 casts its shadow (a floor point dark
// with it there, lit with it moved away, in the map and in the rendered hall); sunlit faces of the
// casters do not shadow themselves (no acne) and shadows reach the casters' feet (no
// peter-panning beyond the bias). Runs the museum plan's own passes on the CPU.
#include "scenes/museum/sun_shadow.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "scenes/museum/exhibits.h"
#include "scenes/museum/lighting.h"
#include "scenes/museum/museum_passes.h"
#include "scenes/registry.h"
#include "scenes/scene_pixels.h"

namespace sdfreel {
namespace {

using namespace museum;
using glm::vec3;

constexpr int W = 65, H = 37;  // odd: the centre pixel's ray is the camera's forward
const vec3 UP(0.0f, 1.0f, 0.0f);

FrameContext museum_context(const CameraPose& pose, double shift_z = 0.0) {
  const SceneInfo& info = *find_scene("museum");
  FrameContext ctx = test::scene_context(info, W, H, 2.0, Quality::Final);
  ctx.pose = pose;
  ctx.params.set("exhibit_shift_z", {shift_z});
  finish_frame_context(ctx);
  return ctx;
}

// Where the sun's ray through p meets the floor.
vec3 on_floor_below(const vec3& p) {
  return p - TO_SUN * (p.y / TO_SUN.y);
}

// Looking down at floor point p from 2 m above: the centre pixel shows p.
CameraPose above(const vec3& p) {
  const glm::dvec3 t(p);
  return CameraPose{t + glm::dvec3(0.3, 2.0, 0.2), t, 30.0, 0.0};
}

float map_visibility(const ImageRGBA& map, const vec3& p, const vec3& n) {
  return sun_visibility(p, n, glm::dot(n, TO_SUN), HallLight{p, {}}, {&map, &sun_view()});
}

float analytic_visibility(const vec3& p, const vec3& n) {
  return sun_visibility(p, n, glm::dot(n, TO_SUN), HallLight{p, sun_occluders()}, SunMap{});
}

float luminance(const ImageRGBA& img) {
  const float* px = img.at(W / 2, H / 2);
  return 0.2126f * px[0] + 0.7152f * px[1] + 0.0722f * px[2];
}

TEST(MuseumSunShadow, OpenFloorIsLitAndTheFloorBehindAPlinthIsNot) {
  const vec3 open = on_floor_below(vec3(-6.0f, 3.0f, 0.65f));  // a pane's centre
  const vec3 behind = on_floor_below(plinth_base(0) + vec3(0.0f, 0.5f, 0.0f));
  const vec3 walled = vec3(3.0f, 0.0f, 3.0f);  // far from the beam: behind the west wall
  const test::MuseumTargets t = test::run_museum_passes(museum_context(above(open)), {});
  EXPECT_EQ(analytic_visibility(open, UP), 1.0f);
  EXPECT_EQ(map_visibility(t.sun_map, open, UP), 1.0f);
  EXPECT_EQ(analytic_visibility(behind, UP), 0.0f);
  EXPECT_EQ(map_visibility(t.sun_map, behind, UP), 0.0f);
  EXPECT_EQ(analytic_visibility(walled, UP), 0.0f);
  EXPECT_EQ(map_visibility(t.sun_map, walled, UP), 0.0f);
  // The rendered hall: the lit point is several times brighter than the plinth's shadow.
  const float lit =
      luminance(test::run_museum_passes(museum_context(above(open)), {"hall"}).colour);
  const float dark =
      luminance(test::run_museum_passes(museum_context(above(behind)), {"hall"}).colour);
  EXPECT_GT(lit, 3.0f * dark) << lit << " against " << dark;
}

TEST(MuseumSunShadow, ExhibitOneCastsItsShadowOnTheFloor) {
  const FrameContext here = museum_context(find_scene("museum")->default_camera, 0.0);
  const vec3 p = on_floor_below(exhibit_one_centre(here));
  EXPECT_EQ(analytic_visibility(p, UP), 1.0f);  // nothing but the exhibit is in the way
  const FrameContext with = museum_context(above(p), 0.0), away = museum_context(above(p), 2.5);
  const test::MuseumTargets shadowed = test::run_museum_passes(with, {"hall"});
  const test::MuseumTargets lit = test::run_museum_passes(away, {"hall"});
  EXPECT_EQ(map_visibility(shadowed.sun_map, p, UP), 0.0f);
  EXPECT_EQ(map_visibility(lit.sun_map, p, UP), 1.0f);
  EXPECT_GT(luminance(lit.colour), 3.0f * luminance(shadowed.colour))
      << luminance(lit.colour) << " against " << luminance(shadowed.colour);
}

TEST(MuseumSunShadow, SunlitCasterFacesDoNotShadowThemselves) {
  // Exhibit 1 moved off its plinth, so the plinth's top is in the open sun.
  const test::MuseumTargets t =
      test::run_museum_passes(museum_context(find_scene("museum")->default_camera, 2.5), {});
  const vec3 base = plinth_base(0);
  const vec3 west_n(-1.0f, 0.0f, 0.0f);
  int lit = 0, points = 0;  // points the analytic test sees fully in the sun
  for (int i = 1; i < 20; ++i)
    for (int j = 1; j < 20; ++j) {
      const float a = -PLINTH_HALF + 2.0f * PLINTH_HALF * float(i) / 20.0f;
      const float b = float(j) / 20.0f;
      const vec3 west = base + vec3(-PLINTH_HALF, b * PLINTH_H, a);  // faces the window
      const vec3 top = base + vec3(a, PLINTH_H, -PLINTH_HALF + 2.0f * PLINTH_HALF * b);
      if (analytic_visibility(west, west_n) == 1.0f) {
        ++points;
        lit += map_visibility(t.sun_map, west, west_n) == 1.0f;
      }
      if (analytic_visibility(top, UP) == 1.0f) {
        ++points;
        lit += map_visibility(t.sun_map, top, UP) == 1.0f;
      }
    }
  EXPECT_GT(points, 400);  // of 722: the west face's lowest rows are below the window's sill
  EXPECT_EQ(lit, points);
}

// A shadow's edge is a ramp as wide as the filter's box that moves smoothly with the point, not
// steps of whole texels: across the sunlit patch of a window pane on the floor, from the shadow of
// the wall beside it into the mullion's, sampled every eighth of a texel, the visibility goes from
// 0 to 1 through many values, never by more than a box column's share of a texel's eighth
// (nearest-texel filtering jumps by a ninth at every texel's border).
TEST(MuseumSunShadow, ShadowEdgesAreRampsNotSteps) {
  const test::MuseumTargets t =
      test::run_museum_passes(museum_context(find_scene("museum")->default_camera), {});
  const vec3 open = on_floor_below(vec3(-6.0f, 3.0f, 0.65f));  // a pane's centre
  const float step = sun_view().texel / 8.0f;
  std::set<float> values;
  float lowest = 1.0f, highest = 0.0f, biggest_jump = 0.0f, previous = -1.0f;
  for (float z = open.z - 0.8f; z <= open.z + 0.8f; z += step) {
    const float v = map_visibility(t.sun_map, vec3(open.x, 0.0f, z), UP);
    if (previous >= 0.0f) biggest_jump = std::max(biggest_jump, std::fabs(v - previous));
    previous = v;
    lowest = std::min(lowest, v), highest = std::max(highest, v);
    values.insert(v);
  }
  EXPECT_EQ(lowest, 0.0f);
  EXPECT_EQ(highest, 1.0f);
  EXPECT_GT(values.size(), 40u);
  EXPECT_LT(biggest_jump, 0.05f);
}

TEST(MuseumSunShadow, ShadowsReachTheCastersFeet) {
  // Floor points just east of plinth 1's east face: the sun's ray from them enters the plinth
  // after 4 cm along the floor, more than the floor's slope-scaled bias (about 3.6 cm).
  const test::MuseumTargets t =
      test::run_museum_passes(museum_context(find_scene("museum")->default_camera), {});
  const vec3 base = plinth_base(0);
  for (int k = -3; k <= 3; ++k) {
    const vec3 p = base + vec3(PLINTH_HALF + 0.04f, 0.0f, 0.08f * float(k));
    ASSERT_EQ(analytic_visibility(p, UP), 0.0f) << k;
    EXPECT_EQ(map_visibility(t.sun_map, p, UP), 0.0f) << k;
  }
}

}  // namespace
}  // namespace sdfreel
