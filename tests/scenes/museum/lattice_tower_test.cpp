// Exhibit 4's lattice tower (issue 28): it stands on its plinth without touching the top's plane,
// inside the plinth's footprint, in the window's sun; and it lays its grid's shadow on the floor:
// across the patch of floor its shadow falls on, some points see the sun and some do not, in the
// analytic test and in the frame's shadow map alike.
#include "scenes/museum/lattice_tower.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "scenes/museum/lighting.h"
#include "scenes/museum/museum_passes.h"
#include "scenes/registry.h"
#include "scenes/scene_pixels.h"

namespace sdfreel {
namespace {

using namespace museum;
using glm::vec3;

const vec3 UP(0.0f, 1.0f, 0.0f);

std::vector<HallBox> tower() {
  std::vector<HallBox> b;
  add_lattice_tower(b, plinth_base(LIGHT_PLINTH) + vec3(0.0f, PLINTH_H, 0.0f));
  return b;
}

TEST(MuseumLatticeTower, StandsOnItsPlinthWithoutSharingItsTopsPlane) {
  const std::vector<HallBox> bars = tower();
  ASSERT_EQ(bars.size(), size_t(lattice_bar_count()));
  const vec3 base = plinth_base(LIGHT_PLINTH);
  float lowest = 1e30f;
  for (const HallBox& b : bars) {
    lowest = std::min(lowest, b.lo.y);
    EXPECT_GE(b.lo.x, base.x - PLINTH_HALF);
    EXPECT_LE(b.hi.x, base.x + PLINTH_HALF);
    EXPECT_GE(b.lo.z, base.z - PLINTH_HALF);
    EXPECT_LE(b.hi.z, base.z + PLINTH_HALF);
    const vec3 e = b.hi - b.lo;
    // A bar: square across, as long as the tower along its axis.
    const int axis = e.x > e.y ? (e.x > e.z ? 0 : 2) : (e.y > e.z ? 1 : 2);
    EXPECT_NEAR(e[(axis + 1) % 3], LATTICE_BAR, 1e-6f);
    EXPECT_NEAR(e[(axis + 2) % 3], LATTICE_BAR, 1e-6f);
    EXPECT_NEAR(e[axis], LATTICE_CELLS[axis] * LATTICE_CELL + LATTICE_BAR, 1e-5f);
  }
  EXPECT_GT(lowest, PLINTH_H);
  EXPECT_LT(lowest, PLINTH_H + 0.01f);
}

// The middle of each of the tower's cells, in the world.
std::vector<vec3> cell_centres() {
  const vec3 top = plinth_base(LIGHT_PLINTH) + vec3(0.0f, PLINTH_H + LATTICE_GAP, 0.0f);
  const vec3 size = vec3(LATTICE_CELLS) * LATTICE_CELL;
  const vec3 first = top + vec3(-0.5f * size.x, 0.5f * LATTICE_BAR, -0.5f * size.z);
  std::vector<vec3> c;
  for (int i = 0; i < LATTICE_CELLS.x; ++i)
    for (int j = 0; j < LATTICE_CELLS.y; ++j)
      for (int k = 0; k < LATTICE_CELLS.z; ++k)
        c.push_back(first + LATTICE_CELL * (vec3(i, j, k) + 0.5f));
  return c;
}

TEST(MuseumLatticeTower, StandsInTheWindowsBeam) {
  int lit = 0;
  for (const vec3& p : cell_centres())  // the window and its mullions only: no occluders
    lit += sun_visibility(p, UP, TO_SUN.y, HallLight{p, {}}, SunMap{}) > 0.5f;
  EXPECT_GE(lit, int(cell_centres().size()) * 3 / 4);
}

TEST(MuseumLatticeTower, CastsAGridOfShadowsOnTheFloor) {
  // Floor points whose ray to the sun crosses the tower's middle plane (x = the plinth's centre)
  // above the plinth and below the mullions' shadow: each passes the tower's bars or its gaps.
  const vec3 base = plinth_base(LIGHT_PLINTH);
  const SceneInfo& info = *find_scene("museum");
  FrameContext ctx = test::scene_context(info, 9, 5, 0.0, Quality::Final);
  finish_frame_context(ctx);
  const test::MuseumTargets t = test::run_museum_passes(ctx, {});
  const std::vector<HallBox> occluders = sun_occluders();
  int analytic_lit = 0, map_lit = 0, n = 0;
  constexpr int STEPS = 48;
  for (int i = 0; i < STEPS; ++i)
    for (int j = 0; j < STEPS; ++j) {
      const vec3 q(base.x, 1.2f + 0.75f * float(i) / STEPS, -0.12f + 0.32f * float(j) / STEPS);
      const vec3 p = q - TO_SUN * (q.y / TO_SUN.y);
      if (sun_visibility(p, UP, TO_SUN.y, HallLight{p, {}}, SunMap{}) < 1.0f)
        continue;  // the window's edges or mullions shade it without the tower
      ++n;
      analytic_lit += sun_visibility(p, UP, TO_SUN.y, HallLight{p, occluders}, SunMap{}) > 0.5f;
      map_lit +=
          sun_visibility(p, UP, TO_SUN.y, HallLight{p, {}}, {&t.sun_map, &sun_view()}) > 0.5f;
    }
  EXPECT_GT(n, STEPS * STEPS / 2);
  // Neither all lit (no tower) nor all dark (a solid block): a lattice.
  EXPECT_GT(analytic_lit, n / 5);
  EXPECT_LT(analytic_lit, n * 4 / 5);
  EXPECT_NEAR(map_lit, analytic_lit, n / 20) << "the shadow map draws the tower as the boxes are";
}

}  // namespace
}  // namespace sdfreel
